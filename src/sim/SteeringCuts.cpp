// Where the follower stops to turn its wheels at a standstill: a path cut at its steering jumps.
#include "sim/SteeringCuts.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Cusps.h"

#include <algorithm>
#include <cmath>

namespace gridcar::detail
{
namespace
{
/// m: closer to the map than this, a steering jump is cut (see SteeringCuts.h)
constexpr double kTightClearance = 0.15;
}  // namespace

std::vector<std::vector<Pose2>> cutAtSteeringJumps(const std::vector<Pose2> &poses, const FootprintChecker &checker)
{
    const VehicleParams &veh = checker.vehicle();
    std::vector<Pose2> pts;
    for (const Pose2 &p : poses)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    if (pts.size() < 4) return {poses};
    std::vector<double> cum{0.0}, heading;
    for (std::size_t i = 1; i < pts.size(); ++i)
    {
        cum.push_back(cum.back() + std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y));
        heading.push_back(std::atan2(pts[i].y - pts[i - 1].y, pts[i].x - pts[i - 1].x));
    }
    // wheel angle at each inner vertex (turning-angle curvature, as the drivable check measures)
    std::vector<double> wheel(pts.size(), 0.0);
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double ds = 0.5 * (cum[i + 1] - cum[i - 1]);
        const double k = wrapAngle(heading[i] - heading[i - 1]) / ds;
        if (std::abs(k) > 1.05 * veh.maxCurvature()) return {poses};  // not followable: paper C's rule alone
        wheel[i] = std::atan(veh.wheelbase * k);
    }
    wheel.front() = wheel[1];
    wheel.back() = wheel[pts.size() - 2];
    const double rate = veh.maxSteerRateDeg * M_PI / 180.0, crawl = std::min(0.1 * veh.maxSpeed, 0.5);
    std::vector<std::size_t> cuts;
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double ds = cum[i + 1] - cum[i];
        if (std::abs(wheel[i + 1] - wheel[i]) <= rate * ds / crawl + 1e-9) continue;
        // the jump is spread over the two vertices round a primitive's joint: cut at the first
        if (cum[i] < 0.3 || cum.back() - cum[i] < 0.3) continue;
        if (!cuts.empty() && cum[i] - cum[cuts.back()] < 0.3) continue;
        bool tight = false;
        for (std::size_t j = i; j < pts.size() && cum[j] - cum[i] <= 2.0 && !tight; ++j)
            tight = checker.clearance(pts[j].x, pts[j].y, pts[j].yaw) < kTightClearance;
        if (tight) cuts.push_back(i);
    }
    if (cuts.empty()) return {poses};
    std::vector<std::vector<Pose2>> out;
    std::size_t from = 0;
    for (std::size_t c : cuts)
    {
        out.emplace_back(pts.begin() + std::ptrdiff_t(from), pts.begin() + std::ptrdiff_t(c) + 1);
        from = c;
    }
    out.emplace_back(pts.begin() + std::ptrdiff_t(from), pts.end());
    return out;
}

}  // namespace gridcar::detail
