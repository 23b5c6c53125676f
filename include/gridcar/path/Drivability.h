#pragma once
/// @file Drivability.h
/// @brief An independent check that a path can be driven by the vehicle it was planned for:
/// the full rectangle free at every pose, densely, and the curvature within K_max.

#include "gridcar/collision/FootprintChecker.h"

#include <functional>
#include <string>
#include <vector>

namespace gridcar
{
/// Options of checkDrivable().
struct DrivabilityOptions
{
    double step{0.02};                ///< m between checked poses along the path
    double curvatureTolerance{1e-3};  ///< relative slack on K_max (rounding of sampled curves)
    /// A Reeds-Shepp path: split at its cusps (splitAtCusps()), a piece driven backwards
    /// checked with the body turned round, the reversal itself no curvature.
    bool reversing{false};
    /// 1/m^2: when positive, the curvature may change along each piece no faster than this
    /// (curvatureRateProfile(), with curvatureTolerance and a 2 % slack for sampling) — a
    /// steering wheel turns at a finite rate; 0: the rate is measured, not required.
    double maxCurvatureRate{0.0};
    /// Polled every 64 poses (a planner's termination condition): when it returns true the
    /// check stops with drivable = false and the reason that it was not finished.
    std::function<bool()> cancelled;
};

/// The verdict of checkDrivable().
struct Drivability
{
    bool drivable{false};
    std::string reason;          ///< why not (empty when drivable)
    double maxCurvature{0.0};    ///< 1/m, largest turning-angle curvature at a vertex
    /// 1/m^2, fastest change of that curvature between neighbouring vertices within a piece
    /// (a jump between two samples shows as |dk| / spacing)
    double maxCurvatureRate{0.0};
    double maxCurvatureRateAt{-1.0};  ///< m of arc length where it is
    double firstCollision{-1.0}; ///< m of arc length where the body first hits something (-1: none)
    int posesChecked{0};
};

/**
 * @brief Drivable = every pose along the polyline, at most @p options.step apart (vertices
 * included; yaw along the segment), has the full vehicle rectangle free by the exact FCL test
 * (FootprintChecker::isValidExact, not the distance-field shortcut the planners use), and the
 * path turns no tighter than K_max: at every vertex the heading change theta over half the
 * summed length of its two segments is at most K_max (the turning-angle curvature of a sampled
 * curve), and the vertex
 * lies within one step of the arc of radius R_min that rounds it, R_min (sec(theta / 2) - 1)
 * <= step (a long-legged sharp corner is a kink, whatever its legs' length). A grid path's
 * corners are therefore not drivable; a smoothed curve sampled finely enough may be. A path of
 * fewer than two distinct points is drivable if its pose is free.
 */
Drivability checkDrivable(const std::vector<Pose2> &path, const FootprintChecker &checker,
                          const DrivabilityOptions &options = DrivabilityOptions());

}  // namespace gridcar
