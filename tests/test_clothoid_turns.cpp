// Clothoid turns and the turn-straight-turn curves of include/gridcar/curves/ClothoidTurns.h:
// the turn against a plain numerical integration of its curvature profile, and seeded random
// pose pairs whose curves must land on the goal, keep K_max and the curvature rate at 1 cm
// samples, and be no shorter than the Dubins curve (the shortest with curvature <= 1 / R).
#include "gridcar/curves/CarCurves.h"
#include "gridcar/curves/ClothoidTurns.h"

#include "gridcar/core/Angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace gridcar;

namespace
{
/// The turn integrated directly: heading from the curvature, position by the midpoint rule on
/// 0.1 mm steps.
Pose2 integrate(const ClothoidTurn &t, double delta, double s)
{
    Pose2 p;
    const int n = std::max(1, int(std::ceil(s / 1e-4)));
    const double h = s / n;
    double yaw = 0.0;
    for (int i = 0; i < n; ++i)
    {
        // heading at the middle of the step: the curvature integrated by the trapezoid rule
        const double kA = t.curvature(delta, i * h), kM = t.curvature(delta, (i + 0.5) * h);
        const double mid = yaw + 0.25 * h * (kA + kM);
        p.x += h * std::cos(mid);
        p.y += h * std::sin(mid);
        yaw += 0.5 * h * (kA + 2 * kM + t.curvature(delta, (i + 1) * h)) / 2;
    }
    p.yaw = yaw;
    return p;
}
}  // namespace

TEST(ClothoidTurns, TheTurnIsItsCurvatureProfileIntegrated)
{
    const ClothoidTurn turn(3.9, 0.13);  // paper C's car: R_min 3.86 m, 0.13 1/m^2
    for (double delta : {0.05, 0.4, -0.7, 1.2, -2.5, 3.0, 6.0})
    {
        SCOPED_TRACE(delta);
        const double L = turn.length(delta);
        for (double f : {0.3, 0.5, 0.8, 1.0})
        {
            const Pose2 a = turn.pose(delta, f * L), b = integrate(turn, delta, f * L);
            EXPECT_NEAR(a.x, b.x, 2e-6);
            EXPECT_NEAR(a.y, b.y, 2e-6);
            EXPECT_NEAR(a.yaw, b.yaw, 1e-6);
        }
        EXPECT_NEAR(turn.pose(delta, L).yaw, delta, 1e-12);
        for (double s = 0; s <= L; s += 0.01)
        {
            EXPECT_LE(std::abs(turn.curvature(delta, s)), 1.0 / 3.9 + 1e-12);
            EXPECT_LE(std::abs(turn.curvature(delta, s + 0.01) - turn.curvature(delta, s)), 0.13 * 0.01 + 1e-12);
        }
        EXPECT_EQ(turn.curvature(delta, 0.0), 0.0);
        EXPECT_NEAR(turn.curvature(delta, L), 0.0, 1e-12);
    }
    EXPECT_THROW(ClothoidTurn(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(ClothoidTurn(1.0, -1.0), std::invalid_argument);
}

TEST(ClothoidTurns, CurvesLandKeepTheRateAndAreNoShorterThanDubins)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(-30.0, 30.0), yaw(-M_PI, M_PI);
    const double R = 3.9, sigma = 0.13;
    const ClothoidTurn turn(R, sigma);
    int found = 0;
    for (int k = 0; k < 200; ++k)
    {
        const Pose2 a{0.0, 0.0, yaw(rng)}, b{pos(rng), pos(rng), yaw(rng)};
        const std::vector<ClothoidCurve> cs = clothoidCurves(a, b, turn, 3);
        if (std::hypot(b.x, b.y) > 4 * R + 2 * turn.length(M_PI)) EXPECT_FALSE(cs.empty()) << "far apart: some word exists";
        if (cs.empty()) continue;
        ++found;
        for (std::size_t i = 1; i < cs.size(); ++i) EXPECT_LE(cs[i - 1].length, cs[i].length);
        const ClothoidCurve &c = cs.front();
        EXPECT_GE(c.length, dubinsCurve(a, b, R).length - 1e-9);
        const Pose2 end = clothoidCurvePose(c, turn, c.length);
        EXPECT_NEAR(end.x, b.x, 1e-7);
        EXPECT_NEAR(end.y, b.y, 1e-7);
        EXPECT_NEAR(wrapAngle(end.yaw - b.yaw), 0.0, 1e-7);
        // the sampled curve: turning-angle curvature within 1 / R, its change within sigma
        const double ds = 0.01;
        std::vector<Pose2> p;
        for (double s = 0; s < c.length; s += ds) p.push_back(clothoidCurvePose(c, turn, s));
        double lastK = 0.0;
        for (std::size_t i = 1; i + 1 < p.size(); ++i)
        {
            const double h0 = std::atan2(p[i].y - p[i - 1].y, p[i].x - p[i - 1].x);
            const double h1 = std::atan2(p[i + 1].y - p[i].y, p[i + 1].x - p[i].x);
            const double k = wrapAngle(h1 - h0) / ds;
            EXPECT_LE(std::abs(k), 1.0 / R * 1.001 + 1e-6);
            if (i > 1) EXPECT_LE(std::abs(k - lastK), sigma * ds * 1.01 + 1e-6);
            lastK = k;
            EXPECT_NEAR(wrapAngle(p[i].yaw - h0), 0.0, 0.5 * ds / R + 1e-6);  // the yaw follows the motion
        }
    }
    EXPECT_GT(found, 190);
}
