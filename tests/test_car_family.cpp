// CarFamily: the car lattice's first search and its fallbacks as one query. A gap the lattice
// turned to the start's heading cannot thread is passed by the hybrid fallback probed while
// the first search runs, not after it has searched out every place it can reach. A route is
// searched on a coarser lattice than a goal pose.
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/util/Console.h>

#include "TestData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gridcar;
namespace ob = ompl::base;

// Paper C's robot on MIT Stata's basement (../shared) beside a box the map does not show (2.56
// x 2.43 m at 37.59, 0.11, as the navigation suite's pair 6 put it), started 4 degrees off the
// corridor's axis: its way on is a gap between the box and a row of slanted obstacles that
// the lattice, turned to that heading, cannot thread. The first search expanded some 490 000
// states in 5 s there without the goal (the navigator then reported no path); the hybrid
// search, probed after some 50 000, reaches it.
TEST(CarFamily, AGapTheLatticesHeadingsCannotThreadIsPassedByTheProbedHybridSearch)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto g = std::make_shared<OccupancyGrid>(loadRosMap(test::sharedMaps() + "/ros/mit_stata_basement/stata_basement.yaml"));
    const Cell lo = g->worldToCell(37.59 - 1.28, 0.11 + 1.215), hi = g->worldToCell(37.59 + 1.28, 0.11 - 1.215);
    for (int r = lo.row; r <= hi.row; ++r)
        for (int c = lo.col; c <= hi.col; ++c) g->set(c, r, CellState::Occupied);
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
    const Pose2 start{32.9, -1.33, -0.075}, goal{42.98, 1.57, 0.0};
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(name);
        auto lattice = configurePlanner(s.ss->getSpaceInformation(), {name, {{"primitives", "lattice"}}, false, false});
        const QueryResult alone = runQuery(s, lattice, start, goal, 1.0, /*freeGoalHeading=*/true);
        ASSERT_NE(alone.status, ob::PlannerStatus::EXACT_SOLUTION) << "the lattice alone threads the gap: no test";
        auto p = makePlanner(s.ss->getSpaceInformation(), name);
        const QueryResult r = runQuery(s, p, start, goal, 30.0, /*freeGoalHeading=*/true);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION) << r.status.asString() << " " << r.notExactBecause;
        EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
        EXPECT_LT(r.expanded, 100000u) << "the first search ran on before the hybrid one was tried";
    }
}

// The lattice's cell follows the kind of query: a route to a goal position on twice the cell
// of a goal pose to meet (a manoeuvre, which the coarse lattice may not make), where a turn at
// R_min spans 2.5 route cells; a lattice_cell set is used for both.
TEST(CarFamily, ARouteIsSearchedOnTwiceTheCellOfAGoalPose)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto open = std::make_shared<OccupancyGrid>(800, 400, 0.05);
    {
        // paper I's car turns too tightly (R_min 1.86 m) for 0.9 m cells: both on 0.45 m
        GridSetup c = makeGridSetup(open, VehicleParams::preset("paper-i"));
        auto p = makePlanner(c.ss->getSpaceInformation(), "corner-astar");
        const QueryResult r = runQuery(c, p, {8.0, 10.0, 0.0}, {32.0, 12.0, 0.0}, 10.0, /*freeGoalHeading=*/true);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_NEAR(dynamic_cast<const CarLatticePlanner &>(*p).carSearch()->lattice().cell(), 0.45, 1e-12);
    }
    GridSetup s = makeGridSetup(open, VehicleParams::preset("paper-c-robot"));
    const Pose2 start{5.0, 10.0, 0.0}, goal{30.0, 12.0, 0.0};
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(name);
        auto p = makePlanner(s.ss->getSpaceInformation(), name);
        const auto *car = dynamic_cast<const CarLatticePlanner *>(p.get());
        ASSERT_NE(car, nullptr);
        for (const double set : {0.0, 0.3})
        {
            SCOPED_TRACE("lattice_cell " + std::to_string(set));
            ASSERT_TRUE(p->params().setParam("lattice_cell", std::to_string(set)));
            const double poseCell = set > 0 ? set : 0.1, routeCell = set > 0 ? set : 0.2;  // (width 0.4 m / 4)
            const QueryResult route = runQuery(s, p, start, goal, 10.0, /*freeGoalHeading=*/true);
            ASSERT_EQ(route.status, ob::PlannerStatus::EXACT_SOLUTION);
            EXPECT_NEAR(car->poseCell(), poseCell, 1e-12);  // (set up on the map's checker by the query)
            EXPECT_NEAR(car->carSearch()->lattice().cell(), routeCell, 1e-12);
            const QueryResult pose = runQuery(s, p, start, goal, 10.0, /*freeGoalHeading=*/false);
            ASSERT_EQ(pose.status, ob::PlannerStatus::EXACT_SOLUTION);
            EXPECT_NEAR(car->carSearch()->lattice().cell(), poseCell, 1e-12);
        }
    }
}

// Why a goal pose keeps the fine cell: on Willow Garage (../shared) paper C's robot backs into
// a goal pose among desks in 34.3 m on the 0.1 m lattice; the 0.2 m one cannot, and loops round
// the block to come at it from the west (61.7 m).
TEST(CarFamily, AGoalPoseAmongObstaclesIsMetOnTheFineCell)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto g = std::make_shared<OccupancyGrid>(loadRosMap(test::sharedMaps() + "/ros/willow_garage/willow-2010-02-18-0.10.yaml"));
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
    auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
    const QueryResult r = runQuery(s, p, {17.35, 59.55, 0.0}, {43.05, 45.85, 0.0}, 30.0);
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
    EXPECT_LT(r.metrics.length, 40.0);
}
