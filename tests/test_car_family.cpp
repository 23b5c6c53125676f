// CarFamily: the car lattice's first search and its fallbacks as one query. A gap the lattice
// turned to the start's heading cannot thread is passed by the hybrid fallback probed while
// the first search runs, not after it has searched out every place it can reach.
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
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
