#pragma once
// Where the follower stops to turn its wheels at a standstill (private to gridcar_core).
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Pose2.h"

#include <vector>

namespace gridcar::detail
{
/// Where a piece's curvature jumps faster than the wheels can follow at a crawl (a lattice
/// path's arcs at full lock against straights or the opposite lock) in a tight spot, the piece
/// is cut: the car stops there and turns its wheels at a standstill before it goes on, as a
/// driver does in a tight manoeuvre. Driven through, such a jump leaves the heading lagging by about half the
/// jump times the distance the wheels take to turn (0.1 rad for paper C's car reversing into a
/// parallel slot), which a body a few centimetres from a parked car has no room for. A jump is
/// a change of the wheel angle, atan(wheelbase x curvature), between two neighbouring vertices
/// of more than the steering rate turns while the car crawls (min(0.1 v_max, 0.5 m/s)) over
/// the step between them, where the body on the path passes within kTightClearance (0.15 m) of the map
/// in the next 2 m (in the open the lag costs nothing, and a stop there only time); cuts closer
/// than 0.3 m to the last one, or to either end, are merged away. A path that is not followable
/// (a grid path's kinks, beyond K_max) is not cut. @p poses carry the body's yaw.
std::vector<std::vector<Pose2>> cutAtSteeringJumps(const std::vector<Pose2> &poses, const FootprintChecker &checker);

}  // namespace gridcar::detail
