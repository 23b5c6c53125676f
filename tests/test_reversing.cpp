// Reverse motion on the car lattice: the planners' `reverse`, `reverse_penalty` and
// `cusp_penalty`, forward-only on a Dubins space, paths that back out drivably.
#include "PlannerTestUtil.h"

#include "gridcar/query/PlanQuery.h"
#include "gridcar/map/ParkingScenes.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/core/Angles.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
/// 30 m x 12 m at 0.1 m: an open square (x < 8 m), then a street 2.6 m wide (y 4.7-7.3 m),
/// closed at x = 25 m: too narrow for paper I's car to turn in.
std::shared_ptr<OccupancyGrid> deadEnd()
{
    auto g = std::make_shared<OccupancyGrid>(300, 120, 0.1, CellState::Free);
    for (int r = 0; r < g->height(); ++r)
        for (int c = 0; c < g->width(); ++c)
        {
            const double x = g->cellCenterX(c), y = g->cellCenterY(r);
            if (x >= 8.0 && (y < 4.7 || y > 7.3 || x >= 25.0)) g->set(c, r, CellState::Occupied);
        }
    return g;
}

int backwardPoses(const std::vector<Pose2> &path)
{
    int n = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double dx = path[i].x - path[i - 1].x, dy = path[i].y - path[i - 1].y;
        if (dx * std::cos(path[i].yaw) + dy * std::sin(path[i].yaw) < -1e-9) ++n;
    }
    return n;
}

/// Plans in the dead end from facing its closed end to the square behind, heading kept.
ob::PlannerStatus planOut(const std::string &planner, const std::string &reverse, SpaceKind kind,
                          std::vector<Pose2> &path, GridSetup &s)
{
    SetupOptions o;
    o.space = kind;
    s = makeGridSetup(deadEnd(), VehicleParams::preset("paper-i"), o);
    auto p = makePlanner(s.ss->getSpaceInformation(), planner);
    p->params().setParam("match_goal_heading", "1");
    p->params().setParam("reverse", reverse);
    s.ss->setPlanner(p);
    s.setStartAndGoal({18.0, 6.0, 0.0}, {4.0, 6.0, 0.0});
    const ob::PlannerStatus st = s.ss->solve(5.0);
    path = s.ss->haveSolutionPath() ? toPoses(s.ss->getSolutionPath()) : std::vector<Pose2>();
    return st;
}
}  // namespace

// Forwards the car cannot leave the street with its heading; with reverse=on both car-lattice
// planners back out, exactly to the goal pose, drivable with the body turned round.
TEST(Reversing, BothPlannersBackOutOfADeadEnd)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(name);
        GridSetup s;
        std::vector<Pose2> path;
        EXPECT_NE(planOut(name, "off", SpaceKind::SE2, path, s), ob::PlannerStatus::EXACT_SOLUTION);
        ASSERT_EQ(planOut(name, "on", SpaceKind::SE2, path, s), ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_GT(backwardPoses(path), 0);
        DrivabilityOptions d;
        d.reversing = true;
        const Drivability dv = checkDrivable(path, *s.checker, d);
        EXPECT_TRUE(dv.drivable) << dv.reason;
        EXPECT_NEAR(path.back().x, 4.0, 1e-6);
        EXPECT_NEAR(path.back().y, 6.0, 1e-6);
        EXPECT_NEAR(wrapAngle(path.back().yaw), 0.0, 1e-6);
    }
}

namespace
{
/// 70 m x 40 m of open ground at 0.1 m, a street 2.6 m wide (y 4.7-7.3 m) from x = 8 m to its
/// closed end at x = 65 m along the bottom: too narrow for paper I's car to turn in.
std::shared_ptr<OccupancyGrid> openGroundAndLongDeadEnd()
{
    auto g = std::make_shared<OccupancyGrid>(700, 400, 0.1, CellState::Free);
    for (int r = 0; r < g->height(); ++r)
        for (int c = 0; c < g->width(); ++c)
        {
            const double x = g->cellCenterX(c), y = g->cellCenterY(r);
            if (x >= 8.0 && y < 12.0 && (y < 4.7 || y > 7.3 || x >= 65.0)) g->set(c, r, CellState::Occupied);
        }
    return g;
}

/// The largest distance of a pose driven backwards from both @p a and @p b (0: none backwards).
double farthestBackwardPose(const std::vector<Pose2> &path, const Pose2 &a, const Pose2 &b)
{
    double far = 0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double dx = path[i].x - path[i - 1].x, dy = path[i].y - path[i - 1].y;
        if (dx * std::cos(path[i].yaw) + dy * std::sin(path[i].yaw) >= -1e-9) continue;
        far = std::max(far, std::min(std::hypot(path[i].x - a.x, path[i].y - a.y), std::hypot(path[i].x - b.x, path[i].y - b.y)));
    }
    return far;
}
}  // namespace

// The default, reverse=auto, reverses where manoeuvres are: within reverse_zone (2 R_min + the
// car's length) of the start and the goal (a primitive or a shot may end up to a couple of
// metres past it). With no penalty on reversing, reverse=on backs the whole 32 m to a goal
// straight behind the car; auto does not, and still arrives exactly.
TEST(Reversing, AutoReversesNearTheEndsOnly)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = makeGridSetup(openGroundAndLongDeadEnd(), VehicleParams::preset("paper-i"));
    const Pose2 start{56.0, 25.0, 0.0}, goal{24.0, 25.0, 0.0};
    double zone = 0, farOn = 0;
    for (const char *reverse : {"on", "auto"})
    {
        SCOPED_TRACE(reverse);
        auto p = std::dynamic_pointer_cast<CarLatticePlanner>(makePlanner(s.ss->getSpaceInformation(), "corner-astar"));
        ASSERT_TRUE(p);
        EXPECT_EQ(p->carSettings().reverse, AutoSwitch::Auto);  // the default
        ASSERT_TRUE(p->params().setParam("reverse", reverse));
        ASSERT_TRUE(p->params().setParam("reverse_penalty", "1"));
        const QueryResult r = runQuery(s, p, start, goal, 10.0);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
        EXPECT_LT(test::poseError(r.path.back(), goal), 1e-6);
        const double far = farthestBackwardPose(r.path, start, goal);
        if (std::string(reverse) == "on")
        {
            EXPECT_LT(p->reverseWithin(), 0.0);
            farOn = far;
            continue;
        }
        zone = p->reverseWithin();
        const VehicleParams v = VehicleParams::preset("paper-i");
        EXPECT_NEAR(zone, 2 * p->turningRadius() + v.length, 1e-9);
        EXPECT_LE(far, zone + 2.5);
    }
    // (on: backwards farther from both ends than the zone, or the test above proves nothing)
    EXPECT_GT(farOn, zone + 2.5);
}

// Out of a 57 m dead end too narrow to turn in, to the open ground behind: the search that
// reverses near the ends only cannot back the 30 m between its zones; the fallback reversing
// everywhere (FallbackSchedule) finds the way, exact and drivable, with the default settings.
TEST(Reversing, AutoFallsBackToReversingEverywhere)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = makeGridSetup(openGroundAndLongDeadEnd(), VehicleParams::preset("paper-i"));
    const Pose2 start{60.0, 6.0, 0.0}, goal{4.0, 6.0, 0.0};
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(name);
        auto p = std::dynamic_pointer_cast<CarLatticePlanner>(makePlanner(s.ss->getSpaceInformation(), name));
        ASSERT_TRUE(p);
        const QueryResult r = runQuery(s, p, start, goal, 10.0);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
        EXPECT_LT(test::poseError(r.path.back(), goal), 1e-6);
        EXPECT_GT(farthestBackwardPose(r.path, start, goal), p->reverseWithin() + 1.0);
    }
}

// A Dubins space drives forwards only: reverse=on is refused with the reason, reverse=auto
// stays forwards; on the Reeds-Shepp space auto reverses.
TEST(Reversing, ForwardOnlyOnTheDubinsSpace)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s;
    std::vector<Pose2> path;
    try
    {
        planOut("corner-astar", "on", SpaceKind::Dubins, path, s);
        FAIL() << "reverse=on accepted on a Dubins space";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("forwards only"), std::string::npos) << e.what();
    }
    planOut("corner-astar", "auto", SpaceKind::Dubins, path, s);
    EXPECT_EQ(backwardPoses(path), 0);
    ASSERT_EQ(planOut("corner-astar", "auto", SpaceKind::ReedsShepp, path, s), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_GT(backwardPoses(path), 0);
}

// The penalties: cusp_penalty defaults to the vehicle's gear-change distance; where a forward
// path exists, a high reverse_penalty keeps the path forwards; both refused on the grid lattice.
TEST(Reversing, PenaltiesAndWhereTheyAct)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = test::carSetup(SpaceKind::SE2);
    auto p = std::make_shared<CornerAStar>(s.ss->getSpaceInformation());
    p->setup();  // the vehicle is the checker's from set-up on
    EXPECT_DOUBLE_EQ(p->cuspPenalty(), gearChangeDistance(VehicleParams::preset("paper-i")));
    EXPECT_GT(p->cuspPenalty(), 0.5);
    ASSERT_TRUE(p->params().setParam("cusp_penalty", "3"));
    EXPECT_DOUBLE_EQ(p->cuspPenalty(), 3.0);
    ASSERT_TRUE(p->params().setParam("cusp_penalty", "auto"));  // unset again: the vehicle's
    EXPECT_DOUBLE_EQ(p->cuspPenalty(), gearChangeDistance(VehicleParams::preset("paper-i")));
    ASSERT_TRUE(p->params().setParam("cusp_penalty", "3"));
    EXPECT_FALSE(p->params().setParam("reverse_penalty", "0.5"));
    EXPECT_FALSE(p->params().setParam("reverse", "sometimes"));
    EXPECT_DOUBLE_EQ(p->carSettings().reversePenalty, 2.0);  // refused values leave the settings as they were
    ASSERT_TRUE(p->params().setParam("reverse", "on"));
    ASSERT_TRUE(p->params().setParam("reverse_penalty", "10"));
    s.ss->setPlanner(p);
    test::setPlainQuery(*s.ss, 10, 30, 50, 30);
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(backwardPoses(toPoses(s.ss->getSolutionPath())), 0);

    // the grid search has no reverse to set
    auto grid = makePlanner(s.ss->getSpaceInformation(), "corner-astar-grid");
    EXPECT_FALSE(grid->params().hasParam("reverse"));
    EXPECT_FALSE(grid->params().hasParam("reverse_penalty"));
}

// Out of a parallel slot the lattice's nodes cannot manoeuvre from the start (every primitive
// longer than the gap allows), but the same search from the goal back into the slot finds the
// way (CarLatticeQuery::timeReversed): primitives=lattice leaves exactly at the goal pose now,
// and so does the default (auto, with the hybrid fallback), drivable, with a cusp.
TEST(Reversing, ASearchFromTheGoalLeavesAParallelSlot)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ParkingQuery q;
    GridSetup s = test::parkingSetup("paper-c-car", "parallel", q, "parallel/leave");
    for (const char *prims : {"lattice", "auto"})
    {
        SCOPED_TRACE(prims);
        auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
        p->params().setParam("reverse", "on");
        p->params().setParam("primitives", prims);
        const QueryResult r = runQuery(s, p, q.start, q.goal, 5.0);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
        EXPECT_GE(r.metrics.cusps, 1);
        EXPECT_LT(test::poseError(r.path.front(), q.start), 1e-6);
        EXPECT_LT(test::poseError(r.path.back(), q.goal), 1e-6);
    }
}

// Paper I's 5.55 m car (2 m of rear overhang swinging out) into and out of a gap of 1.5 car
// lengths: the lattice from the start and from the goal and the hybrid set from the start all
// run out; the hybrid set searched from the goal, or at half its cell, finds both, exact at the
// goal pose, drivable, and the simulation drives them to the goal (before: neither found in 5 s).
TEST(Reversing, PaperIsCarParksInAndLeavesAParallelGap)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    for (const char *name : {"parallel/park", "parallel/leave"})
    {
        SCOPED_TRACE(name);
        ParkingQuery q;
        GridSetup s = test::parkingSetup("paper-i", "parallel", q, name);
        auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
        p->params().setParam("reverse", "on");
        const QueryResult r = runQuery(s, p, q.start, q.goal, 10.0);
        ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
        EXPECT_LT(test::poseError(r.path.back(), q.goal), 1e-6);
        const DriveResult d = drivePath(r.path, *s.checker, Scenario());
        EXPECT_EQ(d.outcome, DriveResult::Outcome::Reached) << d.reason;
    }
}

// A goal pose given with a yaw is reached with that yaw by default on the car lattice (backing
// into a slot ends nose-out, not nose-in); match_goal_heading=0 relaxes it; a free-heading goal
// (PositionGoal) arrives at any heading.
TEST(Reversing, AGoalYawIsReachedByDefault)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ParkingQuery q;
    GridSetup s = test::parkingSetup("paper-c-car", "perpendicular", q, "perpendicular/back-in");
    auto p = makePlanner(s.ss->getSpaceInformation(), "improved-astar");
    p->params().setParam("reverse", "on");
    const QueryResult r = runQuery(s, p, q.start, q.goal, 5.0);
    ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_LT(test::poseError(r.path.back(), q.goal), 1e-6);
    EXPECT_TRUE(r.drivability.drivable) << r.drivability.reason;
    auto grid = makePlanner(s.ss->getSpaceInformation(), "corner-astar-grid");
    EXPECT_EQ(grid->params()["match_goal_heading"].getValue(), "0");  // the papers' grid searches: any heading
    EXPECT_EQ(p->params()["match_goal_heading"].getValue(), "1");
    const QueryResult free = runQuery(s, p, q.start, q.goal, 5.0, /*freeGoalHeading=*/true);
    ASSERT_EQ(free.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_NEAR(free.path.back().x, q.goal.x, 1e-6);
}

// The simulation drives a path with cusps piece by piece, each in its gear: backwards with the
// speed negative and at most the reverse speed limit, standing still at the cusp, to the goal.
TEST(Reversing, TheSimulationDrivesEachPieceInItsGear)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    GridSetup s;
    std::vector<Pose2> path;
    ASSERT_EQ(planOut("corner-astar", "on", SpaceKind::SE2, path, s), ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_GT(backwardPoses(path), 0);
    const DriveResult d = drivePath(path, *s.checker, Scenario());
    EXPECT_EQ(d.outcome, DriveResult::Outcome::Reached) << d.reason;
    const double vRev = reverseSpeedLimit(s.checker->vehicle());
    EXPECT_LT(vRev, s.checker->vehicle().maxSpeed / 2);
    double slowest = 0;
    for (const TrajectorySample &t : d.trajectory)
    {
        slowest = std::min(slowest, t.v);
        EXPECT_GE(t.v, -vRev - 1e-9);
    }
    EXPECT_LT(slowest, -0.5 * vRev) << "never drove backwards";
    EXPECT_NEAR(d.trajectory.back().x, path.back().x, 0.3);
    EXPECT_NEAR(d.trajectory.back().y, path.back().y, 0.3);
    // the limit from the vehicle: max_reverse_speed when set (at most v_max), else v_max / 3, <= 2 m/s
    VehicleParams v = VehicleParams::preset("paper-c-car");
    EXPECT_DOUBLE_EQ(reverseSpeedLimit(v), 2.0);
    v.maxReverseSpeed = 1.2;
    EXPECT_DOUBLE_EQ(reverseSpeedLimit(v), 1.2);
    v.maxReverseSpeed = -1;
    EXPECT_THROW(v.validate(), std::invalid_argument);
}

// The curve heuristic (`curve_heuristic`): read from the lattice's table or computed exactly,
// every perpendicular-parking query is still solved exactly, drivable, at the goal pose; the
// parameter takes off / table / exact (0 and 1 as before) and nothing else.
TEST(Reversing, TheCurveHeuristicFromItsTableOrExactKeepsEveryParkingQuerySolved)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    for (const std::string mode : {"table", "exact"})
        for (const std::string name :
             {"perpendicular/park-forwards", "perpendicular/back-in", "perpendicular/leave-nose-in",
              "perpendicular/leave-backed-in"})
        {
            ParkingQuery q;
            GridSetup s = test::parkingSetup("paper-c-car", "perpendicular", q, name);
            auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
            p->params().setParam("reverse", "on");
            ASSERT_TRUE(p->params().setParam("curve_heuristic", mode));
            const QueryResult r = runQuery(s, p, q.start, q.goal, 5.0);
            ASSERT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION) << mode << " " << name;
            EXPECT_LT(test::poseError(r.path.back(), q.goal), 1e-6) << mode << " " << name;
            EXPECT_TRUE(r.drivability.drivable) << mode << " " << name << ": " << r.drivability.reason;
        }
    GridSetup s = makeGridSetup(deadEnd(), VehicleParams::preset("paper-i"));
    auto planner = std::make_shared<CornerAStar>(s.ss->getSpaceInformation());
    auto &params = planner->params();
    EXPECT_EQ(planner->carSettings().curveHeuristic, CurveHeuristic::Off);
    ASSERT_TRUE(params.setParam("curve_heuristic", "1"));
    EXPECT_EQ(planner->carSettings().curveHeuristic, CurveHeuristic::Exact);
    ASSERT_TRUE(params.setParam("curve_heuristic", "0"));
    EXPECT_EQ(params.getParam("curve_heuristic")->getValue(), "off");
    EXPECT_FALSE(params.setParam("curve_heuristic", "sometimes"));
    EXPECT_EQ(planner->carSettings().curveHeuristic, CurveHeuristic::Off);
}
