#include "gridcar/vehicle/Dynamics.h"

#include "gridcar/core/Cusps.h"

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
double lateralAccelLimit(const VehicleParams &v) { return std::min(v.friction * 9.81, v.maxLateralAccel); }

double cornerDistanceLost(const VehicleParams &v, double vc)
{
    const double V = v.maxSpeed;
    return 0.5 * (V - vc) * (V - vc) * (1.0 / v.acceleration + 1.0 / v.deceleration);
}

double manoeuvringSpeed(const VehicleParams &v)
{
    const double r = v.minTurningRadius();
    if (!(r > 0) || !std::isfinite(r)) return v.maxSpeed;
    return std::min(v.maxSpeed, std::sqrt(lateralAccelLimit(v) * r));
}

double gearChangeDistance(const VehicleParams &v)
{
    const double vm = manoeuvringSpeed(v);
    return 0.5 * vm * vm * (1.0 / v.acceleration + 1.0 / v.deceleration);
}

double cornerTimeLost(const VehicleParams &v, double theta)
{
    theta = std::abs(theta);
    if (theta < 1e-9) return 0.0;
    // the corner's radius: R_min opened up for a gentler turn (as corner-astar's physics weights)
    const double r = std::max(v.minTurningRadius(), 1e-3) / std::tan(std::min(theta, M_PI - 1e-6) / 2);
    return cornerDistanceLost(v, speedLimit(v, theta, r * theta / 2)) / v.maxSpeed;
}

CornerSpeeds cornerSpeeds(const VehicleParams &v)
{
    const double V = v.maxSpeed;
    const double alat = lateralAccelLimit(v);
    auto speed = [&](double thetaDeg, double given) {
        if (given > 0.0) return std::min(V, given);
        const double r = std::max(v.minTurningRadius(), 1e-3) / std::tan(thetaDeg * M_PI / 360.0);
        return std::min(V, std::sqrt(alat * r));
    };
    CornerSpeeds c;
    c.v45 = speed(45.0, v.cornerSpeed45);
    c.v90 = speed(90.0, v.cornerSpeed90);
    c.v135 = speed(135.0, v.cornerSpeed135);
    return c;
}

double speedLimit(const VehicleParams &v, double theta, double window)
{
    const double V = v.maxSpeed;
    theta = std::abs(theta);
    if (theta < 1e-9) return V;
    // curvature: the radius the heading change implies over the window, never below R_min
    const double alat = lateralAccelLimit(v);
    const double r = std::max(window > 0 ? 2.0 * window / theta : 0.0, v.minTurningRadius());
    double lim = alat > 0 ? std::sqrt(alat * r) : V;
    if (v.cornerSpeed45 > 0 || v.cornerSpeed90 > 0 || v.cornerSpeed135 > 0)
    {
        // the vehicle's corner speeds cap the speed through a corner of this angle
        const double deg = std::min(theta * 180.0 / M_PI, 180.0);
        const double pts[4] = {V, v.cornerSpeed45 > 0 ? v.cornerSpeed45 : V, v.cornerSpeed90 > 0 ? v.cornerSpeed90 : V,
                               v.cornerSpeed135 > 0 ? v.cornerSpeed135 : (v.cornerSpeed90 > 0 ? v.cornerSpeed90 : V)};
        const double k = std::min(deg / 45.0, 3.0);
        const int i = std::min(int(k), 2);
        lim = std::min(lim, pts[i] + (pts[i + 1] - pts[i]) * (k - i));
    }
    return std::clamp(lim, 1e-3, V);
}

double VelocityProfile::speedAt(double at) const
{
    if (s.empty() || at < s.front() || at > s.back()) return 0.0;
    const auto it = std::upper_bound(s.begin(), s.end(), at);
    if (it == s.end()) return v.back();
    const std::size_t i = std::size_t(it - s.begin());
    if (i == 0) return v.front();
    const double t = (at - s[i - 1]) / std::max(s[i] - s[i - 1], 1e-12);
    return v[i - 1] + t * (v[i] - v[i - 1]);
}

double reverseSpeedLimit(const VehicleParams &v)
{
    if (v.maxReverseSpeed > 0) return std::min(v.maxReverseSpeed, v.maxSpeed);
    return std::min(v.maxSpeed / 3.0, 2.0);
}

double drivingTime(const std::vector<Pose2> &path, const VehicleParams &v, const DrivingTimeParams &p)
{
    if (!p.reversing) return velocityProfile(path, v, p).time;
    DrivingTimeParams one = p;
    one.reversing = false;
    one.stopAtEnds = true;  // the car stops at every cusp
    double t = 0.0;
    VehicleParams back = v;  // a piece driven backwards: at most the reverse speed limit
    back.maxSpeed = reverseSpeedLimit(v);
    for (const PathPiece &piece : splitAtCusps(path))
    {
        t += velocityProfile(piece.poses, piece.backward ? back : v, one).time;
        one.startSpeed = 0.0;  // the pieces after a cusp start from rest
    }
    return t;
}

VelocityProfile velocityProfile(const std::vector<Pose2> &path, const VehicleParams &v, const DrivingTimeParams &p)
{
    VelocityProfile prof;
    if (!(v.maxSpeed > 0) || !(v.acceleration > 0) || !(v.deceleration > 0))
        throw std::invalid_argument("drivingTime needs max_speed, acceleration and deceleration > 0");
    std::vector<Pose2> pts;
    for (const Pose2 &q : path)
        if (pts.empty() || !samePosition(q, pts.back())) pts.push_back(q);
    if (pts.size() < 2) return prof;
    // resample by arc length
    std::vector<double> xs, ys;
    double total = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) total += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    // at least one interior sample: a short piece from rest to rest still accelerates
    const int n = std::max(2, int(std::ceil(total / p.sampleStep)));
    const double ds = total / n;
    std::size_t seg = 1;
    double segStart = 0;
    for (int k = 0; k <= n; ++k)
    {
        const double s = std::min(total, k * ds);
        while (seg + 1 < pts.size() &&
               segStart + std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y) < s)
        {
            segStart += std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y);
            ++seg;
        }
        const double len = std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y);
        const double t = len > 0 ? std::clamp((s - segStart) / len, 0.0, 1.0) : 0.0;
        xs.push_back(pts[seg - 1].x + t * (pts[seg].x - pts[seg - 1].x));
        ys.push_back(pts[seg - 1].y + t * (pts[seg].y - pts[seg - 1].y));
    }
    const int N = int(xs.size());
    const int w = std::max(1, int(std::lround(p.window / ds)));
    std::vector<double> vel(N);
    for (int k = 0; k < N; ++k)
    {
        const int a = std::max(0, k - w), b = std::min(N - 1, k + w);
        double theta = 0;
        if (a < k && k < b)
        {
            const double h1 = std::atan2(ys[k] - ys[a], xs[k] - xs[a]);
            const double h2 = std::atan2(ys[b] - ys[k], xs[b] - xs[k]);
            theta = std::abs(wrapAngle(h2 - h1));
        }
        vel[k] = speedLimit(v, theta, p.window);
    }
    if (p.stopAtEnds)
    {
        vel.front() = std::min(vel.front(), std::max(p.startSpeed, 0.0));
        vel.back() = 0.0;
    }
    for (int k = 1; k < N; ++k) vel[k] = std::min(vel[k], std::sqrt(vel[k - 1] * vel[k - 1] + 2 * v.acceleration * ds));
    for (int k = N - 2; k >= 0; --k)
        vel[k] = std::min(vel[k], std::sqrt(vel[k + 1] * vel[k + 1] + 2 * v.deceleration * ds));
    double time = 0;
    for (int k = 1; k < N; ++k) time += 2 * ds / std::max(vel[k - 1] + vel[k], 1e-9);
    prof.time = time;
    prof.x = xs;
    prof.y = ys;
    prof.v = vel;
    for (int k = 0; k < N; ++k) prof.s.push_back(k * ds);
    return prof;
}

}  // namespace gridcar
