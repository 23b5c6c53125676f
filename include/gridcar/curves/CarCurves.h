#pragma once
/// @file CarCurves.h
/// @brief Shortest paths of a car with a bounded turning radius: Dubins curves (forwards only)
/// and Reeds-Shepp curves (forwards and backwards), computed by gridcar's own code.
///
/// OMPL 1.5.2 as Debian ships it is built with assertions, and its Dubins code asserts on
/// rounding errors that some pose pairs produce: the process dies. These functions never
/// assert: every candidate word is integrated to its end pose and kept only when it lands on
/// the goal (to 1e-6 of the radius and 1e-6 rad), so a rounding error drops a candidate
/// instead of killing the caller. No OMPL type appears here (the spaces layer wraps these in
/// OMPL state spaces: spaces/CurveSpaces.h).
///
/// @par External documentation
/// L. E. Dubins, "On curves of minimal length with a constraint on average curvature, and with
/// prescribed initial and terminal positions and tangents", American Journal of Mathematics
/// 79(3):497-516, 1957. A. M. Shkel and V. Lumelsky, "Classification of the Dubins set",
/// Robotics and Autonomous Systems 34(4):179-202, 2001 (the six words' formulas).
/// J. A. Reeds and L. A. Shepp, "Optimal paths for a car that goes both forwards and
/// backwards", Pacific Journal of Mathematics 145(2):367-393, 1990 (sections 8.1-8.11: the
/// 48 candidate words, from 9 formulas by time-flip, reflection and reversal).

#include "gridcar/core/Pose2.h"

#include <array>
#include <vector>

namespace gridcar
{
/// One piece of a car curve: an arc turning left, a straight line or an arc turning right.
enum class Steer : unsigned char
{
    Left,
    Straight,
    Right
};

/// A piece of a curve: its steering and its signed length in metres (negative: driven
/// backwards; an arc's heading change is length / radius, its sign from Steer and gear).
struct CurveSegment
{
    Steer steer{Steer::Straight};
    double length{0.0};
};

/**
 * @brief A Dubins or Reeds-Shepp curve from a start pose: at most five segments of one turning
 * radius. Empty (length infinite) when no curve was found, which for these two families
 * happens only for non-finite input or a radius that is not > 0.
 */
struct CarCurve
{
    std::array<CurveSegment, 5> segments{};
    int count{0};
    double radius{1.0};
    double length{0.0};  ///< sum of |segment length| (m); infinity when no curve was found

    /// True when no curve was found (a curve between equal poses has no segment, length 0).
    bool empty() const { return !(length < 1e300); }
    /// Number of gear changes (cusps): consecutive pieces of opposite sign, pieces of length 0
    /// skipped. A curve keeps its whole word, pieces of length 0 included.
    int cusps() const;
};

/// The pose at arc length @p s (clamped to [0, curve.length]) along @p curve from @p start.
/// The yaw is not wrapped (start.yaw plus the turned angle).
Pose2 curvePose(const Pose2 &start, const CarCurve &curve, double s);

/// The pose after one segment driven from @p from at turning radius @p radius.
Pose2 driveSegment(const Pose2 &from, const CurveSegment &seg, double radius);

/// The shortest forward-only (Dubins) curve from @p a to @p b at turning radius @p radius > 0
/// (the six words LSL, RSR, LSR, RSL, RLR, LRL).
CarCurve dubinsCurve(const Pose2 &a, const Pose2 &b, double radius);

/// The shortest Reeds-Shepp curve from @p a to @p b at turning radius @p radius > 0 (the 48
/// words of Reeds and Shepp; cusps allowed).
CarCurve reedsSheppCurve(const Pose2 &a, const Pose2 &b, double radius);

/// The @p maxCount shortest distinct Dubins curves from @p a to @p b (shortest first; the first
/// is dubinsCurve()): the other words are the alternatives an analytic expansion tries when the
/// shortest one is blocked. Empty for non-finite input or a radius that is not > 0.
std::vector<CarCurve> dubinsCurves(const Pose2 &a, const Pose2 &b, double radius, int maxCount);
/// The same for Reeds-Shepp curves (the first is reedsSheppCurve()).
std::vector<CarCurve> reedsSheppCurves(const Pose2 &a, const Pose2 &b, double radius, int maxCount);

}  // namespace gridcar
