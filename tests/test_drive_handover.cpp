// The hooks a navigation loop drives with: an interrupt that ends a run (braking, or still
// rolling), and a run that goes on from the state an earlier one ended in.
#include "gridcar/sim/Simulation.h"

#include "gridcar/core/Angles.h"
#include "gridcar/vehicle/Dynamics.h"
#include "SimTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace gridcar;
using gridcar::test::road;
using gridcar::test::straight;

// The navigation loop's hook: asked before every step, true stops the run; the car brakes to a
// standstill on its course and the run ends as Interrupted, the scenario's clock going on from
// startTime.
TEST(DriveHandover, AnInterruptStopsTheCarWhereItStandsAndTheClockGoesOn)
{
    GridSetup s = road(60.0, 4.0);
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    const auto path = straight(5.0, 55.0, y);
    FollowerParams fp;
    fp.startTime = 7.0;
    int asked = 0;
    fp.interrupt = [&](const VehicleState &st, double t) {
        ++asked;
        EXPECT_GE(t, 7.0);
        return st.x > 20.0;
    };
    const DriveResult r = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(r.outcome, DriveResult::Outcome::Interrupted) << r.reason;
    EXPECT_GT(asked, 10);
    EXPECT_NEAR(r.finalState.v, 0.0, 1e-9);
    EXPECT_GT(r.finalState.x, 20.0);
    EXPECT_LT(r.finalState.x, 30.0);
    EXPECT_NEAR(r.finalState.y, y, 0.2);
    ASSERT_FALSE(r.trajectory.empty());
    EXPECT_NEAR(r.trajectory.back().t - 7.0, r.drivingTime, 1e-9);
    EXPECT_NEAR(r.trajectory.back().x, r.finalState.x, 1e-9);
}

// A run that goes on from an earlier one, rolling (a navigation loop's replan): it starts at the
// speed and steering it is given, drives on without braking to a standstill and so takes less
// time than from rest; an interrupt with interruptRolling ends it at once, still rolling; a
// rolling start into a piece of the other gear is refused.
TEST(DriveHandover, ARollingStartDrivesOnAtItsSpeed)
{
    GridSetup s = road(60.0, 4.0);
    const double y = s.grid->cellCenterY(s.grid->height() / 2);
    const auto path = straight(5.0, 45.0, y);
    const double v0 = 0.8 * s.checker->vehicle().maxSpeed;
    const DriveResult fromRest = drivePath(path, *s.checker, Scenario());
    ASSERT_EQ(fromRest.outcome, DriveResult::Outcome::Reached) << fromRest.reason;
    FollowerParams fp;
    fp.startState = VehicleState{5.0, y, 0.0, v0, 0.0};
    const DriveResult rolling = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(rolling.outcome, DriveResult::Outcome::Reached) << rolling.reason;
    ASSERT_GT(rolling.trajectory.size(), 20u);
    double slowest = 1e9;
    for (std::size_t i = 0; i < 20; ++i) slowest = std::min(slowest, rolling.trajectory[i].v);
    EXPECT_GT(slowest, 0.9 * v0);
    EXPECT_LT(rolling.drivingTime, fromRest.drivingTime - 0.3 * v0 / s.checker->vehicle().acceleration);

    fp.interruptRolling = true;
    fp.interrupt = [](const VehicleState &st, double) { return st.x > 20.0; };
    const DriveResult cut = drivePath(path, *s.checker, Scenario(), fp);
    ASSERT_EQ(cut.outcome, DriveResult::Outcome::Interrupted) << cut.reason;
    EXPECT_GT(cut.finalState.v, 0.5 * v0);
    EXPECT_NEAR(cut.finalState.x, 20.0, 0.2);

    fp.interrupt = nullptr;
    fp.startState = VehicleState{5.0, y, 0.0, -0.3, 0.0};  // rolling backwards into a forward path
    EXPECT_THROW(drivePath(path, *s.checker, Scenario(), fp), std::invalid_argument);

    // backing up: the body heads +x while the car rolls towards -x, at its reverse speed
    std::vector<Pose2> back;
    for (double x = 45.0; x >= 30.0 - 1e-9; x -= 0.25) back.push_back({x, y, 0.0});
    const double vr = -0.8 * reverseSpeedLimit(s.checker->vehicle());
    FollowerParams bp;
    bp.startState = VehicleState{45.0, y, 0.0, vr, 0.0};
    const DriveResult reversing = drivePath(back, *s.checker, Scenario(), bp);
    ASSERT_EQ(reversing.outcome, DriveResult::Outcome::Reached) << reversing.reason;
    ASSERT_GT(reversing.trajectory.size(), 20u);
    for (std::size_t i = 0; i < 20; ++i)
    {
        EXPECT_LT(reversing.trajectory[i].v, 0.9 * vr);  // backwards, not braked
        EXPECT_NEAR(wrapAngle(reversing.trajectory[i].yaw), 0.0, 0.05);
    }
    EXPECT_NEAR(reversing.finalState.x, 30.0, 0.35);
    EXPECT_NEAR(reversing.finalState.yaw, 0.0, 0.05);
}
