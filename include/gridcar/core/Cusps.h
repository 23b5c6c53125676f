#pragma once
/// @file Cusps.h
/// @brief Where a path reverses (Reeds-Shepp cusps): the pieces the car drives forwards or
/// backwards, each from rest to rest.

#include "gridcar/core/Pose2.h"

#include <vector>

namespace gridcar
{
/// A stretch of a path driven in one direction.
struct PathPiece
{
    std::vector<Pose2> poses;  ///< consecutive pieces share their cusp pose
    bool backward{false};      ///< driven in reverse (the car's yaw points against the motion)
};

/**
 * @brief Splits @p path at its cusps. A step is backward when its displacement points against
 * the yaw of both its end poses, forward when along both; a step that agrees with only one
 * (a grid path's first step from a start yaw it ignores) keeps the direction before it. A
 * path with no cusp is one piece; repeated points are dropped.
 */
std::vector<PathPiece> splitAtCusps(const std::vector<Pose2> &path);

/// True if some piece of @p path is driven backwards (splitAtCusps()): a Reeds-Shepp path, or
/// a car-lattice path with reverse motion, on whatever space it was planned.
bool drivesBackwards(const std::vector<Pose2> &path);

}  // namespace gridcar
