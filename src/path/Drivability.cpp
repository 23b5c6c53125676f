#include "gridcar/path/Drivability.h"

#include "gridcar/core/Angles.h"
#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/core/Cusps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridcar
{
namespace
{
/// The body along one piece (yaw of each segment, turned round when driven backwards) and its
/// curvature; @p s0 is the arc length where the piece starts.
/// Returns false when options.cancelled stopped it.
bool checkPiece(const std::vector<Pose2> &pts, bool backward, double s0, const FootprintChecker &checker,
                const DrivabilityOptions &options, double step, Drivability &d, double &worstDeviation)
{
    double s = s0;
    for (std::size_t i = 1; i < pts.size() && d.firstCollision < 0; ++i)
    {
        if ((i & 63) == 0 && options.cancelled && options.cancelled()) return false;
        const Pose2 &a = pts[i - 1], &b = pts[i];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const double yaw = std::atan2(b.y - a.y, b.x - a.x) + (backward ? M_PI : 0.0);
        const int n = std::max(1, int(std::ceil(len / step)));
        for (int k = 0; k <= n; ++k)  // each vertex at the yaw of both its segments
        {
            const double t = double(k) / n;
            ++d.posesChecked;
            if (!checker.isValidExact(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), yaw))
            {
                d.firstCollision = s + t * len;
                break;
            }
        }
        s += len;
    }
    // curvature at each vertex: the heading change over the arc between the midpoints of its
    // segments (half their summed length, the usual turning-angle estimate); and a
    // kink must lie within one step of the curve of radius R_min that rounds it
    const double kmax = checker.vehicle().maxCurvature();
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double l0 = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
        const double l1 = std::hypot(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
        const double theta = std::abs(wrapAngle(headingOf(pts[i], pts[i + 1]) - headingOf(pts[i - 1], pts[i])));
        d.maxCurvature = std::max(d.maxCurvature, theta / (0.5 * (l0 + l1)));
        if (std::isfinite(kmax) && theta > 1e-9)
            worstDeviation = std::max(worstDeviation, theta >= M_PI - 1e-9 ? HUGE_VAL : (1.0 / std::cos(theta / 2) - 1.0) / kmax);
    }
    const CurvatureProfile prof = curvatureRateProfile(pts, s0);
    if (prof.maxRate > d.maxCurvatureRate)
    {
        d.maxCurvatureRate = prof.maxRate;
        d.maxCurvatureRateAt = prof.maxRateAt;
    }
    return true;
}
}  // namespace

Drivability checkDrivable(const std::vector<Pose2> &path, const FootprintChecker &checker, const DrivabilityOptions &options)
{
    Drivability d;
    std::vector<Pose2> pts;
    for (const Pose2 &p : path)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    if (pts.empty())
    {
        d.reason = "empty path";
        return d;
    }
    if (pts.size() == 1)
    {
        d.posesChecked = 1;
        d.drivable = checker.isValidExact(pts[0].x, pts[0].y, pts[0].yaw);
        if (!d.drivable) d.reason = "the pose is in collision";
        return d;
    }
    const double step = options.step > 0 ? options.step : 0.02;
    double worstDeviation = 0.0;
    bool finished = true;
    if (!options.reversing)
        finished = checkPiece(pts, false, 0.0, checker, options, step, d, worstDeviation);
    else
    {
        double s0 = 0.0;
        for (const PathPiece &piece : splitAtCusps(pts))
        {
            finished = finished && checkPiece(piece.poses, piece.backward, s0, checker, options, step, d, worstDeviation);
            for (std::size_t i = 1; i < piece.poses.size(); ++i)
                s0 += std::hypot(piece.poses[i].x - piece.poses[i - 1].x, piece.poses[i].y - piece.poses[i - 1].y);
        }
    }
    const double kmax = checker.vehicle().maxCurvature();
    char buf[160];
    if (!finished)
    {
        d.drivable = false;
        d.reason = "the check was stopped by the termination condition before it finished";
        return d;
    }
    if (d.firstCollision >= 0)
    {
        std::snprintf(buf, sizeof buf, "the body hits an obstacle %.2f m along the path", d.firstCollision);
        d.reason = buf;
    }
    else if (std::isfinite(kmax) && !(d.maxCurvature <= kmax * (1.0 + options.curvatureTolerance)))
    {
        std::snprintf(buf, sizeof buf, "curvature %.3g 1/m exceeds K_max %.3g 1/m", d.maxCurvature, kmax);
        d.reason = buf;
    }
    else if (options.maxCurvatureRate > 0 &&
             !(d.maxCurvatureRate <= options.maxCurvatureRate * (1.02 + options.curvatureTolerance)))
    {
        std::snprintf(buf, sizeof buf, "curvature changes at %.3g 1/m^2 %.2f m along the path, faster than %.3g 1/m^2",
                      d.maxCurvatureRate, d.maxCurvatureRateAt, options.maxCurvatureRate);
        d.reason = buf;
    }
    else if (worstDeviation > step)
    {
        std::snprintf(buf, sizeof buf, "a corner is %.2f m from the tightest curve (R_min) round it: too sharp to drive",
                      worstDeviation);
        d.reason = buf;
    }
    else
        d.drivable = true;
    return d;
}

}  // namespace gridcar
