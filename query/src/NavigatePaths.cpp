// The paths the navigation loop derives from its plans and its track (NavigatePaths.h).
#include "NavigatePaths.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/vehicle/Dynamics.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gridcar::detail
{
/// Index of the path pose nearest (x, y), searched from @p from on over the next @p window m.
std::size_t nearestAhead(const std::vector<Pose2> &path, std::size_t from, double x, double y, double window)
{
    std::size_t best = from;
    double bestD = std::hypot(path[from].x - x, path[from].y - y), along = 0.0;
    for (std::size_t i = from + 1; i < path.size() && along <= window; ++i)
    {
        along += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
        const double d = std::hypot(path[i].x - x, path[i].y - y);
        if (d < bestD) best = i, bestD = d;
    }
    return best;
}

/// The way back along the track driven (the trajectory's poses from its end, 5 cm apart at
/// the least), as long as the body is free in the working map at each pose, up to @p length m:
/// a path that retraces the drive in the other gear.
std::vector<Pose2> retreatPath(const std::vector<TrajectorySample> &track, const FootprintChecker &work, double length)
{
    std::vector<Pose2> out;
    double along = 0.0;
    for (std::size_t i = track.size(); i-- > 0 && along < length;)
    {
        const Pose2 p{track[i].x, track[i].y, track[i].yaw};
        if (!work.isValid(p)) break;
        if (!out.empty())
        {
            const double d = std::hypot(p.x - out.back().x, p.y - out.back().y);
            if (d < 0.05) continue;
            along += d;
        }
        out.push_back(p);
    }
    return out;
}

/// A path the vehicle rolling in state @p s can drive on into without stopping: its first piece
/// in the gear it rolls in, longer than its stopping distance and a half metre, with no curve so
/// near that the car must brake below 70 % of its speed to take it (the profile from its speed).
bool canDriveOn(const std::vector<Pose2> &path, const VehicleState &s, const VehicleParams &vehicle)
{
    const std::vector<PathPiece> pieces = splitAtCusps(path);
    if (pieces.empty() || pieces.front().backward != (s.v < 0)) return false;
    const double speed = std::abs(s.v);
    const std::vector<Pose2> &first = pieces.front().poses;
    if (pathLength(first) < speed * speed / (2.0 * vehicle.deceleration) + 0.5) return false;
    VehicleParams v = vehicle;
    if (pieces.front().backward)  // as the follower drives a reverse piece
    {
        v.maxSpeed = reverseSpeedLimit(vehicle);
        for (double *c : {&v.cornerSpeed45, &v.cornerSpeed90, &v.cornerSpeed135}) *c = std::min(*c, v.maxSpeed);
    }
    DrivingTimeParams dp;
    dp.startSpeed = speed;
    const VelocityProfile profile = velocityProfile(first, v, dp);
    if (profile.v.empty() || profile.v.front() < 0.7 * speed) return false;
    // the wheels must keep up: at each pose of the first 2 s and a metre, the steering the path's
    // curvature asks (over 0.3 m each side) within what the wheels turn at their rate from where
    // they are by the time the car gets there (and 0.1 rad)
    const double rate = vehicle.maxSteerRateDeg * M_PI / 180.0;
    if (!(rate > 0)) return true;
    const double wheels = pieces.front().backward ? -s.steer : s.steer;  // in the frame of the motion
    std::vector<double> cum{0.0}, heading;
    for (std::size_t i = 1; i < first.size(); ++i)
    {
        cum.push_back(cum.back() + std::hypot(first[i].x - first[i - 1].x, first[i].y - first[i - 1].y));
        heading.push_back(std::atan2(first[i].y - first[i - 1].y, first[i].x - first[i - 1].x));
    }
    for (std::size_t i = 0; i < heading.size() && cum[i] <= 2.0 * speed + 1.0; ++i)
    {
        std::size_t a = i, b = i;
        while (a > 0 && cum[i] - cum[a] < 0.3) --a;
        while (b + 1 < heading.size() && cum[b] - cum[i] < 0.3) ++b;
        if (b <= a || cum[b] - cum[a] < 1e-6) continue;
        const double want = std::atan(vehicle.wheelbase * wrapAngle(heading[b] - heading[a]) / (cum[b] - cum[a]));
        if (std::abs(want - wheels) > rate * cum[i] / std::max(speed, 1e-3) + 0.1) return false;
    }
    return true;
}

/// Where the vehicle at @p s, having rolled on while the plan was made, joins @p path: the index
/// of its nearest pose over the first @p within metres, when that is within 0.2 m and 15 degrees
/// of the vehicle (npos otherwise).
std::size_t joinAt(const std::vector<Pose2> &path, const VehicleState &s, double within)
{
    std::size_t best = std::string::npos;
    double bestD = 0.2, along = 0.0;
    for (std::size_t i = 0; i < path.size() && along <= within; ++i)
    {
        if (i) along += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
        const double d = std::hypot(path[i].x - s.x, path[i].y - s.y);
        if (d < bestD && std::abs(wrapAngle(path[i].yaw - s.yaw)) < 15.0 * M_PI / 180.0) best = i, bestD = d;
    }
    return best;
}


}  // namespace gridcar::detail
