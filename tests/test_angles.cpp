/// @file test_angles.cpp
/// @brief wrapAngle() and wrapYaw(): the in-range shortcut gives std::remainder's bits.
#include "gridcar/core/Angles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
bool sameBits(double a, double b)
{
    if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
    return std::memcmp(&a, &b, sizeof a) == 0;
}
}  // namespace

TEST(Angles, WrapAngleIsStdRemainderBitForBit)
{
    std::vector<double> cases{0.0, -0.0, M_PI, -M_PI, 2 * M_PI, -2 * M_PI, 3 * M_PI, -3 * M_PI, 1e300, -1e-300,
                              std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()};
    for (double a : {M_PI, -M_PI, 2 * M_PI, -2 * M_PI})
    {
        cases.push_back(std::nextafter(a, 0.0));
        cases.push_back(std::nextafter(a, a * 2));
    }
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> near(-7.0, 7.0), far(-1e4, 1e4);
    for (int i = 0; i < 100000; ++i) cases.push_back(i % 2 ? near(rng) : far(rng));
    for (double a : cases)
    {
        EXPECT_TRUE(sameBits(gridcar::wrapAngle(a), std::remainder(a, 2.0 * M_PI))) << a;
        const double y = gridcar::wrapYaw(a);
        if (std::isfinite(a)) EXPECT_TRUE(y >= -M_PI && y < M_PI) << a << " -> " << y;
    }
}
