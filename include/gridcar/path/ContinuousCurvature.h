#pragma once
/// @file ContinuousCurvature.h
/// @brief Curvature that a steering wheel can follow: where a path's curvature jumps (a
/// lattice's straight meeting a full-lock arc, arcs of opposite sides), a stretch of it is
/// replaced by a curvature-continuous (G2) quintic whose curvature stays within K_max and
/// changes no faster than the vehicle's curvature rate; the rest of the path, its cusps and its
/// end poses are kept.

#include "gridcar/core/Pose2.h"

#include <array>
#include <functional>
#include <vector>

namespace gridcar
{
/**
 * @brief A quintic curve p(u), u in [0, 1], with given end points, unit tangents, curvatures
 * and tangent magnitude eta at both ends (G2 Hermite interpolation: the eta^2-spline of
 * Piazzi et al. with the second-derivative tangential parts zero).
 *
 * @par External documentation
 * A. Piazzi, C. Guarino Lo Bianco, M. Romano, "eta^3-splines for the smooth path generation of
 * wheeled mobile robots", IEEE Trans. Robotics 23(5), 2007 (G2 / G3 interpolating splines).
 */
class G2Quintic
{
public:
    /// From pose @p a with signed curvature @p ka to pose @p b with @p kb; yaws are the
    /// direction of motion; @p eta > 0 (m) scales both end tangents.
    G2Quintic(const Pose2 &a, double ka, const Pose2 &b, double kb, double eta);
    /// The position and its first three derivatives at @p u: d[k] = (x, y) of the k-th
    /// derivative.
    std::array<std::array<double, 2>, 4> derivatives(double u) const;
    /// Signed curvature at @p u (1/m).
    double curvature(double u) const;
    /// d(curvature)/d(arc length) at @p u (1/m^2).
    double curvatureRate(double u) const;
    /// Control points of the same curve as a quintic Bezier (for tests against a spline library).
    std::array<std::array<double, 2>, 6> bezierPoints() const;

private:
    std::array<std::array<double, 2>, 6> c_;  ///< power-basis coefficients: p(u) = sum c_k u^k
};

/// Options of smoothCurvature().
struct CurvatureSmoothingOptions
{
    double maxCurvature{0.0};      ///< K_max (1/m), > 0
    double maxCurvatureRate{0.0};  ///< sigma (1/m^2), > 0
    double step{0.05};             ///< m between the poses written for a replaced stretch
    /// Split at cusps (splitAtCusps()); each piece is smoothed on its own, its cusps and ends kept.
    bool reversing{false};
    /// Allowed growth of a replaced stretch's length (a replacement may not be longer than
    /// the stretch it replaces by more than this fraction).
    double maxLengthGrowth{0.01};
    /// True if the car is free along these consecutive poses (the first is the stretch's start,
    /// the body at each pose's yaw). Required.
    std::function<bool(const std::vector<Pose2> &)> free;
    /// Polled between stretches; when it returns true the input stays as it was where not yet done.
    std::function<bool()> cancelled;
};

/// What smoothCurvature() did.
struct CurvatureSmoothing
{
    std::vector<Pose2> path;  ///< the path: replaced stretches and the input's other poses
    int stretches{0};         ///< stretches whose curvature changed too fast
    int replaced{0};          ///< of them, replaced by a G2 quintic
    bool cancelled{false};    ///< stopped by CurvatureSmoothingOptions::cancelled
    /// Largest curvature rate left (1/m^2, curvatureRateProfile()): within the limit when every
    /// stretch was replaced.
    double maxRate{0.0};
};

/**
 * @brief Replaces each stretch of @p path where the curvature changes faster than
 * @p options.maxCurvatureRate (a jump between two samples) by a G2 quintic from the last pose
 * before it to the first after it, with the curvature there kept, so that curvature is
 * continuous and its rate within the limit. A candidate is kept only if its curvature stays
 * within K_max, its rate within the limit, it turns through the same angle as the stretch, it is
 * at most maxLengthGrowth longer, and the body is free along it (options.free); otherwise wider
 * stretches and other tangent magnitudes are tried, and if none passes the stretch is kept as it
 * was. The path's first and last poses and its cusps are never moved. Yaws are taken as the
 * direction of the body (reversed pieces: opposite to the motion), as planners write them.
 * Throws std::invalid_argument without a free test or with a limit that is not positive.
 */
CurvatureSmoothing smoothCurvature(const std::vector<Pose2> &path, const CurvatureSmoothingOptions &options);

/**
 * @brief Replaces each turn of @p path (a run of poses whose heading changes, runs less than
 * 0.5 m apart joined) by a wider one where that is free: a G2 quintic from a pose on the
 * straight before it to one on the straight after it, with curvature 0 at both, reaching up to
 * twice the turn's length into each straight (at most half way to the next turn), the widest
 * that passes first. A candidate is kept only if its curvature stays within K_max, its rate
 * within the limit, it turns through the same angle, it is no longer than the stretch it
 * replaces and the body is free along it (options.free); otherwise the turn stays as it was.
 * For paths whose curvature already stays within the rate (clothoid turns at full lock): a
 * wider turn is driven faster (the speed limit sqrt(a_lat / k)) and is shorter. Ends and cusps
 * are kept; options.maxLengthGrowth is not used (never longer). Throws as smoothCurvature().
 */
CurvatureSmoothing widenTurns(const std::vector<Pose2> &path, const CurvatureSmoothingOptions &options);

/// The curvature along a sampled curve and its rate, from the polyline alone (turning angle at
/// each vertex over half its two segments; rate = the change between neighbouring vertices over
/// the segment between them). Used by checkDrivable() and the tests.
struct CurvatureProfile
{
    std::vector<double> curvature;  ///< at vertices 1..n-2 of the de-duplicated polyline
    double maxCurvature{0.0};
    double maxRate{0.0};            ///< 1/m^2
    double maxRateAt{-1.0};         ///< m of arc length of the vertex with maxRate (-1: none)
};
/// The profile of one piece driven in one direction (no cusps in it); @p s0 is added to
/// maxRateAt.
CurvatureProfile curvatureRateProfile(const std::vector<Pose2> &piece, double s0 = 0.0);

}  // namespace gridcar
