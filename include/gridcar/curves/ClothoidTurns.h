#pragma once
/// @file ClothoidTurns.h
/// @brief Turns whose curvature changes continuously, at most at a given rate: a clothoid from
/// curvature 0 up to the peak, an arc at the peak (at most 1 / R), a clothoid back to 0; and
/// the curves of two such turns joined by a straight line that a forward-driving car takes
/// from one pose to another (the analytic expansion of a search whose primitives are such
/// turns: every path it ends keeps the curvature rate).
///
/// @par External documentation
/// T. Fraichard and A. Scheuer, "From Reeds and Shepp's to continuous-curvature paths", IEEE
/// Transactions on Robotics 20(6):1025-1035, 2004 (CC turns: a clothoid, an arc, a clothoid;
/// CC-Dubins paths of such turns and straight lines). This is the turn-straight-turn part of
/// that family, solved numerically for both deflections, not their closed-form construction.
#include "gridcar/core/Pose2.h"

#include <vector>

namespace gridcar
{
/**
 * @brief A symmetric turn of deflection delta (rad, left > 0): curvature rising at sigma
 * (1/m^2) from 0, held at min(1 / R, sqrt(|delta| sigma)) on an arc when it reaches 1 / R,
 * falling at sigma back to 0. The clothoid is tabulated once (Simpson's rule, 1 mm steps) and
 * read with cubic Hermite interpolation on its exact tangent: poses to about 1e-9 m.
 * Throws std::invalid_argument unless R > 0 and sigma > 0 are finite.
 */
class ClothoidTurn
{
public:
    ClothoidTurn(double radius, double sigma);
    double radius() const { return radius_; }
    double sigma() const { return sigma_; }
    /// Arc length of the turn of deflection @p delta (m).
    double length(double delta) const;
    /// Pose at arc length @p s (clamped to the turn) of the turn of deflection @p delta that
    /// starts at the origin heading along +x.
    Pose2 pose(double delta, double s) const;
    /// Signed curvature at arc length @p s of that turn (1/m).
    double curvature(double delta, double s) const;

private:
    /// The clothoid from curvature 0 at sharpness sigma: position at arc length u.
    void clothoid(double u, double &x, double &y) const;
    double radius_, sigma_, h_;
    std::vector<double> x_, y_;  ///< the clothoid at u = i h, up to curvature 1 / R
};

/// A turn, a straight line, a turn (deflections signed, left > 0): forwards from `start`.
struct ClothoidCurve
{
    Pose2 start;
    double delta1{0.0}, straight{0.0}, delta2{0.0};
    double length{0.0};  ///< m; infinity when no curve was found
    bool empty() const { return !(length < 1e300); }
    /// Total turning, |delta1| + |delta2| (rad).
    double turning() const;
};

/**
 * @brief The @p maxCount shortest turn-straight-turn curves from @p a to @p b with @p turn's
 * turns (words LSL, RSR, LSR, RSL; each turn from 0 to under a full circle), shortest first.
 * Each is kept only when integrating it lands on @p b to 1e-7 m and 1e-7 rad. Empty when
 * there is none (for example two poses too close for any turn between them).
 */
std::vector<ClothoidCurve> clothoidCurves(const Pose2 &a, const Pose2 &b, const ClothoidTurn &turn, int maxCount);

/// The pose at arc length @p s (clamped) along @p curve (the yaw wrapped to [-pi, pi)).
Pose2 clothoidCurvePose(const ClothoidCurve &curve, const ClothoidTurn &turn, double s);

}  // namespace gridcar
