/// @file GridPlanner.cpp
/// @brief GridPlanner: set-up of the world, one solve() over the subclass's search family,
/// PlannerData, the report.
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/PlannerData.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gridcar
{
GridPlanner::GridPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
  : ompl::base::Planner(si, name), support_(*this), goals_(si), dataStates_(si)
{
    specs_.approximateSolutions = true;
    specs_.optimizingPaths = false;  // optimal for their own search cost, not for an objective
    specs_.directed = true;
    specs_.multithreaded = false;
    specs_.recognizedGoal = ompl::base::GOAL_REGION;
    declareParam<bool>("free_start_heading", this, &GridPlanner::setFreeStartHeading,
                       &GridPlanner::freeStartHeading, "0,1");
    declareParam<double>("turning_radius", this, &GridPlanner::setTurningRadius, &GridPlanner::turningRadiusParam,
                         "0.:0.1:100.");
    declareParam<double>("max_memory_mb", this, &GridPlanner::setMaxMemoryMb, &GridPlanner::maxMemoryMb, "0.:256.:65536.");
    declareParam<double>("lattice_cell", this, &GridPlanner::setLatticeCell, &GridPlanner::latticeCell, "0.:0.05:5.");
    declareParam<bool>("match_goal_heading", this, &GridPlanner::setMatchGoalHeading,
                       &GridPlanner::matchGoalHeading, "0,1");
    for (auto &[name, read] : support_.progressProperties()) addPlannerProgressProperty(name, read);
}

GridPlanner::~GridPlanner() = default;

const ompl::base::State *GridPlanner::currentStart()
{
    pis_.restart();
    return pis_.nextStart();
}

void GridPlanner::setup()
{
    ompl::base::Planner::setup();
    if (!dynamic_cast<const ompl::base::SE2StateSpace *>(si_->getStateSpace().get()))
        throw ompl::Exception(getName(), "needs a state space derived from ompl::base::SE2StateSpace (plain SE2, "
                                         "Dubins, Reeds-Shepp or gridcar::GridSE2StateSpace)");
    auto vc = std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker());
    checker_ = vc ? &vc->checker() : nullptr;
    if (!collision_ || !support_.builtOnCurrentWorld(*si_))
    {
        // a new map (validity checker) or motion validator: a new collision model, and nothing
        // built on the old one stays (the families rebuild on it)
        support_.rememberWorld(*si_);
        collision_ = checker_ ? std::shared_ptr<CarCollision>(std::make_shared<FootprintCollision>(*checker_))
                              : std::shared_ptr<CarCollision>(std::make_shared<SpaceCollision>(si_));
        mapVersion_ = checker_ ? checker_->mapVersion() : 0;
    }
    genericVehicle_ = genericVehicle();
    space_ = std::dynamic_pointer_cast<GridSE2StateSpace>(si_->getStateSpace());
    if (!space_) space_ = ownGridSpace();  // any other SE(2) space: the map's cells, or cells from the parameters
    setupFamily(collision_);
}

void GridPlanner::clear()
{
    ompl::base::Planner::clear();
    dataStates_.clear();
    support_.resetStatistics();
    clearFamily();
}

ompl::base::PlannerStatus GridPlanner::solve(const ompl::base::PlannerTerminationCondition &timeLimit)
{
    using ompl::base::PlannerStatus;
    if (!support_.builtOnCurrentWorld(*si_))
    {
        OMPL_INFORM("%s: the validity checker or motion validator changed since setup(): setting up again", getName().c_str());
        setup_ = false;
    }
    checkValidity();
    if (checker_ && collision_ && checker_->mapVersion() != mapVersion_)
    {
        // cells changed (FootprintChecker::cellsChanged()): the set-up stays, what the searches
        // learnt of the old cells goes
        mapVersion_ = checker_->mapVersion();
        collision_->mapChanged();
        mapChangedFamily();
    }
    dataStates_.clear();  // PlannerData states are cached by search state, which a new search renumbers
    const ompl::base::PlannerTerminationCondition ptc = support_.withMemoryBound(timeLimit, params_.maxMemoryMb);
    const bool car = usesCarLattice();
    if (const std::string why = cannotSearch(); !why.empty())
    {
        support_.setStopReason(why);
        return support_.memoryStatus(false);
    }
    support_.resetStatistics();
    const ompl::base::State *start = currentStart();
    if (!start)
    {
        OMPL_ERROR("%s: no valid start state (off the map or in collision)", getName().c_str());
        return PlannerStatus::INVALID_START;
    }
    // the car lattice arrives at its own heading: without match_goal_heading a goal state
    // where the car fits at some heading is reachable; a grid path ends at the state itself
    const PlannerStatus goal =
        goals_.read(pdef_->getGoal().get(), matchGoalHeading(), /*anyHeading=*/car, *collision_, getName(), goal_);
    if (goal != PlannerStatus::UNKNOWN) return goal;
    const auto cancelled = [&] { return ptc.eval(); };
    FamilyRun run = searchFamily(start, goal_, cancelled, support_.progress());
    support_.record(run.expanded, run.cost, run.searchSeconds);
    SearchEnd &end = run.end;
    if (end.path)
    {
        // an approximate path stopped by the time limit is returned as it is: post-processing
        // it would run past the limit
        notExactBecause_.clear();
        const bool replaced = (end.reached || !ptc.eval()) && postProcess(*end.path, ptc);
        if (end.reached && !notExactBecause_.empty())
            end.notExactBecause = notExactBecause_;
        else if (replaced && end.reached && checker_)
        {
            // a smoothed path is a drivable solution only if the independent check says so
            const std::vector<Pose2> poses = toPoses(*end.path);
            const std::string why = smoothedPathVerdict(poses, *checker_, ptc);
            if (!why.empty()) end.notExactBecause = "the smoothed path is not drivable: " + why;
            else end.notExactBecause = endsOffGoal(goal_, poses.back());
        }
    }
    return support_.finish(std::move(end));
}

std::string GridPlanner::endsOffGoal(const GoalTarget &goal, const Pose2 &end)
{
    // a GoalState whose heading need not be matched: its position
    const bool positionOnly = goal.kind == GoalTarget::Kind::State && goal.yawTolerance < 0;
    if (positionOnly ? std::hypot(end.x - goal.pose.x, end.y - goal.pose.y) <= 1e-6 : goal.satisfied(end)) return "";
    char buf[200];
    std::snprintf(buf, sizeof buf, "the smoothed path ends at (%.3f, %.3f) heading %.1f deg, off the goal (%.3f, %.3f) heading %.1f deg",
                  end.x, end.y, end.yaw * 180.0 / M_PI, goal.pose.x, goal.pose.y, goal.pose.yaw * 180.0 / M_PI);
    return buf;
}

PlannerReport GridPlanner::lastReport() const
{
    PlannerReport r;
    r.ownPoses = true;
    r.searchesMapCells = !usesCarLattice();
    r.searchesCarLattice = usesCarLattice();
    r.expanded = support_.expanded();
    r.searchCost = support_.cost();
    r.searchSeconds = support_.searchSeconds();
    r.stopReason = support_.stopReason();
    return r;
}

void GridPlanner::getPlannerData(ompl::base::PlannerData &data) const
{
    ompl::base::Planner::getPlannerData(data);
    if (!space_) return;
    familyData(data, dataStates_);
}

}  // namespace gridcar
