/// @file Dubins.cpp
/// @brief The six Dubins words (Shkel and Lumelsky's closed forms), every candidate checked to
/// land on the goal before it is taken.
#include "gridcar/curves/CarCurves.h"

#include "CurveWords.h"

#include <algorithm>
#include <cmath>

namespace gridcar
{
namespace
{
using curves::mod2pi;
constexpr Steer L = Steer::Left, S = Steer::Straight, R = Steer::Right;

/// sqrt of a square that rounding may have pushed just below 0; negative when truly negative.
double rootOf(double sq) { return sq >= 0 ? std::sqrt(sq) : (sq > -1e-9 ? 0.0 : -1.0); }

/// Both CSC words with turns of the same sense and of opposite senses, and the two CCC words,
/// for the normalised problem (start at the origin heading +x, the line to the goal of length
/// d at angle alpha below the start heading and beta below the goal heading).
void addWords(curves::Candidates &c, double d, double alpha, double beta)
{
    const double sa = std::sin(alpha), sb = std::sin(beta), ca = std::cos(alpha), cb = std::cos(beta);
    const double cab = std::cos(alpha - beta);
    // LSL
    if (const double p = rootOf(2 + d * d - 2 * cab + 2 * d * (sa - sb)); p >= 0)
    {
        const double th = std::atan2(cb - ca, d + sa - sb);
        c.add({{L, mod2pi(th - alpha)}, {S, p}, {L, mod2pi(beta - th)}});
    }
    // RSR
    if (const double p = rootOf(2 + d * d - 2 * cab + 2 * d * (sb - sa)); p >= 0)
    {
        const double th = std::atan2(ca - cb, d - sa + sb);
        c.add({{R, mod2pi(alpha - th)}, {S, p}, {R, mod2pi(th - beta)}});
    }
    // LSR
    if (const double p = rootOf(-2 + d * d + 2 * cab + 2 * d * (sa + sb)); p >= 0)
    {
        const double th = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p);
        c.add({{L, mod2pi(th - alpha)}, {S, p}, {R, mod2pi(th - beta)}});
    }
    // RSL
    if (const double p = rootOf(-2 + d * d + 2 * cab - 2 * d * (sa + sb)); p >= 0)
    {
        const double th = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p);
        c.add({{R, mod2pi(alpha - th)}, {S, p}, {L, mod2pi(beta - th)}});
    }
    // RLR and LRL: the middle arc longer than half a turn (acos clamped against rounding)
    const double rlr = (6 - d * d + 2 * cab + 2 * d * (sa - sb)) / 8;
    if (std::abs(rlr) <= 1 + 1e-12)
    {
        const double p = mod2pi(2 * M_PI - std::acos(std::clamp(rlr, -1.0, 1.0)));
        const double t = mod2pi(alpha - std::atan2(ca - cb, d - sa + sb) + p / 2);
        c.add({{R, t}, {L, p}, {R, mod2pi(alpha - beta - t + p)}});
    }
    const double lrl = (6 - d * d + 2 * cab + 2 * d * (sb - sa)) / 8;
    if (std::abs(lrl) <= 1 + 1e-12)
    {
        const double p = mod2pi(2 * M_PI - std::acos(std::clamp(lrl, -1.0, 1.0)));
        const double t = mod2pi(-alpha + std::atan2(cb - ca, d + sa - sb) + p / 2);
        c.add({{L, t}, {R, p}, {L, mod2pi(beta - alpha - t + p)}});
    }
}
}  // namespace

std::vector<CarCurve> dubinsCurves(const Pose2 &a, const Pose2 &b, double radius, int maxCount)
{
    if (!curves::finitePoses(a, b, radius)) return {};
    const Pose2 g = curves::normalisedGoal(a, b, radius);
    const double d = std::hypot(g.x, g.y), th = d > 0 ? std::atan2(g.y, g.x) : 0.0;
    curves::Candidates c;
    c.add({});  // equal poses: no motion at all
    addWords(c, d, mod2pi(-th), mod2pi(g.yaw - th));
    return c.landings(g, radius, maxCount);
}

CarCurve dubinsCurve(const Pose2 &a, const Pose2 &b, double radius)
{
    std::vector<CarCurve> one = dubinsCurves(a, b, radius, 1);
    return one.empty() ? curves::Candidates().shortestLanding({}, 1.0) : one.front();
}

}  // namespace gridcar
