#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/GridAStar.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <filesystem>
#include <queue>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace gridcar::test;


// ---------------------------------------------------------------- Moving AI optimal lengths
namespace
{
/// Checks @p samples scenarios per map, evenly spaced, always including the last (longest).
void checkScenarios(const std::string &planner, std::size_t samples)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    namespace fs = std::filesystem;
    int maps = 0;
    for (const auto &f : fs::directory_iterator(test::sharedMaps() + "/movingai"))
    {
        if (f.path().extension() != ".map") continue;
        auto grid = std::make_shared<const OccupancyGrid>(loadMovingAiMap(f.path().string()));
        const auto scen = loadScenario(f.path().string() + ".scen");
        GridSetup s = makeGridSetup(grid, VehicleParams::preset("point"));
        auto p = makePlanner(s.ss->getSpaceInformation(), planner);
        s.ss->setPlanner(p);
        int checked = 0;
        for (std::size_t k = 0; k < samples; ++k)
        {
            const std::size_t i = (scen.size() - 1) - k * (scen.size() - 1) / std::max<std::size_t>(1, samples - 1);
            const auto &e = scen[i];
            s.ss->clear();
            s.setStartAndGoal(cellPose(*grid, e.startX, e.startY), cellPose(*grid, e.goalX, e.goalY));
            ASSERT_EQ(s.ss->solve(30.0), ob::PlannerStatus::EXACT_SOLUTION) << f.path() << " line " << i + 2;
            const double cost = dynamic_cast<GridPlanner &>(*p).lastCost();
            EXPECT_NEAR(cost, e.optimalLength, std::max(1e-3, 1e-5 * e.optimalLength))
                << f.path() << " scenario " << i;
            ++checked;
        }
        EXPECT_EQ(checked, int(samples));
        ++maps;
    }
    EXPECT_EQ(maps, 10);
}
}  // namespace

TEST(MovingAiScenarios, AStarOctileMatchesPublishedOptimalLengths) { checkScenarios("astar-octile", 40); }
TEST(MovingAiScenarios, DijkstraMatchesPublishedOptimalLengths) { checkScenarios("dijkstra", 8); }
