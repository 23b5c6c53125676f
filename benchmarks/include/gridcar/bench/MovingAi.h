#pragma once
/// @file MovingAi.h
/// @brief Runs a Moving AI scenario file with one planner and checks each path's length against
/// the published optimum (used by `gridcar scen` and benchmarks/bench_movingai).

#include "gridcar/map/MapIO.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace gridcar::bench
{
/// Counts and times of a scenario run.
struct ScenarioStats
{
    std::size_t queries{0}, solved{0}, matched{0};
    std::uint64_t expanded{0};
    double solveSeconds{0.0};   ///< wall time of solve()
    double searchSeconds{0.0};  ///< of that, the grid planner's search loop
};

/// True if @p length matches the published @p optimal (within max(1e-3, 1e-5 x optimal)).
bool matchesOptimal(double length, double optimal);

/**
 * @brief Solves the first @p limit (0: all) scenarios of @p scen with @p planner on @p setup
 * (60 s each) and compares the planner's search cost (the path length for OMPL's planners) with
 * the published optimal length. @p progress, if set, is called after each query with
 * (done, total). InputError when a scenario is for another map size.
 */
ScenarioStats runScenarios(GridSetup &setup, const ompl::base::PlannerPtr &planner, const std::vector<ScenarioEntry> &scen,
                           const std::string &scenFile, std::size_t limit = 0,
                           const std::function<void(std::size_t, std::size_t)> &progress = {});

}  // namespace gridcar::bench
