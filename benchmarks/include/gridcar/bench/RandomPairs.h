#pragma once
/// @file RandomPairs.h
/// @brief Seeded start / goal pairs on a real map for the benchmark programs (bench_native,
/// bench_drive, bench_defaults): positions where the vehicle fits at every heading, joined by the
/// free space; and the areas (a map and a vehicle) the suites run them on.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Pose2.h"
#include "gridcar/map/OccupancyGrid.h"
#include "gridcar/sim/Simulation.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
/// One area of a benchmark suite: a map, a vehicle, how far apart its pairs are.
struct BenchArea
{
    std::string name, map;  ///< map: a file under the shared folder, or "embedded"
    std::string vehicle;
    double lo, hi;          ///< m, straight-line distance of the pairs
};

/// The area's map: the embedded campus, or the file under @p shared (null, with a line on
/// stdout saying it was skipped, when the file is absent).
std::shared_ptr<const OccupancyGrid> loadAreaMap(const std::string &shared, const BenchArea &area);

/**
 * @brief @p n seeded random pairs, their straight-line distance in [@p lo, @p hi] m, on cells
 * where the circumscribed disc fits, both in one 4-connected region of the cells with
 * d_O > width / 2 (the car cannot join two regions); yaws 0 (the callers' goals are free-heading
 * or take the first fitting yaw). Fewer pairs when the map has no more (a million tries).
 */
std::vector<std::pair<Pose2, Pose2>> randomPairs(const FootprintChecker &fc, int n, unsigned seed, double lo, double hi);

/// @p p with the first of 72 yaws at which the vehicle fits (unchanged when none does).
Pose2 withFittingYaw(const FootprintChecker &fc, Pose2 p);

/// A pedestrian (a disc) that crosses @p path at @p fraction of its length, perpendicular to
/// it, and reaches the path when the vehicle would by the planned velocity profile; its size and
/// speed scale with the vehicle (a person for a car, a small object for paper C's robot). It is
/// walking for 8 s before it reaches the vehicle's lane (through walls if there are any: it is a
/// moving obstacle, not a planner), so it can be seen coming; one that steps out from standing
/// within the vehicle's braking distance could not be avoided by any follower. It stands still
/// on the far side afterwards. (bench_drive at the middle, bench_navigate.)
MovingObstacle crossingPedestrian(const std::vector<Pose2> &path, const VehicleParams &v, double fraction = 0.5);

}  // namespace gridcar
