#include "gridcar/objectives/Objectives.h"

#include "gridcar/spaces/Setup.h"

#include <gtest/gtest.h>

#include <ompl/base/ScopedState.h>

#include <cmath>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
std::vector<Pose2> polyline(std::initializer_list<std::pair<double, double>> pts)
{
    std::vector<Pose2> p;
    for (const auto &xy : pts) p.push_back({xy.first, xy.second, 0.0});
    return p;
}
}  // namespace

TEST(DrivingTime, StraightLineIsAccelerateCruiseDecelerate)
{
    const VehicleParams v = VehicleParams::preset("paper-c-car");  // 30 m/s, 3 m/s^2 both ways
    const double L = 500.0, V = v.maxSpeed, a = v.acceleration, d = v.deceleration;
    const double cruise = L - V * V / (2 * a) - V * V / (2 * d);
    ASSERT_GT(cruise, 0.0);
    const double expected = V / a + cruise / V + V / d;  // 10 + 6.67 + 10 s
    EXPECT_NEAR(drivingTime(polyline({{0, 0}, {L, 0}}), v), expected, 0.002 * expected);
    // a grid staircase (E, NE, E, NE, ... on 0.298 m cells) has no net heading change over the
    // 2 m window: paper I's car drives it as fast as a straight line of the same length
    const VehicleParams car = VehicleParams::preset("paper-i");
    std::vector<Pose2> stair{{0, 0, 0}};
    double len = 0;
    for (int i = 0; i < 400; ++i)
    {
        const Pose2 &p = stair.back();
        stair.push_back({p.x + 0.298, p.y + ((i % 2) ? 0.298 : 0.0), 0});
        len += (i % 2) ? 0.298 * std::sqrt(2.0) : 0.298;
    }
    const double straight = drivingTime(polyline({{0, 0}, {len, 0}}), car);
    EXPECT_NEAR(drivingTime(stair, car), straight, 0.01 * straight);
}

TEST(DrivingTime, ShortLineNeverReachesFullSpeed)
{
    const VehicleParams v = VehicleParams::preset("paper-c-car");
    const double L = 60.0, a = v.acceleration, d = v.deceleration;
    const double vpeak = std::sqrt(2 * L * a * d / (a + d));  // 13.4 m/s < 30
    EXPECT_NEAR(drivingTime(polyline({{0, 0}, {L, 0}}), v), vpeak / a + vpeak / d, 0.01 * (vpeak / a + vpeak / d));
}

TEST(DrivingTime, OneRightAngleCornerCostsTheBrakingAndReacceleration)
{
    const VehicleParams v = VehicleParams::preset("paper-c-car");
    // a sharp 90-degree polyline corner is driven at R_min: vc = sqrt(a_lat R_min) = 3.04 m/s
    // (below the car's 6 m/s for 90-degree corners, which needs its 15 m radius)
    const double vc = std::sqrt(v.maxLateralAccel * v.minTurningRadius());
    EXPECT_NEAR(speedLimit(v, M_PI / 2, 2.0), vc, 1e-12);
    EXPECT_NEAR(speedLimit(v, M_PI / 2, 15.0 * M_PI / 4), 6.0, 1e-12);  // a 15 m arc: the table's 6 m/s
    const double L = 400.0, V = v.maxSpeed, a = v.acceleration, d = v.deceleration;
    // leg 1: 0 -> V, cruise, V -> vc at the corner; leg 2: vc -> V, cruise, V -> 0
    const double s1 = V * V / (2 * a) + (V * V - vc * vc) / (2 * d);
    const double s2 = (V * V - vc * vc) / (2 * a) + V * V / (2 * d);
    const double expected = V / a + (L - s1) / V + (V - vc) / d + (V - vc) / a + (L - s2) / V + V / d;
    const double t = drivingTime(polyline({{0, 0}, {L, 0}, {L, L}}), v);
    // the profile slows over the 2 m window on either side of the corner too (the heading changes
    // there): never faster than the point-corner closed form, at most that window at vc slower
    const double window = DrivingTimeParams().window;
    EXPECT_GE(t, expected - 0.01);
    EXPECT_LE(t, expected + 2 * window / vc);
    // so the corner costs the braking and re-acceleration time, (V - vc)^2 / 2 (1/a + 1/d) / V,
    // plus at most the window, over a straight of equal length
    const double straight = drivingTime(polyline({{0, 0}, {2 * L, 0}}), v);
    const double lost = (V - vc) * (V - vc) / 2 * (1 / a + 1 / d) / V;
    EXPECT_GE(t - straight, lost - 0.01);
    EXPECT_LE(t - straight, lost + 2 * window / vc);
}

TEST(DrivingTime, RejectsAVehicleThatCannotMove)
{
    VehicleParams v = VehicleParams::preset("paper-i");
    v.acceleration = 0;
    EXPECT_THROW(drivingTime(polyline({{0, 0}, {1, 0}}), v), std::invalid_argument);
}

TEST(Objectives, ObstacleDistanceAndDrivingTimeAsOmplObjectives)
{
    auto g = std::make_shared<OccupancyGrid>(40, 40, 0.5);
    for (int r = 0; r < 40; ++r) g->set(20, r, CellState::Occupied);  // a wall at x = 10.25 m
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
    const auto si = s.ss->getSpaceInformation();
    ObstacleDistanceObjective obs(si, s.field, 2.0);
    ob::ScopedState<ob::SE2StateSpace> a(s.space), b(s.space);
    a->setXY(g->cellCenterX(16), g->cellCenterY(10));  // 4 cells = 2 m from the wall
    a->setYaw(0);
    b->setXY(g->cellCenterX(16), g->cellCenterY(14));  // 2 m further along the wall
    b->setYaw(0);
    EXPECT_NEAR(obs.stateCost(a.get()).value(), 2.0 / 2.0, 1e-9);
    // along the wall the state cost is constant: motion cost = length x cost = 2 m x 1
    EXPECT_NEAR(obs.motionCost(a.get(), b.get()).value(), 2.0, 1e-6);

    const VehicleParams car = VehicleParams::preset("paper-c-robot");
    DrivingTimeObjective dt(si, car);
    // straight ahead: length / v_max
    ob::ScopedState<ob::SE2StateSpace> c(s.space);
    c->setXY(a->getX() + 3.0, a->getY());
    c->setYaw(0);
    EXPECT_NEAR(dt.motionCost(a.get(), c.get()).value(), 3.0 / car.maxSpeed, 1e-12);
    // a 90-degree turn from a's yaw costs the corner's lost time on top
    EXPECT_NEAR(dt.motionCost(a.get(), b.get()).value(), 2.0 / car.maxSpeed + dt.turnPenalty(M_PI / 2), 1e-12);
    EXPECT_GT(dt.turnPenalty(M_PI / 2), dt.turnPenalty(M_PI / 4));
    EXPECT_EQ(dt.turnPenalty(0.0), 0.0);
    EXPECT_LE(dt.motionCostHeuristic(a.get(), b.get()).value(), dt.motionCost(a.get(), b.get()).value());
    for (const auto &name : objectiveNames()) EXPECT_TRUE(makeObjective(name, si, *s.checker)) << name;
    EXPECT_THROW(makeObjective("fastest", si, *s.checker), std::invalid_argument);
}
