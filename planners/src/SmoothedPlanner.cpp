#include "gridcar/planners/SmoothedPlanner.h"

#include "gridcar/path/Drivability.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/util/Console.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>

namespace gridcar
{
SmoothingResult smoothSolutionPath(const ompl::base::SpaceInformationPtr &si, const FootprintChecker &checker,
                                   ompl::geometric::PathGeometric &path, std::vector<Pose2> &raw,
                                   const ompl::base::PlannerTerminationCondition &ptc)
{
    raw = toPoses(path);
    SmoothingParams params;
    params.cancelled = [&ptc] { return ptc.eval(); };
    SmoothingResult res = smoothPath(raw, checker, params);
    if (!res.cancelled) path = toPath(si, res.path);
    return res;
}

std::string smoothedPathVerdict(const std::vector<Pose2> &path, const FootprintChecker &checker,
                                const ompl::base::PlannerTerminationCondition &ptc)
{
    DrivabilityOptions check;
    check.cancelled = [&ptc] { return ptc.eval(); };
    const Drivability d = checkDrivable(path, checker, check);
    return d.drivable ? std::string() : d.reason;
}

SmoothedPlanner::SmoothedPlanner(ompl::base::PlannerPtr inner, Method method)
  : ompl::base::Planner(inner->getSpaceInformation(),
                        inner->getName() + (method == Method::PaperI ? "+smooth" : "+simplify"))
  , inner_(std::move(inner))
  , method_(method)
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
    if (method_ == Method::PaperI && !std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker()))
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
    raw_.clear();
    const ompl::base::PlannerStatus st = inner_->solve(ptc);
    const auto &pdef = getProblemDefinition();
    if (!pdef->hasSolution()) return st;
    auto *path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
    if (!path || path->getStateCount() < 3) return st;
    // out of time without an exact solution: the inner planner's path as it is (smoothing it
    // would run past the limit)
    if (st != ompl::base::PlannerStatus::EXACT_SOLUTION && ptc.eval()) return st;
    if (method_ == Method::OmplSimplifier)
    {
        ompl::geometric::PathSimplifier(si_, pdef->getGoal()).simplify(*path, ptc);
        return st;
    }
    // a car-lattice path is drivable as searched: paper I's smoothing would only move it off
    // the curves whose footprint was checked
    if (reportOf(*inner_).searchesCarLattice) return st;
    auto vc = std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker());
    auto out = std::make_shared<ompl::geometric::PathGeometric>(*path);
    last_ = smoothSolutionPath(si_, vc->checker(), *out, raw_, ptc);
    if (last_.cancelled)
    {
        // stopped by the termination condition: the inner planner's path, not smoothed, and so
        // not the exact solution asked for
        OMPL_WARN("%s: smoothing stopped by the termination condition; the path is not smoothed", getName().c_str());
        last_ = SmoothingResult();
        last_.notDrivable = "the smoothing was stopped by the termination condition";
        raw_.clear();
        const double difference = pdef->getSolutionDifference();
        pdef->clearSolutionPaths();
        pdef->addSolutionPath(out, true, difference, getName());
        if (st == ompl::base::PlannerStatus::EXACT_SOLUTION) return ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
        return st;
    }
    bool approximate = pdef->hasApproximateSolution();
    const double difference = pdef->getSolutionDifference();
    ompl::base::PlannerStatus result = st;
    if (st == ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        // an exact solution stays exact only if the smoothed path passes the independent check
        last_.notDrivable = smoothedPathVerdict(last_.path, vc->checker(), ptc);
        if (!last_.notDrivable.empty())
        {
            approximate = true;
            result = ompl::base::PlannerStatus::APPROXIMATE_SOLUTION;
            OMPL_WARN("%s: the smoothed path is not drivable: %s", getName().c_str(), last_.notDrivable.c_str());
        }
    }
    pdef->clearSolutionPaths();
    pdef->addSolutionPath(out, approximate, difference, getName());
    return result;
}

void SmoothedPlanner::getPlannerData(ompl::base::PlannerData &data) const { inner_->getPlannerData(data); }

PlannerReport SmoothedPlanner::lastReport() const
{
    PlannerReport r = reportOf(*inner_);
    r.ownPoses = method_ == Method::PaperI;
    // a wrapper over a planner with a `smooth` switch smooths as that switch says
    r.smoothsItself = !params_.hasParam("smooth") || params_.getParam("smooth")->getValue() == "1";
    // the smoothing reported is this wrapper's (none with OMPL's simplifier)
    r.smoothing = method_ == Method::PaperI ? &last_ : nullptr;
    r.rawPath = raw_;
    return r;
}

}  // namespace gridcar
