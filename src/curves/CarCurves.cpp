/// @file CarCurves.cpp
/// @brief Shared part of the car curves: driving a segment, sampling a curve, choosing the
/// shortest candidate word that lands on the goal.
#include "gridcar/curves/CarCurves.h"

#include "CurveWords.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
int CarCurve::cusps() const
{
    // zero-length pieces (a word's straight of length 0, say) drive in no gear
    int n = 0, gear = 0;
    for (int i = 0; i < count; ++i)
    {
        const double l = segments[std::size_t(i)].length;
        const int g = l > 0 ? 1 : l < 0 ? -1 : 0;
        if (g == 0) continue;
        if (gear != 0 && g != gear) ++n;
        gear = g;
    }
    return n;
}

Pose2 driveSegment(const Pose2 &p, const CurveSegment &seg, double radius)
{
    const double l = seg.length;
    switch (seg.steer)
    {
        case Steer::Left:
        {
            const double yaw = p.yaw + l / radius;
            return {p.x + radius * (std::sin(yaw) - std::sin(p.yaw)), p.y + radius * (std::cos(p.yaw) - std::cos(yaw)), yaw};
        }
        case Steer::Right:
        {
            const double yaw = p.yaw - l / radius;
            return {p.x + radius * (std::sin(p.yaw) - std::sin(yaw)), p.y + radius * (std::cos(yaw) - std::cos(p.yaw)), yaw};
        }
        default: return {p.x + l * std::cos(p.yaw), p.y + l * std::sin(p.yaw), p.yaw};
    }
}

Pose2 curvePose(const Pose2 &start, const CarCurve &curve, double s)
{
    Pose2 p = start;
    if (!(s > 0)) return p;
    for (int i = 0; i < curve.count; ++i)
    {
        const CurveSegment &seg = curve.segments[std::size_t(i)];
        const double len = std::abs(seg.length);
        if (s < len)
            return driveSegment(p, {seg.steer, std::copysign(s, seg.length)}, curve.radius);
        p = driveSegment(p, seg, curve.radius);
        s -= len;
    }
    return p;
}

namespace curves
{
double mod2pi(double a)
{
    double v = std::fmod(a, 2 * M_PI);
    if (v < 0) v += 2 * M_PI;
    // a rounding error just below a full turn is no turn at all (else a whole loop is added)
    if (v > 2 * M_PI - kSnap) v = 0.0;
    return v;
}

double modPi(double a)
{
    double v = std::remainder(a, 2 * M_PI);  // [-pi, pi]
    if (std::abs(v) < kSnap) v = 0.0;
    return v;
}

void Candidates::add(std::initializer_list<CurveSegment> segs)
{
    Word w;
    for (const CurveSegment &s : segs)
    {
        if (!std::isfinite(s.length)) return;
        w.length += std::abs(s.length);
        if (w.count < 5) w.segments[std::size_t(w.count++)] = s;
    }
    words_.push_back(w);
}

CarCurve Candidates::shortestLanding(const Pose2 &goal, double radius)
{
    std::vector<CarCurve> one = landings(goal, radius, 1);
    if (!one.empty()) return one.front();
    CarCurve out;
    out.radius = radius;
    out.length = std::numeric_limits<double>::infinity();
    return out;
}

std::vector<CarCurve> Candidates::landings(const Pose2 &goal, double radius, int maxCount)
{
    std::stable_sort(words_.begin(), words_.end(), [](const Word &a, const Word &b) { return a.length < b.length; });
    std::vector<CarCurve> out;
    for (const Word &w : words_)
    {
        if (int(out.size()) >= maxCount) break;
        // integrate the word from the origin at unit radius: it must land on the goal
        Pose2 p{};
        for (int i = 0; i < w.count; ++i) p = driveSegment(p, w.segments[std::size_t(i)], 1.0);
        const double miss = std::max(std::hypot(p.x - goal.x, p.y - goal.y), std::abs(std::remainder(p.yaw - goal.yaw, 2 * M_PI)));
        if (!(miss < kLandTolerance)) continue;
        // the whole word, zero-length pieces included (the word stays one of the family's)
        CarCurve c;
        c.radius = radius;
        for (int i = 0; i < w.count; ++i)
            c.segments[std::size_t(c.count++)] = {w.segments[std::size_t(i)].steer, w.segments[std::size_t(i)].length * radius};
        c.length = w.length * radius;
        bool same = false;  // the same curve found by another formula (a symmetry of the family)
        for (const CarCurve &o : out)
        {
            if (std::abs(o.length - c.length) > 1e-9 * std::max(1.0, c.length)) continue;
            const Pose2 m1 = curvePose({}, o, o.length / 3), m2 = curvePose({}, c, c.length / 3);
            const Pose2 n1 = curvePose({}, o, 2 * o.length / 3), n2 = curvePose({}, c, 2 * c.length / 3);
            if (std::hypot(m1.x - m2.x, m1.y - m2.y) < 1e-9 * radius && std::hypot(n1.x - n2.x, n1.y - n2.y) < 1e-9 * radius)
                same = true;
        }
        if (!same) out.push_back(c);
    }
    return out;
}

Pose2 normalisedGoal(const Pose2 &a, const Pose2 &b, double radius)
{
    const double dx = b.x - a.x, dy = b.y - a.y, c = std::cos(a.yaw), s = std::sin(a.yaw);
    return {(c * dx + s * dy) / radius, (-s * dx + c * dy) / radius, modPi(b.yaw - a.yaw)};
}

bool finitePoses(const Pose2 &a, const Pose2 &b, double radius)
{
    return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.yaw) && std::isfinite(b.x) && std::isfinite(b.y) &&
           std::isfinite(b.yaw) && std::isfinite(radius) && radius > 0;
}

}  // namespace curves
}  // namespace gridcar
