#pragma once
/// @file RandomPairs.h
/// @brief Seeded start / goal pairs on a real map for the benchmark programs (bench_native,
/// bench_drive): positions where the vehicle fits at every heading, joined by the free space.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Pose2.h"

#include <utility>
#include <vector>

namespace gridcar
{
/**
 * @brief @p n seeded random pairs, their straight-line distance in [@p lo, @p hi] m, on cells
 * where the circumscribed disc fits, both in one 4-connected region of the cells with
 * d_O > width / 2 (the car cannot join two regions); yaws 0 (the callers' goals are free-heading
 * or take the first fitting yaw). Fewer pairs when the map has no more (a million tries).
 */
std::vector<std::pair<Pose2, Pose2>> randomPairs(const FootprintChecker &fc, int n, unsigned seed, double lo, double hi);

/// @p p with the first of 72 yaws at which the vehicle fits (unchanged when none does).
Pose2 withFittingYaw(const FootprintChecker &fc, Pose2 p);

}  // namespace gridcar
