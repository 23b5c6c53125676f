/// @file WidenTurns.cpp
/// @brief Full-lock turns of a path within the curvature rate opened up where there is room
/// (widenTurns()).
#include "gridcar/path/ContinuousCurvature.h"

#include "gridcar/core/Angles.h"
#include "detail/CurvatureStretch.h"

#include <algorithm>
#include <cmath>

namespace gridcar
{
namespace
{
using namespace detail;

/// Widens the turns of one piece (widenTurns()); returns the body poses.
std::vector<Pose2> widenPiece(const std::vector<Pose2> &poses, bool backward, const CurvatureSmoothingOptions &o,
                              CurvatureSmoothing &r)
{
    const Piece p = makePiece(poses, backward, o.maxCurvatureRate);
    const std::size_t n = p.pts.size();
    PieceWriter w(p, backward);
    // the turns: runs of intervals that turn, joined across straights shorter than kGap
    constexpr double kGap = 0.5;
    std::vector<std::pair<std::size_t, std::size_t>> turns;  // vertices [first, last] of each
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
        if (std::abs(p.k[i]) <= 1e-9) continue;
        if (!turns.empty() && p.s[i] - p.s[turns.back().second] < kGap - kArcTie)
            turns.back().second = i + 1;
        else
            turns.push_back({i, i + 1});
    }
    CurvatureSmoothingOptions noLonger = o;
    noLonger.maxLengthGrowth = 0.0;
    for (std::size_t t = 0; t < turns.size(); ++t)
    {
        if (o.cancelled && o.cancelled())
        {
            r.cancelled = true;
            break;
        }
        const auto [first, last] = turns[t];
        if (first < w.done()) continue;
        ++r.stretches;
        // room on the straights either side: to the previous replacement or half way to the
        // previous turn, half way to the next turn, the piece's ends
        const double before = std::max(p.s[w.done()], t > 0 ? 0.5 * (p.s[turns[t - 1].second] + p.s[first]) : 0.0);
        const double after = t + 1 < turns.size() ? 0.5 * (p.s[last] + p.s[turns[t + 1].first]) : p.s[n - 1];
        const double len = p.s[last] - p.s[first];
        bool placed = false;
        for (const double f : {2.0, 1.4, 1.0, 0.6, 0.3})
        {
            std::size_t a = first, b = last;
            while (a > w.done() && p.s[a - 1] >= std::max(before, p.s[first] - f * len) - kArcTie) --a;
            while (b + 1 < n && p.s[b + 1] <= std::min(after, p.s[last] + f * len) + kArcTie) ++b;
            if (a == first && b == last && f < 2.0) break;  // no room: the narrower tries are the same
            for (const double e : {1.0, 0.8, 1.25, 0.65})
            {
                // the ends on straights: curvature 0 there (a piece's start or end stands: 0 too)
                std::vector<Pose2> mid = fitStretch(p, a, b, 0.0, 0.0, e * (p.s[b] - p.s[a]), noLonger);
                if (mid.empty()) continue;
                // followable at its speed: the rate limit sigma holds at the speed of a turn
                // at K_max, v_m = sqrt(a_lat / K_max); the steering's rate over time is fixed,
                // so at the speed of this turn's peak curvature k_p, sqrt(a_lat / k_p), the
                // curvature may change only sigma sqrt(k_p / K_max) per metre
                std::vector<Pose2> motion{p.pts[a]};
                motion.insert(motion.end(), mid.begin(), mid.end());
                motion.push_back(p.pts[b]);
                const CurvatureProfile prof = curvatureRateProfile(motion);
                if (prof.maxRate > 0.97 * o.maxCurvatureRate * std::sqrt(std::min(1.0, prof.maxCurvature / o.maxCurvature)))
                    continue;
                if ((placed = w.replace(a, b, mid, o.free))) break;
            }
            if (placed) break;
        }
        if (placed) ++r.replaced;
    }
    return w.finish();
}
}  // namespace

CurvatureSmoothing widenTurns(const std::vector<Pose2> &path, const CurvatureSmoothingOptions &o)
{
    return detail::byPieces(path, o, "widenTurns", widenPiece);
}

}  // namespace gridcar
