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

namespace
{
/// A straight run along +x to (10, 0), an arc of radius @p r turning left by @p turnDeg sampled
/// with @p samples vertices, and a straight run of 10 m after it.
std::vector<Pose2> straightArcStraight(double r, double turnDeg, int samples)
{
    std::vector<Pose2> p = {{0, 0, 0}, {10, 0, 0}};
    const double turn = turnDeg * M_PI / 180.0;
    for (int k = 1; k <= samples; ++k)
    {
        const double a = turn * k / samples;  // heading after k steps; centre at (10, r)
        p.push_back({10 + r * std::sin(a), r - r * std::cos(a), a});
    }
    const Pose2 e = p.back();
    p.push_back({e.x + 10 * std::cos(turn), e.y + 10 * std::sin(turn), turn});
    return p;
}
}  // namespace

TEST(PathMetrics, TheTurnAngleDoesNotDependOnTheSampling)
{
    // a sharp corner and the same turn as an arc at any sampling density: one turn of its angle
    for (double turnDeg : {45.0, 90.0, 135.0, 180.0})
    {
        const Pose2 corner{10, 0, 0};
        const double t = turnDeg * M_PI / 180.0;
        const std::vector<Pose2> sharp = {{0, 0, 0}, corner, {10 + 10 * std::cos(t), 10 * std::sin(t), t}};
        const PathMetrics a = computePathMetrics(sharp, nullptr);
        EXPECT_EQ(a.turns, 1) << turnDeg;
        EXPECT_NEAR(a.maxTurnAngleDeg, turnDeg, 1.0) << turnDeg;
        for (int samples : {3, 30, 300})
        {
            const PathMetrics b = computePathMetrics(straightArcStraight(2.0, turnDeg, samples), nullptr);
            EXPECT_EQ(b.turns, 1) << turnDeg << " deg, " << samples << " samples";
            EXPECT_NEAR(b.maxTurnAngleDeg, turnDeg, 2.0) << turnDeg << " deg, " << samples << " samples";
            if (samples >= 30) EXPECT_LT(b.maxTurnDeg, turnDeg / 10);  // the vertex measure sees only a step
        }
    }
    // a full loop turns 360 degrees, not 0
    const PathMetrics loop = computePathMetrics(straightArcStraight(2.0, 360.0, 200), nullptr);
    EXPECT_NEAR(loop.maxTurnAngleDeg, 360.0, 3.0);
    // a staircase around a straight line is no turn at all
    std::vector<Pose2> zig;
    for (int k = 0; k <= 60; ++k) zig.push_back({0.3 * k, (k % 2) * 0.3, 0});
    EXPECT_DOUBLE_EQ(computePathMetrics(zig, nullptr).maxTurnAngleDeg, 0.0);
}
