#pragma once
/// @file SmoothedPlanner.h
/// @brief Paper I's post-processing (smoothPath()) of an OMPL solution path: one function that
/// every route to smoothing uses, and a wrapper that adds it to any OMPL planner.

#include "gridcar/path/PostProcess.h"
#include "gridcar/planners/PlannerReport.h"

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>

#include <vector>

namespace gridcar
{
/// Replaces @p path (at least 3 states) by smoothPath() of it, collision-checked with
/// @p checker; @p raw receives the poses before smoothing. Returns the smoothing report.
/// @p ptc is polled between corners: when it stops the smoothing, @p path is left as it was
/// (SmoothingResult::cancelled).
SmoothingResult smoothSolutionPath(const ompl::base::SpaceInformationPtr &si, const FootprintChecker &checker,
                                   ompl::geometric::PathGeometric &path, std::vector<Pose2> &raw,
                                   const ompl::base::PlannerTerminationCondition &ptc);

/// The one rule for a smoothed exact solution (improved-astar's own smoothing and the
/// `+smooth` wrapper): it stays exact only if checkDrivable() passes on @p path, checked to
/// the end (a check stopped by @p ptc does not pass). Returns "" when it stays exact, else
/// checkDrivable()'s reason.
std::string smoothedPathVerdict(const std::vector<Pose2> &path, const FootprintChecker &checker,
                                const ompl::base::PlannerTerminationCondition &ptc);

/**
 * @brief Wraps a planner: solve() runs it, then replaces its solution path by smoothPath() of
 * it (line of sight, turning-point adjustment under K_max, Bezier; collision-checked with the
 * footprint checker). The time limit covers both. Name: "<inner name>+smooth". Parameters and
 * progress properties are the inner planner's (forwarded). Needs gridcar's
 * FootprintValidityChecker on the space information (ompl::Exception in setup() otherwise).
 * A grid planner searching the car lattice (corner-astar, improved-astar by default) returns
 * drivable curves already; its path is passed through unchanged.
 * With Method::OmplSimplifier it is OMPL's own simplifier instead (shortcuts checked by the
 * space information's motion validator: on a Reeds-Shepp set-up, the footprint along the
 * curves); it needs no gridcar type and reports no SmoothingResult.
 */
class SmoothedPlanner : public ompl::base::Planner, public ReportingPlanner
{
public:
    /// What the wrapper does to the inner planner's path.
    enum class Method
    {
        PaperI,         ///< smoothPath() (name suffix "+smooth")
        OmplSimplifier  ///< OMPL's PathSimplifier::simplify() in the time left, as
                        ///< SimpleSetup::simplifySolution() would (name suffix "+simplify")
    };
    explicit SmoothedPlanner(ompl::base::PlannerPtr inner, Method method = Method::PaperI);
    void setProblemDefinition(const ompl::base::ProblemDefinitionPtr &pdef) override;
    void setup() override;
    void clear() override;
    void checkValidity() override;
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void getPlannerData(ompl::base::PlannerData &data) const override;
    const ompl::base::PlannerPtr &inner() const { return inner_; }
    Method method() const { return method_; }
    /// The post-processing of the last solve() (empty path when nothing was smoothed).
    const SmoothingResult &lastSmoothing() const { return last_; }
    /// The path before smoothing (world poses; empty when nothing was smoothed).
    const std::vector<Pose2> &lastRawPath() const { return raw_; }
    /// The inner planner's report, with this wrapper's smoothing (Method::PaperI: its poses are
    /// the path; OmplSimplifier: the space's curves still join them).
    PlannerReport lastReport() const override;

private:
    ompl::base::PlannerPtr inner_;
    Method method_;
    SmoothingResult last_;
    std::vector<Pose2> raw_;
};
}  // namespace gridcar
