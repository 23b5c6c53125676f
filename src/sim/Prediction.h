#pragma once
// Where a moving obstacle's course meets the vehicle's body on the path ahead (private to
// gridcar_core; used by the follower's stopping-distance rule, sim/Follower.h).
#include "gridcar/sim/Simulation.h"

#include "sim/TrackedPath.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar::detail
{
/**
 * The free distance along @p path from @p sProj before the body would meet the course of an
 * obstacle (radius @p r, at @p mx, @p my, velocity @p vx, @p vy as measured, extrapolated over
 * @p horizon s): the first path pose within @p range whose body (the vehicle's rectangle, grown
 * by r and 0.1 m sideways) the course enters at any time within the horizon, less 0.3 m;
 * infinity when none does. Whenever the vehicle would get there counts: a vehicle that slows for
 * a bend ahead would otherwise meet an obstacle it expected to miss; it yields, then goes on
 * once the course has left its way. The body along the path, not a straight lane, so an
 * obstacle crossing in a bend is seen where it crosses.
 */
inline double courseAhead(const TrackedPath &path, std::size_t seg, double sProj, double range, const VehicleParams &veh,
                          double mx, double my, double r, double vx, double vy, double horizon)
{
    if (std::hypot(vx, vy) < 1e-6) return std::numeric_limits<double>::infinity();
    const double front = std::max(veh.length - veh.rearOverhang, 0.0), rear = veh.rearOverhang;
    const double reach = veh.width / 2 + r + 0.1;
    const auto &pts = path.pts;
    for (std::size_t i = seg; i < pts.size() && path.cum[i] <= sProj + range; ++i)
    {
        if (path.cum[i] < sProj) continue;
        const double hx = std::cos(path.heading[i]), hy = std::sin(path.heading[i]);
        for (double tau = 0.0; tau <= horizon; tau += 0.2)
        {
            const double ox = mx + vx * tau - pts[i].x, oy = my + vy * tau - pts[i].y;
            const double a = ox * hx + oy * hy, l = std::abs(-ox * hy + oy * hx);
            if (a > -rear - r && a < front + r && l < reach) return std::max(path.cum[i] - sProj - 0.3, 0.0);
        }
    }
    return std::numeric_limits<double>::infinity();
}

}  // namespace gridcar::detail
