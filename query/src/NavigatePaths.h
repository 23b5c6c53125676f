#pragma once
// The paths the navigation loop derives from its plans and its track: where the vehicle stands
// on the plan, the way back along its track, whether a rolling vehicle can drive on into a new
// plan and where it joins it (private to gridcar_query; see Navigate.cpp).
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/sim/Simulation.h"

#include <cstddef>
#include <vector>

namespace gridcar::detail
{
/// Index of the path pose nearest (x, y), searched from @p from on over the next @p window m.
std::size_t nearestAhead(const std::vector<Pose2> &path, std::size_t from, double x, double y, double window = 10.0);

/// The way back along the track driven (the trajectory's poses from its end, 5 cm apart at
/// the least), as long as the body is free in the working map at each pose, up to @p length m:
/// a path that retraces the drive in the other gear.
std::vector<Pose2> retreatPath(const std::vector<TrajectorySample> &track, const FootprintChecker &work, double length);

/// A path the vehicle rolling in state @p s can drive on into without stopping: its first piece
/// in the gear it rolls in, longer than its stopping distance and a half metre, with no curve so
/// near that the car must brake below 70 % of its speed to take it (the profile from its speed),
/// nor one its wheels cannot turn to at their rate in time (0.1 rad of slack).
bool canDriveOn(const std::vector<Pose2> &path, const VehicleState &s, const VehicleParams &vehicle);

/// Where the vehicle at @p s, having rolled on while the plan was made, joins @p path: the index
/// of its nearest pose over the first @p within metres, when that is within 0.2 m and 15 degrees
/// of the vehicle (npos otherwise).
std::size_t joinAt(const std::vector<Pose2> &path, const VehicleState &s, double within);

}  // namespace gridcar::detail
