#include "gridcar/sim/Simulation.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Errors.h"
#include "gridcar/spaces/Setup.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/vehicle/Dynamics.h"
#include "gridcar/planners/PlannerFactory.h"
#include "SimTestUtil.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace gridcar;
using gridcar::test::road;
using gridcar::test::straight;

// What `driving_time_profile` (drivingTime()) and the simulation each count: the profile is the
// path at the vehicle's limits; the follower drives it so where no obstacle is within rho0 of the
// body, and slower (speed x rho / rho0, down to half) where one is: a
// corridor with 0.8 m beside the robot takes it nearly twice the profile's time, and
// the same with rho0 below that room takes the profile's time.
TEST(Simulation, TheProfileIsTheSimulatedTimeWhereNoObstacleIsWithinRho0)
{
    GridSetup s = road(60.0, 0.5);  // 2 m of free cells between the curbs: 0.8 m beside the robot (0.4 m wide)
    const VehicleParams &v = s.checker->vehicle();
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    const auto path = straight(5.0, 55.0, y);
    const double profile = drivingTime(path, v);
    FollowerParams fp;  // rho0 1.5 m
    const DriveResult near = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(near.outcome, DriveResult::Outcome::Reached) << near.reason;
    fp.rho0 = 0.2;  // below the room on either side
    const DriveResult clear = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(clear.outcome, DriveResult::Outcome::Reached) << clear.reason;
    std::printf("corridor: profile %.2f s, simulated %.2f s (rho0 1.5 m), %.2f s (rho0 0.2 m)\n", profile,
                near.drivingTime, clear.drivingTime);
    EXPECT_NEAR(clear.drivingTime, profile, 0.02 * profile);
    EXPECT_GT(near.drivingTime, 1.3 * profile);
    EXPECT_LT(near.drivingTime, 2.0 * profile + 1.0);
}

TEST(Simulation, BicycleTurnsOnTheCircleItsSteeringImplies)
{
    VehicleParams v = VehicleParams::preset("paper-i");
    VehicleState s;
    s.v = 2.0;
    s.steer = 0.3;
    const double dt = 0.01;
    double yaw0 = s.yaw;
    for (int i = 0; i < 100; ++i) s = stepBicycle(s, v, 0.3, 2.0, dt);
    // 1 s at 2 m/s on radius wheelbase / tan(0.3): yaw advances by 2 tan(0.3) / 1.56 rad
    EXPECT_NEAR(s.yaw - yaw0, 2.0 * std::tan(0.3) / v.wheelbase, 1e-9);
    // limits: the steering rate and the acceleration
    VehicleState r;
    r = stepBicycle(r, v, 1.0, 100.0, 0.1);
    EXPECT_NEAR(r.steer, v.maxSteerRateDeg * M_PI / 180 * 0.1, 1e-12);
    EXPECT_NEAR(r.v, v.acceleration * 0.1, 1e-12);
}

TEST(Simulation, StraightRoadDrivingTimeMatchesTheClosedForm)
{
    GridSetup s = road(100.0, 6.0);
    const VehicleParams &v = s.checker->vehicle();  // paper C's robot: 0.6 m/s, 0.3 m/s^2 both ways
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    const auto path = straight(5.0, 95.0, y);
    FollowerParams fp;
    const DriveResult r = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(r.outcome, DriveResult::Outcome::Reached) << r.reason;
    const double L = 90.0, V = v.maxSpeed, a = v.acceleration, d = v.deceleration;
    const double closed = V / a + V / d + (L - V * V / (2 * a) - V * V / (2 * d)) / V;  // 152 s
    std::printf("straight road: simulated %.3f s, closed form %.3f s\n", r.drivingTime, closed);
    EXPECT_NEAR(r.drivingTime, closed, 2 * fp.dt);
    EXPECT_LT(r.crossTrackMax, 0.01);
    // deterministic
    const DriveResult r2 = drivePath(path, *s.checker, Scenario(), fp);
    EXPECT_EQ(r2.drivingTime, r.drivingTime);
    EXPECT_EQ(r2.trajectory.size(), r.trajectory.size());
}

TEST(Simulation, MovingObstacleCrossingIsAvoidedAndTheVehicleReturnsToThePath)
{
    GridSetup s = road(60.0, 8.0);
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    const auto path = straight(3.0, 57.0, y);
    // a pedestrian crossing the road at x = 25 m, timed to meet the robot there
    // (the robot needs about 2 + 40 s to reach x = 25 m)
    Scenario sc;
    MovingObstacle ped;
    ped.name = "pedestrian";
    ped.radius = 0.3;
    ped.waypoints = {{25.0, y - 4.5}, {25.0, y + 4.5}};
    ped.speed = 0.25;
    ped.startTime = 24.0;
    sc.obstacles.push_back(ped);
    const DriveResult r = drivePath(path, *s.checker, sc);
    std::printf("crossing: %s, %.1f s, cross-track max %.2f m, min clearance %.2f m\n",
                DriveResult::outcomeName(r.outcome).c_str(), r.drivingTime, r.crossTrackMax, r.minClearance);
    ASSERT_EQ(r.outcome, DriveResult::Outcome::Reached) << r.reason;
    EXPECT_GT(r.minClearance, 0.0);
    // it did react (left the line or slowed) ...
    const DriveResult free = drivePath(path, *s.checker, Scenario());
    EXPECT_TRUE(r.crossTrackMax > 0.05 || r.drivingTime > free.drivingTime + 1.0);
    // ... and came back: the last 10 m are on the path
    for (const TrajectorySample &q : r.trajectory)
        if (q.x > 47.0) EXPECT_LT(std::abs(q.y - y), 0.15) << "at x = " << q.x;
}

TEST(Simulation, LocalMinimumTrapEndsAsStuckNeverEndlessly)
{
    // a cup-shaped wall across the road, open towards the vehicle; the given path runs through it
    GridSetup s = road(40.0, 10.0);
    auto g = std::const_pointer_cast<OccupancyGrid>(s.grid);
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    OccupancyGrid trap = *s.grid;
    const Cell c = trap.worldToCell(20.0, y);
    for (int r = c.row - 12; r <= c.row + 12; ++r) trap.set(c.col, r, CellState::Occupied);
    for (int k = 0; k < 16; ++k)
    {
        trap.set(c.col - k, c.row - 12, CellState::Occupied);
        trap.set(c.col - k, c.row + 12, CellState::Occupied);
    }
    GridSetup t = makeGridSetup(std::make_shared<OccupancyGrid>(trap), VehicleParams::preset("paper-c-robot"));
    FollowerParams fp;
    fp.stuckWindow = 4.0;
    fp.maxRecoveries = 2;
    const DriveResult r = drivePath(straight(3.0, 37.0, y), *t.checker, Scenario(), fp);
    std::printf("trap: %s after %.1f s (%s), %d recoveries\n", DriveResult::outcomeName(r.outcome).c_str(), r.drivingTime,
                r.reason.c_str(), r.recoveries);
    EXPECT_TRUE(r.outcome == DriveResult::Outcome::Stuck || r.outcome == DriveResult::Outcome::Reached) << r.reason;
    EXPECT_NE(r.outcome, DriveResult::Outcome::Collided) << r.reason;
    EXPECT_LT(r.drivingTime, 60.0 + 5.0 * 34.0 / 0.6);
}

TEST(Simulation, ScenarioFilesAreReadAndBadOnesNamed)
{
    const std::filesystem::path dir = std::filesystem::path(GRIDCAR_TEST_TMP) / "scenario";
    std::filesystem::create_directories(dir);
    const std::string good = (dir / "good.yaml").string();
    std::ofstream(good) << "obstacles:\n"
                           "  - {name: ped, shape: disc, radius: 0.4, waypoints: [[0, 0], [10, 0]], speed: 2, start_time: 1}\n"
                           "  - {shape: box, size: [2, 1], waypoints: [[5, 5]]}\n";
    const Scenario sc = Scenario::load(good);
    ASSERT_EQ(sc.obstacles.size(), 2u);
    double x, y;
    sc.obstacles[0].positionAt(3.0, x, y);  // 2 s of travel at 2 m/s
    EXPECT_NEAR(x, 4.0, 1e-12);
    EXPECT_NEAR(sc.obstacles[0].distanceFrom(4.0, 1.0, 3.0), 0.6, 1e-12);
    EXPECT_NEAR(sc.obstacles[1].distanceFrom(5.0, 7.0, 0.0), 1.5, 1e-12);
    const std::string bad = (dir / "bad.yaml").string();
    std::ofstream(bad) << "obstacles:\n  - {shape: triangle, waypoints: [[0, 0]]}\n";
    try
    {
        Scenario::load(bad);
        FAIL();
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find("bad.yaml: obstacle 1: shape must be disc or box"), std::string::npos) << e.what();
    }
    std::ofstream(bad) << "obstacles:\n  - {radius: -1, waypoints: [[0, 0]]}\n";
    EXPECT_THROW(Scenario::load(bad), MapLoadError);
    EXPECT_THROW(Scenario::load((dir / "missing.yaml").string()), MapLoadError);
    try
    {
        Scenario::load(dir.string());  // a directory: bad input, not a stream error
        ADD_FAILURE() << "a directory must be refused";
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }
}

// A path whose curvature jumps from straight to full lock (a lattice path's arc) beside a wall
// is driven by stopping at the jump and turning the wheels at a standstill, as a driver does in
// a tight manoeuvre: the car then stays on the arc (driven through, the wheels turning at the
// steering rate leave the heading lagging by a tenth of a radian, paper C's car at full lock).
// The same jump in the open is driven through (a stop there would cost only time).
TEST(Simulation, TheWheelsTurnAtAStandstillWhereTheCurvatureJumps)
{
    auto g = std::make_shared<OccupancyGrid>(600, 400, 0.1);
    for (int r = 0; r < g->height(); ++r)  // a wall 0.1 m right of the car, up to x = 20.5 m
        for (int c = 0; c < g->width(); ++c)
            if (std::abs(g->cellCenterY(r) - 8.95) < 0.04 && g->cellCenterX(c) < 20.5) g->set(c, r, CellState::Occupied);
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-car"));
    const VehicleParams &v = s.checker->vehicle();
    const double R = 1.01 * v.minTurningRadius();
    std::vector<Pose2> path;
    for (double x = 10.0; x < 20.0 - 1e-9; x += 0.05) path.push_back({x, 10.0, 0.0});
    for (double a = 0.0; a < M_PI / 2 - 1e-9; a += 0.05 / R)
        path.push_back({20.0 + R * std::sin(a), 10.0 + R * (1.0 - std::cos(a)), a});
    for (double y = 10.0 + R; y <= 20.0 + R + 1e-9; y += 0.05) path.push_back({20.0 + R, y, M_PI / 2});
    for (const Pose2 &p : path) ASSERT_TRUE(s.checker->isValid(p.x, p.y, p.yaw)) << p.x << ", " << p.y;
    auto turnedStanding = [&path](const DriveResult &d) {
        // standing on the way (not at the start, not at the goal) with the wheels turning
        double turned = 0.0;
        for (std::size_t i = 1; i < d.trajectory.size(); ++i)
        {
            const TrajectorySample &a = d.trajectory[i - 1], &b = d.trajectory[i];
            const bool onTheWay = std::hypot(b.x - path.front().x, b.y - path.front().y) > 1.0 &&
                                  std::hypot(b.x - path.back().x, b.y - path.back().y) > 1.0;
            if (onTheWay && std::abs(a.v) < 1e-9 && std::abs(b.v) < 1e-9) turned += std::abs(b.steer - a.steer);
        }
        return turned;
    };
    const DriveResult d = drivePath(path, *s.checker, Scenario());
    ASSERT_EQ(d.outcome, DriveResult::Outcome::Reached) << d.reason;
    EXPECT_GT(turnedStanding(d), 0.8 * std::atan(v.wheelbase / R)) << "the wheels were not turned at a standstill";
    GridSetup open = makeGridSetup(std::make_shared<OccupancyGrid>(600, 400, 0.1), v);
    const DriveResult o = drivePath(path, *open.checker, Scenario());
    ASSERT_EQ(o.outcome, DriveResult::Outcome::Reached) << o.reason;
    EXPECT_EQ(turnedStanding(o), 0.0);
    EXPECT_LT(o.drivingTime, d.drivingTime);
}

// Blocked at speed, the follower brakes with the steering whose braking stays free. On the
// Tsudanuma campus (../shared) paper C's car follows improved-astar's shortcut path (the
// lattice's turns as arcs) between a drive-suite pair through a pinch point at 5.5 m/s, 3.6
// degrees behind the path's heading; every command failed the 0.6 s rollout there and braking
// with the refused one hit the map at (-12.9, -137.5), 79 m along a path the independent
// check passes. Now it arrives.
TEST(Simulation, AFastCarBlockedAtAPinchPointBrakesClearOfIt)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    auto grid = std::make_shared<const OccupancyGrid>(loadRosMap(test::sharedMaps() + "/ros/tsudanuma_campus/tsudanuma_all.yaml"));
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-c-car"));
    // (without the safety margin, on the route lattice's cell of the time: the path of the drive
    // suite then, which met the pinch point)
    auto p = configurePlanner(
        s.ss->getSpaceInformation(),
        {"improved-astar", {{"mode", "integral"}, {"shortcut", "on"}, {"turns", "arc"}, {"safety_margin", "0"}, {"lattice_cell", "0.45"}}, true, false});
    const QueryResult r = runQuery(s, p, {48.525, -102.975, -2.677945}, {-82.975, -80.525, 0.0}, 10.0, /*freeGoalHeading=*/true);
    ASSERT_EQ(r.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    ASSERT_TRUE(r.drivability.drivable) << r.drivability.reason;
    EXPECT_NEAR(r.metrics.length, 203.6, 0.5);  // the path the drive suite drove (else the test drives another)
    const DriveResult d = drivePath(r.path, *s.checker, Scenario());
    EXPECT_NE(d.outcome, DriveResult::Outcome::Collided) << d.reason;
    EXPECT_EQ(d.outcome, DriveResult::Outcome::Reached) << d.reason;
}

TEST(Simulation, APathThatCirclesIsDrivenRoundItsCircleNotAcrossIt)
{
    // a forward route that turns a full circle before going on (as a search may turn a car
    // round), for every radius from the vehicle's R_min up: where the circle closes, the path
    // runs on from the point where it entered it. The follower projected the car on the
    // nearest point up to 12 m ahead, so a car a little outside the circle as it began to
    // turn was projected past it and cut across (bench_native, paper I's car, paper mode,
    // pair 10: it then arrived beside the goal at the wrong heading). The car drives the circle
    for (const char *vehicle : {"paper-c-robot", "paper-i"})
        for (double f : {1.05, 1.3, 2.0})
        {
            GridSetup s = road(60.0, 16.0, vehicle);
            const double R = f * s.checker->vehicle().minTurningRadius();
            const double y0 = s.grid->cellCenterY(s.grid->height() / 2) - R;
            std::vector<Pose2> path = straight(4.0, 20.0, y0, 0.05);
            const int n = int(2 * M_PI * R / 0.05);
            for (int k = 1; k < n; ++k)
            {
                const double a = 2 * M_PI * k / n;  // a left turn round the centre (20, y0 + R)
                path.push_back({20.0 + R * std::sin(a), y0 + R - R * std::cos(a), wrapAngle(a)});
            }
            for (const Pose2 &p : straight(20.0, 40.0, y0, 0.05)) path.push_back(p);
            const DriveResult r = drivePath(path, *s.checker, Scenario(), FollowerParams());
            const std::string what = std::string(vehicle) + ", R " + std::to_string(R) + " m";
            ASSERT_EQ(r.outcome, DriveResult::Outcome::Reached) << what << ": " << r.reason;
            double highest = -1e9;  // round the circle: near its top at some point
            for (const auto &t : r.trajectory) highest = std::max(highest, t.y);
            EXPECT_GT(highest, y0 + 1.5 * R) << what << ": the car cut across the circle";
            EXPECT_GT(r.distanceDriven, 0.9 * (36.0 + 2 * M_PI * R)) << what << ": driven " << r.distanceDriven;
        }
}

// A heading tolerance at the goal: a path whose last pose turns 90 degrees on the spot (no car
// can) ends Stuck with the heading named; without the tolerance it ends Reached as before.
TEST(Simulation, AGoalHeadingToleranceIsChecked)
{
    GridSetup s = road(30.0, 4.0);
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    auto path = straight(5.0, 25.0, y);
    path.back().yaw = M_PI / 2;
    FollowerParams fp;
    EXPECT_EQ(drivePath(path, *s.checker, Scenario(), fp).outcome, DriveResult::Outcome::Reached);
    fp.goalYawTolerance = 0.25;
    const DriveResult r = drivePath(path, *s.checker, Scenario(), fp);
    EXPECT_EQ(r.outcome, DriveResult::Outcome::Stuck);
    EXPECT_NE(r.reason.find("heading"), std::string::npos) << r.reason;
    path.back().yaw = 0.1;
    EXPECT_EQ(drivePath(path, *s.checker, Scenario(), fp).outcome, DriveResult::Outcome::Reached);
}

// A box standing beside the road, 0.58 m from paper I's car's side as it passes: the safety
// rollout keeps the body clear of it by discs that cover the body (its circumscribed disc,
// 2.9 m across the road, refused every command there and the drive ended stuck).
TEST(Simulation, AStandingBoxBesideTheRoadIsDrivenPast)
{
    GridSetup s = road(60.0, 10.0, "paper-i");
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    Scenario sc;
    MovingObstacle box;
    box.name = "parked van";
    box.shape = MovingObstacle::Shape::Box;
    box.sizeX = 4.0, box.sizeY = 1.0;
    box.waypoints = {{30.0, y + 2.0}};  // its near side 1.5 m from the path's line
    box.speed = 0.0;
    sc.obstacles.push_back(box);
    const DriveResult r = drivePath(straight(5.0, 55.0, y), *s.checker, sc);
    ASSERT_EQ(r.outcome, DriveResult::Outcome::Reached) << r.reason;
    EXPECT_GT(r.minClearance, 0.3);
    EXPECT_LT(r.crossTrackMax, 0.5);
}
