#include "gridcar/planners/SmoothedPlanner.h"

#include "gridcar/spaces/GridSE2StateSpace.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/geometric/PathGeometric.h>

namespace gridcar
{
SmoothedPlanner::SmoothedPlanner(ompl::base::PlannerPtr inner)
  : ompl::base::Planner(inner->getSpaceInformation(), inner->getName() + "+smooth"), inner_(std::move(inner))
{
    specs_ = inner_->getSpecs();
    params_ = inner_->params();  // copies hold the inner planner's setter / getter functions
    for (const auto &kv : inner_->getPlannerProgressProperties()) addPlannerProgressProperty(kv.first, kv.second);
}

void SmoothedPlanner::setProblemDefinition(const ompl::base::ProblemDefinitionPtr &pdef)
{
    ompl::base::Planner::setProblemDefinition(pdef);
    inner_->setProblemDefinition(pdef);
}

void SmoothedPlanner::setup()
{
    ompl::base::Planner::setup();
    if (!std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker()))
        throw ompl::Exception(getName(), "needs gridcar's footprint validity checker (see gridcar::makeGridSetup)");
    inner_->setup();
}

void SmoothedPlanner::checkValidity()
{
    ompl::base::Planner::checkValidity();
    inner_->checkValidity();
}

void SmoothedPlanner::clear()
{
    ompl::base::Planner::clear();
    inner_->clear();
    last_ = SmoothingResult();
}

ompl::base::PlannerStatus SmoothedPlanner::solve(const ompl::base::PlannerTerminationCondition &ptc)
{
    last_ = SmoothingResult();
    const ompl::base::PlannerStatus st = inner_->solve(ptc);
    const auto &pdef = getProblemDefinition();
    if (!pdef->hasSolution()) return st;
    auto *path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    if (!path || path->getStateCount() < 3) return st;
    std::vector<Pose2> poses;
    for (const auto *s : path->getStates()) poses.push_back(toPose(s));
    auto vc = std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker());
    last_ = smoothPath(poses, vc->checker());
    auto out = std::make_shared<ompl::geometric::PathGeometric>(si_);
    ompl::base::State *tmp = si_->allocState();
    for (const Pose2 &p : last_.path)
    {
        auto *se2 = tmp->as<ompl::base::SE2StateSpace::StateType>();
        se2->setXY(p.x, p.y);
        se2->setYaw(GridSE2StateSpace::wrapYaw(p.yaw));
        out->append(tmp);
    }
    si_->freeState(tmp);
    const bool approximate = pdef->hasApproximateSolution();
    const double difference = pdef->getSolutionDifference();
    pdef->clearSolutionPaths();
    pdef->addSolutionPath(out, approximate, difference, getName());
    return st;
}

void SmoothedPlanner::getPlannerData(ompl::base::PlannerData &data) const { inner_->getPlannerData(data); }

}  // namespace gridcar
