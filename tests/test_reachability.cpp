// FootprintChecker::reachability(), the fast-failure proof: a shut room is proven apart, a door
// the body fits through joins, one it does not fit through does not; the cell budget; and on
// random maps the proof never separates two poses a planner joins with an exact path.
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;
using Reach = FootprintChecker::Reach;

namespace
{
/// 40 m x 20 m at 0.1 m, a room with 1 m walls round x 25-35, y 5-15, and a door in its west
/// wall @p door metres wide (0: shut) centred at y = 10.
std::shared_ptr<OccupancyGrid> roomMap(double door)
{
    auto g = std::make_shared<OccupancyGrid>(400, 200, 0.1, CellState::Free);
    for (int r = 0; r < g->height(); ++r)
        for (int c = 0; c < g->width(); ++c)
        {
            const double x = g->cellCenterX(c), y = g->cellCenterY(r);
            const bool inOuter = x > 25 && x < 35 && y > 5 && y < 15, inInner = x > 26 && x < 34 && y > 6 && y < 14;
            const bool inDoor = x < 26.5 && std::abs(y - 10) < door / 2;
            if (inOuter && !inInner && !inDoor) g->set(c, r, CellState::Occupied);
        }
    return g;
}

Reach reach(double door, const char *vehicle, std::size_t budget = std::size_t(1) << 22, bool anyYaw = false)
{
    auto g = roomMap(door);
    auto f = std::make_shared<DistanceField>(*g);
    const FootprintChecker fc(g, f, VehicleParams::preset(vehicle));
    return fc.reachability({5.0, 10.0, 0.0}, anyYaw, {30.0, 10.0, 0.0}, anyYaw, budget);
}
}  // namespace

TEST(Reachability, AShutRoomIsProvenApartAndADoorTheBodyFitsThroughJoins)
{
    for (const char *vehicle : {"paper-i", "paper-c-robot", "point"})
    {
        SCOPED_TRACE(vehicle);
        for (bool anyYaw : {false, true})
        {
            const Reach shut = reach(0.0, vehicle, std::size_t(1) << 22, anyYaw);
            EXPECT_EQ(shut.verdict, Reach::Separated);
            EXPECT_EQ(shut.shutEnd, 1);  // the goal's room, the smaller region, was run out of
            // the room's 8 m x 8 m inside, less the band its disc cannot reach near the walls
            EXPECT_GT(double(shut.shutCells) * 0.01, 10.0);
            EXPECT_LT(double(shut.shutCells) * 0.01, 64.0 + 1e-9);
            EXPECT_EQ(reach(3.0, vehicle, std::size_t(1) << 22, anyYaw).verdict, Reach::Joined);
        }
    }
    // a door 1 m wide: paper I's car (1.835 m wide) cannot pass, the 0.4 m robot can
    EXPECT_EQ(reach(1.0, "paper-i").verdict, Reach::Separated);
    EXPECT_EQ(reach(1.0, "paper-c-robot").verdict, Reach::Joined);
    // within a budget too small to decide: not a proof
    EXPECT_EQ(reach(0.0, "paper-i", 100).verdict, Reach::Unknown);
}

TEST(Reachability, AnEndWhereTheBodyFitsNowhereDecidesNothing)
{
    auto g = roomMap(0.0);
    auto f = std::make_shared<DistanceField>(*g);
    const FootprintChecker fc(g, f, VehicleParams::preset("paper-i"));
    EXPECT_EQ(fc.reachability({25.5, 10.0, 0.0}, false, {5.0, 10.0, 0.0}, false, 1000000).verdict, Reach::Unknown);  // in the wall
    EXPECT_EQ(fc.reachability({std::nan(""), 10.0, 0.0}, false, {5.0, 10.0, 0.0}, false, 1000000).verdict, Reach::Unknown);
    EXPECT_EQ(fc.reachability({-50.0, 10.0, 0.0}, true, {5.0, 10.0, 0.0}, false, 1000000).verdict, Reach::Unknown);  // off the map
}

// Random maps of walls with gaps: wherever corner-astar (reversing everywhere) finds an exact
// path, the proof must not have separated the two poses; and it does separate some pairs (the
// planners then answer at once that the goal is unreachable).
TEST(Reachability, NeverSeparatesPosesAPlannerJoins)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(7);
    std::mt19937 rng(20261205);
    int joinedByPlanner = 0, separated = 0;
    for (int map = 0; map < 6; ++map)
    {
        auto g = std::make_shared<OccupancyGrid>(300, 300, 0.1, CellState::Free);
        std::uniform_real_distribution<double> u(0.0, 30.0), gap(0.8, 3.0);
        // walls across the map, each with one gap of random width
        for (int w = 0; w < 4; ++w)
        {
            const bool vertical = rng() % 2;
            const double at = u(rng), gapAt = u(rng), gapW = gap(rng);
            for (int r = 0; r < 300; ++r)
                for (int c = 0; c < 300; ++c)
                {
                    const double x = g->cellCenterX(c), y = g->cellCenterY(r);
                    const double across = vertical ? x : y, along = vertical ? y : x;
                    if (std::abs(across - at) < 0.4 && std::abs(along - gapAt) > gapW / 2) g->set(c, r, CellState::Occupied);
                }
        }
        GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
        for (int q = 0; q < 6; ++q)
        {
            std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
            const Pose2 a{u(rng), u(rng), yaw(rng)}, b{u(rng), u(rng), yaw(rng)};
            if (!s.checker->isValid(a.x, a.y, a.yaw) || !s.checker->isValid(b.x, b.y, b.yaw)) continue;
            const Reach r = s.checker->reachability(a, false, b, false, std::size_t(1) << 22);
            if (r.verdict == Reach::Separated) ++separated;
            auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
            p->params().setParam("reverse", "on");
            const QueryResult res = runQuery(s, p, a, b, 2.0);
            if (res.status != ob::PlannerStatus::EXACT_SOLUTION) continue;
            ++joinedByPlanner;
            EXPECT_NE(r.verdict, Reach::Separated) << "map " << map << " query " << q;
        }
    }
    EXPECT_GT(joinedByPlanner, 5);
    EXPECT_GT(separated, 0);
}

// A goal in a room whose wall is one cell thick: the car lattice's 2D heuristic joins the room
// to the rest (its graph's long steps pass over the wall between two free nodes), so the search
// would exhaust the start's whole region (for the point robot, 40 m x 20 m of 0.1 m cells at 16
// headings) before the proof after it. The proof asked once the search has run a while answers
// instead, after a fraction of the expansions that exhausting the region takes: the goal
// unreachable, the path to the state nearest it that the search had reached.
TEST(Reachability, AGoalShutBehindAThinWallIsAnsweredWithoutExhaustingTheStartsRegion)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto g = std::make_shared<OccupancyGrid>(400, 200, 0.1, CellState::Free);
    for (int r = 0; r < g->height(); ++r)
        for (int c = 0; c < g->width(); ++c)
        {
            const double x = g->cellCenterX(c), y = g->cellCenterY(r);
            const bool inOuter = x > 25 && x < 35 && y > 5 && y < 15, inInner = x > 25.1 && x < 34.9 && y > 5.1 && y < 14.9;
            if (inOuter && !inInner) g->set(c, r, CellState::Occupied);
        }
    GridSetup s = makeGridSetup(g, VehicleParams::preset("point"));
    const Pose2 start{5.0, 10.0, 0.0}, goal{30.0, 10.0, 0.0};
    ASSERT_EQ(s.checker->reachability(start, false, goal, false, std::size_t(1) << 22).verdict, Reach::Separated);
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(name);
        auto p = makePlanner(s.ss->getSpaceInformation(), name);
        const QueryResult res = runQuery(s, p, start, goal, 30.0);
        EXPECT_EQ(res.status, ob::PlannerStatus::APPROXIMATE_SOLUTION) << res.status.asString();
        EXPECT_NE(res.notExactBecause.find("the goal is unreachable"), std::string::npos) << res.notExactBecause;
        EXPECT_NE(res.notExactBecause.find("round the goal"), std::string::npos) << res.notExactBecause;
        EXPECT_FALSE(res.path.empty());
        // (the region holds some 70 000 nodes x 16 headings)
        EXPECT_LT(res.expanded, 20000u) << "the start's region was searched out before the proof";
    }
}
