#pragma once
/// @file SmoothedPlanner.h
/// @brief Any OMPL planner followed by paper I's post-processing (smoothPath()).

#include "gridcar/path/PostProcess.h"

#include <ompl/base/Planner.h>

namespace gridcar
{
/**
 * @brief Wraps a planner: solve() runs it, then replaces its solution path by smoothPath() of
 * it (line of sight, turning-point adjustment under K_max, Bezier; collision-checked with the
 * footprint checker). The time limit covers both. Name: "<inner name>+smooth". Parameters are
 * the inner planner's (forwarded). Needs gridcar's FootprintValidityChecker on the space
 * information (ompl::Exception in setup() otherwise).
 */
class SmoothedPlanner : public ompl::base::Planner
{
public:
    explicit SmoothedPlanner(ompl::base::PlannerPtr inner);
    void setProblemDefinition(const ompl::base::ProblemDefinitionPtr &pdef) override;
    void setup() override;
    void clear() override;
    void checkValidity() override;
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void getPlannerData(ompl::base::PlannerData &data) const override;
    const ompl::base::PlannerPtr &inner() const { return inner_; }
    /// Report of the last smoothing (empty if the inner planner found no path).
    const SmoothingResult &lastSmoothing() const { return last_; }

private:
    ompl::base::PlannerPtr inner_;
    SmoothingResult last_;
};
}  // namespace gridcar
