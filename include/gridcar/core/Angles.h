#pragma once
/// @file Angles.h
/// @brief Angle wrapping, in one place.

#include <cmath>

namespace gridcar
{
/// @p a mapped into [-pi, pi] (std::remainder: a heading difference, either sign). An angle
/// already in range is returned as it is, as std::remainder would (the same bits); the check
/// spares the searches and smoothers a libm call that sets and restores the rounding mode.
inline double wrapAngle(double a)
{
    if (a >= -M_PI && a <= M_PI) return a;
    return std::remainder(a, 2.0 * M_PI);
}

/// @p yaw mapped into OMPL's SO2 range [-pi, pi) (OMPL 1.5 rejects exactly +pi and its
/// distance() asserts on it).
inline double wrapYaw(double yaw)
{
    double y = wrapAngle(yaw);
    if (y >= M_PI) y -= 2.0 * M_PI;
    return y;
}

/// Direction of the segment a -> b (rad).
template <class P>
double headingOf(const P &a, const P &b)
{
    return std::atan2(b.y - a.y, b.x - a.x);
}

}  // namespace gridcar
