#pragma once
/// @file PathMetrics.h
/// @brief Path measures shared by the CLI, the benchmarks and the simulation.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Cusps.h"

#include <vector>

namespace gridcar
{
/// Parameters of the turn count (see computePathMetrics()).
struct TurnParams
{
    double sampleStep{0.25};    ///< m, resampling step
    double window{3.0};         ///< m, chord length before / after each sample
    double thresholdDeg{15.0};  ///< a turn: net heading change above this over the window
};

/// Measures of a path of poses (only positions matter except for clearance).
struct PathMetrics
{
    double length{0.0};         ///< m, sum of segment lengths
    int turns{0};               ///< number of turns (see computePathMetrics())
    double maxTurnDeg{0.0};     ///< largest heading change at one turning point, degrees (depends on the sampling)
    /// Largest heading change of one turn (as `turns` counts them), degrees: the same for a
    /// sharp corner and for the arc or the densely sampled curve that drives it
    double maxTurnAngleDeg{0.0};
    int turningPoints{0};       ///< vertices where the heading changes (collinear ones removed)
    double minClearance{0.0};   ///< m, FootprintChecker::clearance minimum along the path
    double minPathDistance{0.0}; ///< m, smallest obstacle distance d_O of the path line itself (paper I's "nearest distance to the curb")
    double maxCurvature{0.0};   ///< 1/m, largest Menger curvature of consecutive vertices (maxMengerCurvature())
    int cusps{0};               ///< reversals (with `reversing`: Reeds-Shepp paths; splitAtCusps())
};

/**
 * @brief Length, turns, max turning angle and clearance of a path.
 *
 * - Turning points: vertices left after dropping repeated and collinear points (heading
 *   change below 1e-6 rad); maxTurnDeg is the largest heading change at one of them (paper I's
 *   "maximum turning angle").
 * - Turns: the path is resampled every TurnParams::sampleStep metres; at each sample the
 *   direction of the chord over the TurnParams::window metres before it is compared with the
 *   chord over the window after it; a turn is a maximal stretch of samples where they differ
 *   by more than TurnParams::thresholdDeg. So a 90-degree corner is one turn whether it is a
 *   sharp grid corner or a smooth arc, while a grid staircase (E, NE, E, NE, ...) or a zigzag
 *   around a straight line is no turn. Corners closer than one window to either end of the
 *   path are not counted. maxTurnAngleDeg is the largest heading change of one turn, from the
 *   chord before its first sample to the chord after its last: it does not depend on how
 *   densely the path is sampled (maxTurnDeg does: a smooth 90-degree arc at 5 cm steps turns
 *   some degrees per vertex).
 * - Max curvature: maxMengerCurvature() (PostProcess.h) of the vertices: for a smooth, densely
 *   sampled path the curvature the vehicle must drive; for a grid path it scores the sharpest
 *   corner (2 sin(theta) / chord).
 * - Path distance: DistanceField::distance (bilinear d_O) at the same points as clearance: how
 *   far the path line stays from obstacle cell centres (paper I's metric; > D/2 keeps a
 *   vehicle centred on the line off the curb sideways).
 * - Clearance: FootprintChecker::clearance at the path's poses and at points every half cell
 *   along each segment (yaw of the segment, reversed on a piece driven backwards); 0 if any of
 *   them collides.
 * - With @p reversing (a path of a Reeds-Shepp space), the path is split at its cusps
 *   (splitAtCusps()) and each piece measured on its own: the reversal itself is no turn and no
 *   curvature; `cusps` counts them. Without it every step counts as forward.
 */
PathMetrics computePathMetrics(const std::vector<Pose2> &path, const FootprintChecker *checker,
                               const TurnParams &turnParams = TurnParams(), bool reversing = false);

/// Length (m) of the polyline through @p path's positions (0 for fewer than two poses).
double pathLength(const std::vector<Pose2> &path);

}  // namespace gridcar
