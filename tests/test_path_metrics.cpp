#include "gridcar/path/PathMetrics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;

TEST(PathMetrics, StraightLineHasNoTurns)
{
    const std::vector<Pose2> p = {{0, 0, 0}, {5, 0, 0}, {10, 0, 0}};
    const PathMetrics m = computePathMetrics(p, nullptr);
    EXPECT_DOUBLE_EQ(m.length, 10.0);
    EXPECT_EQ(m.turns, 0);
    EXPECT_EQ(m.turningPoints, 0);
    EXPECT_DOUBLE_EQ(m.maxTurnDeg, 0.0);
}

TEST(PathMetrics, SharpAndSmoothRightAnglesAreOneTurnEach)
{
    const std::vector<Pose2> sharp = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}};
    const PathMetrics a = computePathMetrics(sharp, nullptr);
    EXPECT_EQ(a.turns, 1);
    EXPECT_NEAR(a.maxTurnDeg, 90.0, 1e-9);
    std::vector<Pose2> arc = {{0, 0, 0}};
    for (int k = 0; k <= 30; ++k)  // quarter circle of radius 5 from (5, 0) to (10, 5)
    {
        const double t = -M_PI / 2 + k * (M_PI / 2) / 30;
        arc.push_back({5 + 5 * std::cos(t), 5 + 5 * std::sin(t), 0});
    }
    arc.push_back({10, 15, 0});
    const PathMetrics b = computePathMetrics(arc, nullptr);
    EXPECT_EQ(b.turns, 1);
    EXPECT_LT(b.maxTurnDeg, 5.0);  // no sharp turning point on the arc
}

TEST(PathMetrics, ZigzagStaircaseIsNoTurnButTwoCornersAreTwo)
{
    std::vector<Pose2> zig;  // +-45 degrees around the x axis, 0.3 m steps
    for (int k = 0; k <= 60; ++k) zig.push_back({0.3 * k, (k % 2) * 0.3, 0});
    const PathMetrics z = computePathMetrics(zig, nullptr);
    EXPECT_EQ(z.turns, 0);
    EXPECT_NEAR(z.maxTurnDeg, 90.0, 1e-9);  // but each vertex changes heading by 90 degrees
    const std::vector<Pose2> two = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {20, 10, 0}};
    EXPECT_EQ(computePathMetrics(two, nullptr).turns, 2);
}
