#include "gridcar/query/Navigate.h"

#include "gridcar/path/Drivability.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;

namespace
{
/// A hall 40 x 12 m at 0.1 m cells, walls round it.
std::shared_ptr<const OccupancyGrid> hall()
{
    auto g = std::make_shared<OccupancyGrid>(400, 120, 0.1);
    for (int c = 0; c < 400; ++c) g->set(c, 0, CellState::Occupied), g->set(c, 119, CellState::Occupied);
    for (int r = 0; r < 120; ++r) g->set(0, r, CellState::Occupied), g->set(399, r, CellState::Occupied);
    return g;
}

MovingObstacle standingBox(double x, double y, double sx, double sy)
{
    MovingObstacle o;
    o.name = "pallet";
    o.shape = MovingObstacle::Shape::Box;
    o.sizeX = sx, o.sizeY = sy;
    o.waypoints = {{x, y}};
    o.speed = 0.0;
    return o;
}

/// Every trajectory sample's body free of the map and of the scenario's obstacles.
double worstClearance(const NavigationResult &r, const FootprintChecker &world, const Scenario &sc)
{
    double worst = 1e9;
    for (const TrajectorySample &s : r.trajectory)
    {
        double d = world.clearance(s.x, s.y, s.yaw);
        double cx[4], cy[4];
        world.corners(s.x, s.y, s.yaw, cx, cy);
        for (const MovingObstacle &o : sc.obstacles)
            for (int k = 0; k < 4; ++k) d = std::min(d, o.distanceFrom(cx[k], cy[k], s.t));
        worst = std::min(worst, d);
    }
    return worst;
}
}  // namespace

// With nothing the map did not show, the first plan is driven to the goal: no replan.
TEST(Navigator, AKnownWorldIsDrivenWithoutReplanning)
{
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"));
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, Scenario());
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached) << r.reason;
    EXPECT_EQ(r.replans, 0);
    EXPECT_EQ(r.plans.size(), 1u);
    EXPECT_EQ(r.sensedCells, 0u);
    EXPECT_LT(std::hypot(r.finalPose.x - 37.0, r.finalPose.y - 6.0), 0.35);
}

// A pallet across the planned route, not in the map: the sensor sees it, the robot plans
// round it from where it is and arrives; no sample of the drive touches anything.
TEST(Navigator, AnUnmappedObstacleAcrossTheRouteIsSeenAndDrivenRound)
{
    Scenario sc;
    sc.obstacles.push_back(standingBox(20.0, 5.0, 1.0, 8.0));  // y 1-9 at x 19.5-20.5: 3 m left above it
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"));
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached) << r.reason;
    EXPECT_GE(r.replans, 1);
    EXPECT_EQ(r.replanSeconds.size(), std::size_t(r.replans));
    EXPECT_GT(r.sensedCells, 10u);
    EXPECT_FALSE(r.updateSeconds.empty());
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
    // the last plan goes above the pallet and is drivable in the working map
    const std::vector<Pose2> &last = r.plans.back();
    bool above = false;
    for (const Pose2 &p : last) above = above || (std::abs(p.x - 20.0) < 0.6 && p.y > 9.0);
    EXPECT_TRUE(above);
    DrivabilityOptions d;
    d.reversing = true;
    EXPECT_TRUE(checkDrivable(last, *nav.setup().checker, d).drivable);
    // the drive went round it: further than the straight line
    EXPECT_GT(r.distanceDriven, 34.5);
    EXPECT_LT(std::hypot(r.finalPose.x - 37.0, r.finalPose.y - 6.0), 0.35);
}

// Replanning while rolling: the pallet seen ahead, the robot rolls on along its old path while
// the plan is made (a fixed latency here, for a repeatable run) and drives on into the new path;
// the same run braking to a standstill before every replan takes longer.
TEST(Navigator, AReplanWhileRollingStandsStillLessAndArrivesSooner)
{
    Scenario sc;
    sc.obstacles.push_back(standingBox(20.0, 5.0, 1.0, 8.0));
    const VehicleParams robot = VehicleParams::preset("paper-c-robot");
    NavigationOptions roll;
    roll.planLatency = 0.3;
    Navigator rollingNav(hall(), robot, roll);
    const NavigationResult rolling = rollingNav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, sc);
    NavigationOptions stop = roll;
    stop.replanRolling = false;
    Navigator stopNav(hall(), robot, stop);
    const NavigationResult stopped = stopNav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, sc);
    ASSERT_EQ(rolling.outcome, NavigationResult::Outcome::Reached) << rolling.reason;
    ASSERT_EQ(stopped.outcome, NavigationResult::Outcome::Reached) << stopped.reason;
    EXPECT_GE(rolling.rollingReplans, 1);
    EXPECT_EQ(stopped.rollingReplans, 0);
    EXPECT_EQ(rolling.replanSeconds.size(), std::size_t(rolling.replans));
    EXPECT_EQ(stopped.replanSeconds.size(), std::size_t(stopped.replans));
    EXPECT_GT(worstClearance(rolling, rollingNav.worldChecker(), sc), 0.0);
    // fewer standstills on the way (the stopping run stands for every replan)
    const auto standstills = [](const NavigationResult &r) {
        int n = 0;
        bool moving = false;
        for (const TrajectorySample &t : r.trajectory)
        {
            if (moving && std::abs(t.v) < 0.01) ++n;
            moving = std::abs(t.v) >= 0.01;
        }
        return n;
    };
    EXPECT_GE(standstills(stopped), stopped.replans);
    EXPECT_LT(standstills(rolling), standstills(stopped)) << rolling.replans << " replans, " << rolling.rollingReplans << " rolling, " << standstills(stopped) << " standstills stopping";
    EXPECT_LT(rolling.drivingTime, stopped.drivingTime);
}

// A goal the pallet stands on: reported as blocked, with the nearest pose the planner reached.
TEST(Navigator, AGoalOnAnUnmappedObstacleIsReportedBlocked)
{
    Scenario sc;
    sc.obstacles.push_back(standingBox(30.0, 6.0, 2.0, 2.0));
    NavigationOptions o;
    o.planTimeLimit = 1.0;
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"), o);
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {30.0, 6.0, 0.0}, false, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::GoalBlocked) << r.reason;
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
    ASSERT_TRUE(r.hasNearestReachable);
    EXPECT_LT(std::hypot(r.nearestReachable.x - 30.0, r.nearestReachable.y - 6.0), 3.0);
    EXPECT_TRUE(nav.setup().checker->isValid(r.nearestReachable));
}

// A pedestrian crossing the route is not planned round (it moves): the follower's field lets
// it pass; the car arrives without touching it.
TEST(Navigator, APedestrianCrossingIsLeftToTheFollower)
{
    Scenario sc;
    MovingObstacle walker;
    walker.name = "pedestrian";
    walker.radius = 0.3;
    walker.waypoints = {{15.0, 11.0}, {15.0, 1.0}};
    walker.speed = 1.0;
    walker.startTime = 8.0;
    sc.obstacles.push_back(walker);
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"));
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached) << r.reason;
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
    EXPECT_EQ(r.replans, 0);  // standing by the walls before and after, never on the route
}

// The same goal with a tolerance (Nav2's goal checker): the car stops beside the pallet within
// it, and every plan ended within it; a tolerance the pallet leaves no room in is still blocked.
TEST(Navigator, AGoalToleranceIsHonouredByThePlansAndTheDrive)
{
    Scenario sc;
    sc.obstacles.push_back(standingBox(30.0, 6.0, 2.0, 2.0));
    NavigationOptions o;
    o.planTimeLimit = 2.0;
    o.goalTolerance = {2.0, 0.0};
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"), o);
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {30.0, 6.0, 0.0}, true, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached) << r.reason;
    EXPECT_LE(std::hypot(r.finalPose.x - 30.0, r.finalPose.y - 6.0), 2.0 + 1e-9);
    for (const std::vector<Pose2> &p : r.plans) EXPECT_LE(std::hypot(p.back().x - 30.0, p.back().y - 6.0), 2.0 + 1e-6);
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
    // a heading tolerance: the last plan ends within 20 degrees of the goal's heading
    NavigationOptions h = o;
    h.goalTolerance = {0.5, 20.0 * M_PI / 180.0};
    Navigator nav2(hall(), VehicleParams::preset("paper-c-robot"), h);
    const NavigationResult r2 = nav2.run({3.0, 6.0, 0.0}, {20.0, 6.0, M_PI / 2}, false, Scenario());
    ASSERT_EQ(r2.outcome, NavigationResult::Outcome::Reached) << r2.reason;
    EXPECT_LE(std::abs(std::remainder(r2.plans.back().back().yaw - M_PI / 2, 2 * M_PI)), 20.0 * M_PI / 180.0 + 1e-6);
    EXPECT_LE(std::abs(std::remainder(r2.finalPose.yaw - M_PI / 2, 2 * M_PI)), 20.0 * M_PI / 180.0 + 1e-6);
    EXPECT_LE(std::hypot(r2.finalPose.x - 20.0, r2.finalPose.y - 6.0), 0.5 + 1e-9);
}

// A forward-only planner whose car has driven into a 1 m channel (too narrow to turn in) that
// an unmapped box closes: no plan starts where it stands, so it backs up along its own track
// until one does, then drives round the channel's walls to the goal.
TEST(Navigator, NoPlanFromWhereTheCarStandsBacksItUpAlongItsTrack)
{
    auto g = std::make_shared<OccupancyGrid>(*hall());
    for (int c = 140; c < 180; ++c)  // walls at y 5.4-5.5 and 6.5-6.6 from x = 14 m to 18 m
        g->set(c, 119 - 54, CellState::Occupied), g->set(c, 119 - 65, CellState::Occupied);
    Scenario sc;
    sc.obstacles.push_back(standingBox(17.6, 6.0, 0.6, 1.0));  // closes the channel's far end
    NavigationOptions o;
    o.planner.params = {{"reverse", "off"}};
    o.sensor.range = 3.0;  // seen only from inside the channel
    o.planTimeLimit = 2.0;
    Navigator nav(g, VehicleParams::preset("paper-c-robot"), o);
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached)
        << r.reason << " (" << r.retreats << " retreats, " << r.replans << " replans, " << r.plans.size() << " plans, "
        << r.distanceDriven << " m driven)";
    EXPECT_GE(r.retreats, 1);
    EXPECT_GE(r.replans, 1);
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
    // the first plan went through the channel, the last one round its walls
    bool through = false, round = true;
    for (const Pose2 &p : r.plans.front()) through = through || (p.x > 14.5 && p.x < 17.5 && std::abs(p.y - 6.0) < 0.5);
    for (const Pose2 &p : r.plans.back()) round = round && !(p.x > 14.0 && p.x < 18.0 && std::abs(p.y - 6.0) < 0.5);
    EXPECT_TRUE(through);
    EXPECT_TRUE(round);
    // it backed up: some stretch of the drive moved away from the goal along the channel
    bool backed = false;
    for (std::size_t i = 1; i < r.trajectory.size(); ++i)
        backed = backed || (r.trajectory[i].v < 0 && r.trajectory[i].x < r.trajectory[i - 1].x && r.trajectory[i].x > 10.0);
    EXPECT_TRUE(backed);
}

// Footprint clearing (Nav2's obstacle layer): a pallet 4 cm beside the robot as it stands shares
// a 0.1 m cell with its body; a scan that marked that cell would leave the robot's own pose in
// collision in the working map, with no plan from it. The cells the body overlaps are kept clear,
// so the robot plans, drives off and arrives.
TEST(Navigator, AnObstacleSharingACellWithTheBodyLeavesItsPoseFree)
{
    const VehicleParams robot = VehicleParams::preset("paper-c-robot");
    const Pose2 start{3.0, 6.05, 0.0};
    const double top = start.y + robot.width / 2;  // the body's left side, y 6.25 (cell 6.2-6.3)
    Scenario sc;
    sc.obstacles.push_back(standingBox(3.0, top + 0.04 + 0.5, 1.0, 1.0));
    Navigator nav(hall(), robot);
    const NavigationResult r = nav.run(start, {13.0, 6.05, 0.0}, false, sc);
    ASSERT_EQ(r.outcome, NavigationResult::Outcome::Reached) << r.reason;
    EXPECT_GT(r.sensedCells, 0u);  // the pallet's face beside where the robot stood is mapped
    const Cell beside = nav.workingMap().worldToCell(2.55, top + 0.05);
    EXPECT_EQ(nav.workingMap().at(beside.col, beside.row), CellState::Occupied);
    EXPECT_GT(worstClearance(r, nav.worldChecker(), sc), 0.0);
}

// A drive that runs past its time limit (the follower backing up and trying again on a short
// piece until then) is planned again from where the car stands, as a stall; the run ends as
// timeout only when the stalls run out.
TEST(Navigator, ADriveThatRunsOutOfTimeIsPlannedAgainAsAStall)
{
    NavigationOptions o;
    o.follower.timeLimit = 2.0;  // each drive: 2 s, far short of the 34 m route
    Navigator nav(hall(), VehicleParams::preset("paper-c-robot"), o);
    const NavigationResult r = nav.run({3.0, 6.0, 0.0}, {37.0, 6.0, 0.0}, false, Scenario());
    EXPECT_EQ(r.outcome, NavigationResult::Outcome::Timeout) << r.reason;
    EXPECT_EQ(r.stalls, o.maxStalls + 1);
    EXPECT_GE(r.plans.size(), std::size_t(o.maxStalls + 1));
    EXPECT_NE(r.reason.find("stalls"), std::string::npos) << r.reason;
    EXPECT_GT(r.finalPose.x, 3.5);  // each drive got on: planned from where the last one ended
}
