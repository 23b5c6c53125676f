// The query pipeline (planners/PlanQuery): configurePlanner, progress properties, runQuery.
#include "gridcar/core/Errors.h"
#include "gridcar/planners/CornerAStar.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>

using namespace gridcar;
using namespace gridcar::test;

TEST(PlanQuery, ParsesParameterSettings)
{
    const PlannerParams p = parsePlannerParams({"mode=integral", "delta=0.5", "empty="});
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0].first, "mode");
    EXPECT_EQ(p[0].second, "integral");
    EXPECT_EQ(p[2].second, "");
    EXPECT_THROW(parsePlannerParams({"novalue"}), InputError);
    EXPECT_THROW(parsePlannerParams({"=3"}), InputError);
}

TEST(PlanQuery, ConfigurePlannerAppliesParametersAndSaysWhatIsWrong)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = testSetup();
    const auto si = s.ss->getSpaceInformation();
    auto p = configurePlanner(si, {"corner-astar", {{"corner_weight_90", "3.5"}}, true, false});
    EXPECT_EQ(p->params().getParam("corner_weight_90")->getValue(), "3.5");
    EXPECT_EQ(p->params().getParam("free_start_heading")->getValue(), "1");
    try
    {
        configurePlanner(si, {"corner-astar", {{"wheels", "4"}}, false, false});
        FAIL() << "an unknown parameter must be refused";
    }
    catch (const InputError &e)
    {
        EXPECT_NE(std::string(e.what()).find("no parameter 'wheels'"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("corner_weight_90"), std::string::npos) << "lists the parameters";
    }
    EXPECT_THROW(configurePlanner(si, {"corner-astar", {{"weights", "bogus"}}, false, false}), InputError);
    EXPECT_THROW(configurePlanner(si, {"improved-astar", {{"mode", "bogus"}}, false, false}), InputError);
    EXPECT_THROW(configurePlanner(si, {"no-such-planner", {}, false, false}), std::invalid_argument);
    // OMPL's planners have no free_start_heading: asking for it is not an error
    EXPECT_NO_THROW(configurePlanner(si, {"rrtconnect", {}, true, false}));
}

TEST(PlanQuery, SmoothingIsAddedOnceWhereThePlannerDoesNotSmoothItself)
{
    GridSetup s = testSetup("paper-c-robot");
    const auto si = s.ss->getSpaceInformation();
    EXPECT_TRUE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"astar-octile", {}, false, true}).get()));
    EXPECT_FALSE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"astar-octile", {}, false, false}).get()));
    // improved-astar's paths are final (the car lattice's, drivable as searched); paper I's grid
    // search smooths its own path (smooth = 1) ...
    EXPECT_FALSE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"improved-astar", {}, false, true}).get()));
    EXPECT_FALSE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"improved-astar-grid", {}, false, true}).get()));
    // ... unless told not to, when --smooth wraps it
    EXPECT_TRUE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"improved-astar-grid", {{"smooth", "0"}}, false, true}).get()));
    EXPECT_TRUE(dynamic_cast<SmoothedPlanner *>(configurePlanner(si, {"improved-astar", {{"lattice", "grid"}, {"smooth", "0"}}, false, true}).get()));
    // a "+smooth" name is not wrapped twice
    auto named = configurePlanner(si, {"astar-octile+smooth", {}, false, true});
    auto *sp = dynamic_cast<SmoothedPlanner *>(named.get());
    ASSERT_TRUE(sp);
    EXPECT_FALSE(dynamic_cast<SmoothedPlanner *>(sp->inner().get()));
}

TEST(PlanQuery, RunQueryReadsTheGridPlannersProgressProperties)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = testSetup();
    const Pose2 a = cellPose(*s.grid, 5, 30), b = cellPose(*s.grid, 50, 30);
    auto p = configurePlanner(s.ss->getSpaceInformation(), {"corner-astar", {}, true, false});
    const QueryResult q = runQuery(s, p, a, b, 5.0);
    ASSERT_EQ(q.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    auto &corner = dynamic_cast<CornerAStar &>(*p);
    EXPECT_EQ(q.expanded, corner.expandedNodes());
    EXPECT_GT(q.expanded, 0u);
    EXPECT_DOUBLE_EQ(q.cost, corner.lastCost());
    // the typed report says the same as the planner, and an OMPL planner reports no search
    const PlannerReport report = reportOf(*p);
    ASSERT_TRUE(report.searchCost && report.expanded && report.searchSeconds);
    EXPECT_DOUBLE_EQ(*report.searchCost, corner.lastCost());
    EXPECT_EQ(*report.expanded, corner.expandedNodes());
    EXPECT_DOUBLE_EQ(*report.searchSeconds, corner.lastSearchSeconds());
    EXPECT_TRUE(report.ownPoses && report.searchesCarLattice && !report.searchesMapCells);
    const PlannerReport ompl = reportOf(*configurePlanner(s.ss->getSpaceInformation(), {"rrtconnect", {}, false, false}));
    EXPECT_FALSE(ompl.searchCost || ompl.expanded || ompl.searchSeconds || ompl.ownPoses || ompl.smoothing);
    EXPECT_GE(q.metrics.length, 45 * 0.5 - 1e-9);
    EXPECT_FALSE(q.smoothed);
    const auto cells = exploredCells(*p, *s.grid);
    EXPECT_EQ(cells.size(), q.expanded);
    for (const Cell &c : cells) EXPECT_TRUE(s.grid->inBounds(c.col, c.row));
}

TEST(PlanQuery, RunQueryReportsSmoothingAndTheRawPath)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = testSetup("paper-c-robot");
    const Pose2 a = cellPose(*s.grid, 5, 30), b = cellPose(*s.grid, 50, 15);
    auto p = configurePlanner(s.ss->getSpaceInformation(), {"astar-octile", {}, true, true});
    const QueryResult q = runQuery(s, p, a, b, 5.0);
    ASSERT_EQ(q.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(q.smoothed);
    EXPECT_GT(q.expanded, 0u) << "the wrapper forwards the inner planner's progress properties";
    EXPECT_GE(q.rawPath.size(), 3u);
    EXPECT_NE(q.rawPath.size(), q.path.size());
    EXPECT_GE(q.smoothingSeconds, 0.0);
    EXPECT_LE(q.smoothingSeconds, q.seconds);
}

// A goal tolerance: the goal pose on an obstacle is no goal for an exact query, and with a
// tolerance the path ends within it, free; a negative tolerance is refused.
TEST(PlanQuery, AGoalToleranceLetsThePathEndWithinIt)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    auto g = std::make_shared<OccupancyGrid>(200, 100, 0.1, CellState::Free);
    for (int r = 40; r < 60; ++r)
        for (int c = 140; c < 160; ++c) g->set(c, r, CellState::Occupied);  // a 2 x 2 m block at x 14-16, y 4-6
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
    auto p = configurePlanner(s.ss->getSpaceInformation(), {"corner-astar", {}, false, false});
    const Pose2 start{2.0, 5.0, 0.0}, goal{15.0, 5.0, 0.0};
    EXPECT_NE(runQuery(s, p, start, goal, 2.0).status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    const QueryResult q = runQuery(s, p, start, goal, 2.0, false, GoalTolerance{1.8, M_PI});
    ASSERT_EQ(q.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << q.status.asString();
    EXPECT_LE(std::hypot(q.path.back().x - goal.x, q.path.back().y - goal.y), 1.8 + 1e-6);
    EXPECT_TRUE(q.drivability.drivable) << q.drivability.reason;
    EXPECT_THROW(s.setStartAndGoal(start, goal, false, GoalTolerance{-1.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(s.setStartAndGoal(start, goal, false, GoalTolerance{0.5, NAN}), std::invalid_argument);
}
