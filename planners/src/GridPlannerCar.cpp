/// @file GridPlannerCar.cpp
/// @brief GridPlanner on the car lattice: parameters, goal conversion, solve() and PlannerData.
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace gridcar
{
void GridPlanner::declareCarLatticeParams()
{
    declareParam<int>("headings", this, &GridPlanner::setLatticeHeadings, &GridPlanner::latticeHeadings, "8,16");
    declareParam<double>("heuristic_weight", this, &GridPlanner::setHeuristicWeight, &GridPlanner::heuristicWeight,
                         "1.:0.05:3.");
}

void GridPlanner::setHeuristicWeight(double w)
{
    if (!std::isfinite(w) || w < 1.0 || w > 100.0)
        throw std::invalid_argument(getName() + ": heuristic_weight must be a number in [1, 100]");
    heuristicWeight_ = w;
    parameterSet("heuristic_weight");
}

void GridPlanner::setLatticeCell(double m)
{
    if (!std::isfinite(m) || m < 0.0 || m > 1000.0)
        throw std::invalid_argument(getName() + ": lattice_cell must be 0 (automatic) or a length in (0, 1000] m");
    latticeCell_ = m;
    parameterSet("lattice_cell");
}

void GridPlanner::setLatticeHeadings(int h)
{
    if (h != 8 && h != 16)
        throw std::invalid_argument(getName() + ": headings must be 8 or 16 on the car lattice (the directions of lattice "
                                                "vectors: 32 or 72 equal steps do not land on nodes), got " +
                                    std::to_string(h));
    latticeHeadings_ = h;
    parameterSet("headings");
}

CarLatticeConfig GridPlanner::carLatticeConfig() const
{
    const double rmin = turningRadius();
    CarLatticeConfig cfg;
    cfg.headings = latticeHeadings_;
    if (checker_)
    {
        const VehicleParams &v = checker_->vehicle();
        const double res = checker_->grid().resolution();
        const double want = std::min(v.isPoint() ? 4 * res : v.width, rmin > 0 ? rmin : 4 * res) / 4;
        cfg.cell = latticeCell_ > 0 ? latticeCell_ : res * std::max(1.0, std::round(want / res));
        cfg.spacing = std::min(res, 0.1);
        cfg.reach = checker_->reach();
    }
    else
    {
        // any other validity checker: poses no farther apart than 0.1 m or OMPL's longest
        // valid segment, whichever is shorter (the checker sees poses only)
        cfg.cell = latticeCell_ > 0 ? latticeCell_ : rmin / 4;
        cfg.spacing = std::min({0.1, cfg.cell / 2, si_->getStateSpace()->getLongestValidSegmentLength()});
        cfg.reach = 0.0;
    }
    // arcs 1 % wider than R_min: sampled curves then stay within K_max by a clear margin
    cfg.turnRadius = rmin > 0 ? 1.01 * rmin : cfg.cell;
    return cfg;
}

bool GridPlanner::carGoal(CarLatticeQuery &q, ompl::base::PlannerStatus &bad)
{
    using ompl::base::PlannerStatus;
    const ompl::base::Goal *goal = pdef_->getGoal().get();
    auto invalid = [&](const char *why) {
        OMPL_ERROR("%s: %s", getName().c_str(), why);
        bad = PlannerStatus::INVALID_GOAL;
        return false;
    };
    if (const auto *pg = dynamic_cast<const PositionGoal *>(goal))
    {
        q.goal = {pg->x(), pg->y(), pg->yaw()};
        q.goalYawTolerance = pg->yawTolerance();
        q.inGoal = [this, pg](const Pose2 &p) {
            setPose(scratchB_, p);
            return pg->isSatisfied(scratchB_);
        };
        const CarCollision &c = car_->collision();
        const bool ok = pg->freeHeading() ? c.fitsAtSomeHeading(q.goal.x, q.goal.y, 72) : c.poseFree(q.goal);
        return ok || invalid("the vehicle fits at no allowed heading at the goal position");
    }
    if (const auto *gs = dynamic_cast<const ompl::base::GoalState *>(goal))
    {
        q.goal = toPose(gs->getState());
        q.goalYawTolerance = matchGoalHeading_ ? 0.0 : -1.0;
        if (!si_->satisfiesBounds(gs->getState())) return invalid("goal state is off the map");
        const CarCollision &c = car_->collision();
        const bool ok = matchGoalHeading_ ? c.poseFree(q.goal) : c.fitsAtSomeHeading(q.goal.x, q.goal.y, 72);
        return ok || invalid(matchGoalHeading_ ? "goal state is in collision" : "the vehicle fits at no heading at the goal");
    }
    const auto *gsr = dynamic_cast<const ompl::base::GoalSampleableRegion *>(goal);
    if (gsr && gsr->canSample())
    {
        gsr->sampleGoal(scratchB_);  // a target for the heuristic; the region itself decides
        q.goal = toPose(scratchB_);
        q.shoot = false;
        q.inGoal = [this, gsr](const Pose2 &p) {
            setPose(scratchB_, p);
            return gsr->isSatisfied(scratchB_);
        };
        return true;
    }
    const auto *region = dynamic_cast<const ompl::base::GoalRegion *>(goal);
    if (!region)
    {
        OMPL_ERROR("%s: the goal must be a GoalRegion (e.g. GoalState, PositionGoal)", getName().c_str());
        bad = PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
        return false;
    }
    // a region we cannot aim at: Dijkstra order until a node satisfies it
    q.aim = false;
    q.shoot = false;
    q.inGoal = [this, region](const Pose2 &p) {
        setPose(scratchB_, p);
        return region->isSatisfied(scratchB_);
    };
    return true;
}

ompl::base::PlannerStatus GridPlanner::solveCarLattice(const ompl::base::PlannerTerminationCondition &ptc)
{
    using ompl::base::PlannerStatus;
    const ompl::base::State *start = currentStart();
    if (!start)
    {
        OMPL_ERROR("%s: no valid start state (off the map or in collision)", getName().c_str());
        return PlannerStatus::INVALID_START;
    }
    CarLatticeQuery q;
    q.start = toPose(start);
    q.freeStartHeading = freeStartHeading_;
    q.weight = heuristicWeight_;
    PlannerStatus bad;
    if (!carGoal(q, bad)) return bad;
    const std::unique_ptr<LatticeCostModel> cost = carCost();
    const auto t0 = std::chrono::steady_clock::now();
    const CarLatticeResult r = car_->run(q, *cost, [&] { return ptc.eval(); }, &progressExpanded_);
    lastSearchSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    lastExpanded_ = r.expanded;
    progressExpanded_ = r.expanded;
    lastCost_ = r.cost;
    if (r.path.empty())
    {
        if (memoryStopped_) return memoryStatus(false);
        if (r.outcome == SearchOutcome::Cancelled) return PlannerStatus::TIMEOUT;
        OMPL_ERROR("%s: the vehicle fits at no lattice heading at the start", getName().c_str());
        return PlannerStatus::INVALID_START;
    }
    auto path = std::make_shared<ompl::geometric::PathGeometric>(toPath(si_, r.path));
    double dist = 0.0;
    pdef_->getGoal()->isSatisfied(path->getState(path->getStateCount() - 1), &dist);
    pdef_->addSolutionPath(path, !r.exact, r.exact ? 0.0 : dist, getName());
    if (r.exact) return PlannerStatus::EXACT_SOLUTION;
    if (memoryStopped_) return memoryStatus(true);
    if (r.outcome == SearchOutcome::Cancelled) return PlannerStatus(PlannerStatus::TIMEOUT);
    return PlannerStatus::APPROXIMATE_SOLUTION;
}

void GridPlanner::getCarPlannerData(ompl::base::PlannerData &data) const
{
    std::map<std::tuple<double, double, double>, ompl::base::State *> states;
    auto stateOf = [&](const Pose2 &p) {
        const auto key = std::make_tuple(p.x, p.y, p.yaw);
        auto it = states.find(key);
        if (it != states.end()) return it->second;
        ompl::base::State *st = si_->allocState();
        setPose(st, p);
        carDataStates_.push_back(st);
        states.emplace(key, st);
        return st;
    };
    car_->forEachExpanded([&](const Pose2 &node, const Pose2 &parent) {
        if (node.x == parent.x && node.y == parent.y && node.yaw == parent.yaw)
            data.addStartVertex(ompl::base::PlannerDataVertex(stateOf(node)));
        else
            data.addEdge(ompl::base::PlannerDataVertex(stateOf(parent)), ompl::base::PlannerDataVertex(stateOf(node)));
    });
}

}  // namespace gridcar
