#include "gridcar/bench/MovingAi.h"

#include "gridcar/core/Errors.h"
#include "gridcar/query/PlanQuery.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gridcar::bench
{
bool matchesOptimal(double length, double optimal)
{
    return std::abs(length - optimal) <= std::max(1e-3, 1e-5 * optimal);
}

ScenarioStats runScenarios(GridSetup &setup, const ompl::base::PlannerPtr &planner, const std::vector<ScenarioEntry> &scen,
                           const std::string &scenFile, std::size_t limit,
                           const std::function<void(std::size_t, std::size_t)> &progress)
{
    using Clock = std::chrono::steady_clock;
    const OccupancyGrid &grid = *setup.grid;
    setup.ss->setPlanner(planner);
    setup.ss->setup();
    ScenarioStats st;
    st.queries = limit ? std::min(limit, scen.size()) : scen.size();
    for (std::size_t i = 0; i < st.queries; ++i)
    {
        const ScenarioEntry &e = scen[i];
        if (e.mapWidth != grid.width() || e.mapHeight != grid.height())
            throw InputError(scenFile + ": line " + std::to_string(i + 2) + " is for a " + std::to_string(e.mapWidth) +
                             " x " + std::to_string(e.mapHeight) + " map, not this one");
        setup.ss->clear();
        setup.setStartAndGoal({grid.cellCenterX(e.startX), grid.cellCenterY(e.startY), 0.0},
                              {grid.cellCenterX(e.goalX), grid.cellCenterY(e.goalY), 0.0});
        const auto t0 = Clock::now();
        const auto status = setup.ss->solve(60.0);
        st.solveSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
        const PlannerReport report = reportOf(*planner);
        st.searchSeconds += report.searchSeconds.value_or(0.0);
        st.expanded += report.expanded.value_or(0);
        if (progress) progress(i + 1, st.queries);
        if (status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
        ++st.solved;
        const double len = report.searchCost ? *report.searchCost : setup.ss->getSolutionPath().length();
        if (matchesOptimal(len, e.optimalLength)) ++st.matched;
    }
    return st;
}

}  // namespace gridcar::bench
