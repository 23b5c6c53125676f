#pragma once
/// @file PostProcess.h
/// @brief Paper I's path post-processing: turning points, turning-point adjustment under a
/// maximum curvature, quadratic Bezier smoothing. Works on any planner's path.

#include "gridcar/collision/FootprintChecker.h"

#include <string>
#include <functional>
#include <vector>

namespace gridcar
{
/// Options of smoothPath().
struct SmoothingParams
{
    double maxCurvature{0.0};  ///< K_max, 1/m; 0 = the checker's vehicle (tan(phi_max) / wheelbase)
    bool lineOfSight{true};    ///< also drop turning points whose neighbours see each other (see smoothPath())
    bool adjust{true};         ///< run the turning-point adjustment (section 3.4)
    int maxAdjustSteps{40};    ///< one-cell moves allowed per turning point
    bool bezier{true};         ///< quadratic Bezier smoothing (section 3.5)
    double sampleStep{0.0};    ///< m between Bezier samples; 0 = a quarter cell
    /// Polled between corners and legs (a planner's termination condition): when it returns
    /// true smoothPath() stops and returns the input path (SmoothingResult::cancelled).
    std::function<bool()> cancelled;
};

/// What happened at one interior turning point.
struct CornerReport
{
    Pose2 point;                 ///< the turning point after adjustment (yaw unused)
    double turnDeg{0.0};         ///< heading change at it
    double parabolaCurvature{0}; ///< paper I's K of the parabola through the triple, after adjustment
    double bezierCurvature{0};   ///< largest curvature of the Bezier piece round it (1/m)
    int moves{0};                ///< one-cell moves the adjustment made
    bool curvatureOk{false};     ///< both curvatures < K_max after the adjustment
    bool smoothed{false};        ///< the Bezier piece is in the output (false: it collided, the corner was kept)
};

/// Result of smoothPath().
struct SmoothingResult
{
    std::vector<Pose2> turningPoints;  ///< after redundant-point removal (input order)
    int latticeTurningPoints{0};       ///< turning points before the line-of-sight pass
    std::vector<Pose2> adjusted;       ///< after the adjustment (same count)
    std::vector<Pose2> path;           ///< output: dense poses, yaw along the path
    std::vector<CornerReport> corners; ///< one per interior turning point of `adjusted`
    int adjustFailures{0};             ///< corners still at or above K_max after the adjustment
    int bezierFallbacks{0};            ///< corners kept sharp because their Bezier piece collided
    double maxCurvature{0.0};          ///< of the output path (Menger curvature of its samples), 1/m
    double seconds{0.0};               ///< wall time of the whole post-processing
    /// Set by the planners that smooth an exact solution: why the smoothed path failed the
    /// independent drivable check (checkDrivable()); the solution is then only approximate
    std::string notDrivable;
    /// SmoothingParams::cancelled stopped the smoothing: `path` is the input path, unsmoothed.
    bool cancelled{false};
};

/**
 * @brief Redundant point removal: the vertices of @p path where the direction changes (first
 * and last point always kept; repeated points and points on a straight line dropped).
 */
std::vector<Pose2> turningPoints(const std::vector<Pose2> &path);

/**
 * @brief Paper I's curvature of the parabola through three points at the middle one:
 * K = |y''| / (1 + y'^2)^(3/2) for y = a x^2 + b x + c. The points are first rotated into a
 * frame whose x axis runs from @p p0 to @p p2, so vertical segments (where y(x) is not a
 * function in map axes) are handled. +inf if the three x values are not distinct in that
 * frame (a reversal), 0 for collinear points.
 */
double parabolaCurvature(const Pose2 &p0, const Pose2 &p1, const Pose2 &p2);

/**
 * @brief The symmetric quadratic Bezier piece round the corner @p p1 between neighbours @p p0
 * and @p p2: end points at distance a along both legs, a = half the shorter leg (the whole leg
 * where the neighbour is the path's start or end, flags @p p0IsEnd / @p p2IsEnd), control point
 * @p p1. Its largest curvature is sin(theta/2) / (a cos^2(theta/2)) for a heading change theta.
 */
struct BezierCorner
{
    Pose2 a, p, c;  ///< start, control, end
    double maxCurvature{0.0};
};
BezierCorner bezierCorner(const Pose2 &p0, const Pose2 &p1, const Pose2 &p2, bool p0IsEnd, bool p2IsEnd);

/**
 * @brief Paper I's post-processing of any path (grid or sampling planner).
 *
 * 1. Redundant point removal (step 1 of section 3.4, after the paper's reference [11]):
 *    turningPoints(), then, with SmoothingParams::lineOfSight, a greedy line-of-sight pass:
 *    from each kept point the farthest later turning point reachable by a collision-free
 *    straight leg (swept footprint at the leg's heading) is kept next. This removes the
 *    staircase jogs an 8-heading lattice makes along slanted roads.
 * 2. Adjustment (section 3.4), corner by corner along the path: K = max(parabola curvature
 *    through the triple at the middle point (eq. 9-10), largest curvature of the Bezier piece
 *    that will replace the corner). While K >= K_max the middle point moves by one cell to the
 *    8-neighbour position of least K whose two straight legs are collision-free (swept
 *    footprint); it stops when no move lowers K. Eq. 11 picks one direction from the sign of a
 *    and the side of the axis of symmetry; trying the 8 neighbours contains that move and also
 *    covers the cases eq. 11 leaves open (vertical legs, a point on the axis). The Bezier's
 *    curvature is part of K because the parabola through the three points is not the curve
 *    the vehicle drives: a corner whose parabola is flat enough can still have a Bezier piece
 *    sharper than K_max.
 * 3. Smoothing (section 3.5, eq. 13): each corner is replaced by its BezierCorner, sampled every
 *    SmoothingParams::sampleStep, with straight pieces between; a piece whose sampled poses
 *    (yaw = tangent) fail FootprintChecker::isMotionValid is replaced by the unsmoothed corner.
 *
 * Failures are reported per corner (CornerReport), not hidden. The output path's curvature is
 * <= K_max on every corner with curvatureOk && smoothed.
 */
SmoothingResult smoothPath(const std::vector<Pose2> &path, const FootprintChecker &checker,
                           const SmoothingParams &params = SmoothingParams());

/// Largest Menger curvature (1/m) over consecutive distinct point triples of @p path: the
/// discrete curvature of a polyline (a sharp corner between short segments scores high).
double maxMengerCurvature(const std::vector<Pose2> &path);

}  // namespace gridcar
