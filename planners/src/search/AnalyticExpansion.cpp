/// @file AnalyticExpansion.cpp
/// @brief The car lattice's analytic expansion: when to try, the curves, the free check.
#include "gridcar/planners/search/AnalyticExpansion.h"

#include "gridcar/core/Angles.h"
#include "gridcar/curves/CarCurves.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/planners/search/detail/CurveSampling.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gridcar
{
namespace
{
/// The curve's turning (rad), its lengths driven forwards and backwards, and its gear changes
/// (its cusps, and one before it when it sets off in the other gear than @p gear).
struct CurveDrive
{
    double turn{0}, forward{0}, backward{0};
    int gearChanges{0};
};

CurveDrive curveDrive(const CarCurve &path, double R, int gear)
{
    CurveDrive d;
    for (int seg = 0; seg < path.count; ++seg)
    {
        const CurveSegment &sg = path.segments[std::size_t(seg)];
        if (sg.steer != Steer::Straight) d.turn += std::abs(sg.length) / R;
        (sg.length < 0 ? d.backward : d.forward) += std::abs(sg.length);
    }
    d.gearChanges = path.cusps();
    for (int seg = 0; seg < path.count; ++seg)
        if (path.segments[std::size_t(seg)].length != 0)
        {
            const int first = path.segments[std::size_t(seg)].length < 0 ? -1 : 1;
            if (gear != 0 && gear != first) ++d.gearChanges;
            break;
        }
    return d;
}
}  // namespace

AnalyticExpansion::AnalyticExpansion(const CarCollision &collision, const CarLattice &lattice)
  : col_(collision), lattice_(lattice)
{
    const CarLatticeConfig &cfg = lattice_.config();
    if (cfg.curvatureRate > 0) clothoid_ = std::make_unique<ClothoidTurn>(cfg.turnRadius, cfg.curvatureRate);
}

AnalyticExpansion::~AnalyticExpansion() = default;

AnalyticExpansion::Range AnalyticExpansion::due(const Pose2 &from, const Pose2 &goal, std::uint64_t expansions,
                                                const std::function<double()> &obstacleDistance) const
{
    const double e = std::hypot(goal.x - from.x, goal.y - from.y);
    const double R = lattice_.config().turnRadius, c = lattice_.cell();
    if (e > 30 * R + 10 * c) return Range::Out;
    if (e <= 2 * R + 2 * c) return Range::Near;
    if (expansions % 8 != 0) return Range::Out;
    // where the obstacle-aware distance is well above the straight line, something is in the
    // way: a Dubins curve (nearly straight this far out) would hit it
    return obstacleDistance() > 1.1 * e + R ? Range::Out : Range::Far;
}

bool AnalyticExpansion::shoot(const Pose2 &from, int gear, const CarLatticeQuery &q, double frameYaw, Range range,
                              const LatticeCostModel &cost, const std::function<bool()> *cancelled, AnalyticShot &out,
                              int &tried) const
{
    if (range == Range::Out) return false;
    const Pose2 &g = q.goal;
    const double e = std::hypot(g.x - from.x, g.y - from.y);
    const double R = lattice_.config().turnRadius;
    const bool near = range == Range::Near;
    // gridcar's Dubins / Reeds-Shepp curves (OMPL 1.5.2's asserts on rounding errors and would
    // abort); near the goal the few shortest words per end yaw, since in a tight spot the
    // shortest one is often blocked where a slightly longer one is free
    // reversing where the query lets it (CarLatticeQuery::reverseWithin): from there, and no
    // farther than that
    const bool rs = lattice_.config().reverse && q.mayReverseAt(from);
    const auto reversesTooFar = [&](const CarCurve &c) {
        if (!rs || q.reverseWithin < 0) return false;
        const CurveDrive d = curveDrive(c, R, 0);
        return (q.timeReversed ? d.forward : d.backward) > q.reverseWithin;
    };
    const int words = near ? (rs ? 4 : 2) : 1;
    std::vector<std::pair<double, double>> cand;  // (length, index)
    std::vector<CarCurve> curves;
    std::vector<double> curveYaw;
    for (double y : CarGoal(q).endYaws(from, lattice_, frameYaw))
    {
        // the curve family of the primitive set's directions: Reeds-Shepp when it reverses
        const Pose2 to{g.x, g.y, y};
        for (const CarCurve &c : rs ? reedsSheppCurves(from, to, R, words) : dubinsCurves(from, to, R, words))
            if (c.length <= e + 2 * M_PI * R && !reversesTooFar(c))
            {
                cand.push_back({c.length, double(curves.size())});
                curves.push_back(c);
                curveYaw.push_back(y);
            }
    }
    std::sort(cand.begin(), cand.end());
    const std::size_t tries = near ? (rs ? 6u : 3u) : 1u;
    if (cand.size() > tries) cand.resize(tries);
    std::vector<double> arc;  // arc length of each sampled pose along the curve
    for (const auto &candidate : cand)
    {
        const double len = candidate.first;  // a plain variable: lambdas may capture it (C++17)
        const double index = candidate.second;
        ++tried;
        const CarCurve &path = curves[std::size_t(index)];
        const double y = curveYaw[std::size_t(index)];
        detail::sampleArcs(path, col_.reach(), lattice_.config().spacing, arc);
        const int n = int(arc.size());
        auto poseAt = [&](int i) {
            Pose2 p = curvePose(from, path, std::min(arc[std::size_t(i - 1)], len));
            p.yaw = wrapYaw(p.yaw);
            return p;
        };
        if (cancelled && (*cancelled)()) return false;  // the search then stops at its next poll
        if (!free(from, n, poseAt, cancelled)) continue;
        CurveDrive d = curveDrive(path, R, gear);
        std::vector<Pose2> poses;
        if (clothoid_ && !rs)
        {
            // the Dubins curve's arcs break the curvature rate: its clothoid counterpart (the
            // free Dubins curve only tells where one is worth computing)
            if (!clothoidShot(from, {g.x, g.y, y}, poses, d.forward, d.turn, cancelled)) continue;
        }
        else
        {
            poses.reserve(std::size_t(n));
            for (int i = 1; i <= n; ++i) poses.push_back(poseAt(i));
        }
        poses.back() = {g.x, g.y, y};
        if (q.crossesCostlierGround(poses)) continue;
        if (q.timeReversed) std::swap(d.forward, d.backward);  // driven in the other gear
        out.cost = cost.stepCost(from, poses, d.forward + q.settings.reversePenalty * d.backward, d.turn) +
                   d.gearChanges * q.cuspPenalty + q.mapCost(poses, d.forward + d.backward) * cost.costPerMetreOfPenalty();
        out.poses = std::move(poses);
        return true;
    }
    return false;
}

bool AnalyticExpansion::free(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt,
                             const std::function<bool()> *cancelled) const
{
    // blocks of 64 poses, the run's termination condition polled between them
    constexpr int kBlock = 64;
    Pose2 blockStart = from;
    for (int b = 0; b < n; b += kBlock)
    {
        if (b > 0 && cancelled && (*cancelled)()) return false;
        const int m = std::min(kBlock, n - b);
        if (!col_.curveFree(blockStart, m, [&](int i) { return poseAt(b + i); }, lattice_.margin())) return false;
        blockStart = poseAt(b + m);
    }
    return true;
}

bool AnalyticExpansion::clothoidShot(const Pose2 &from, const Pose2 &to, std::vector<Pose2> &poses, double &length,
                                     double &turn, const std::function<bool()> *cancelled) const
{
    const double K = 1.0 / clothoid_->radius();
    for (const ClothoidCurve &c : clothoidCurves(from, to, *clothoid_, 2))
    {
        // each part sampled on its own, no body point moving more than the lattice's spacing
        std::vector<double> arc;
        double at = 0;
        for (const double l : {clothoid_->length(c.delta1), c.straight, clothoid_->length(c.delta2)})
        {
            if (l < 1e-6)  // (a deflection of 1e-13 rad is a turn of 1e-7 m: no pose of its own)
            {
                at += l;
                continue;
            }
            detail::appendArcs(l, l * (1.0 + col_.reach() * K), lattice_.config().spacing, at, arc);
        }
        if (arc.empty()) continue;
        const auto poseAt = [&](int i) { return clothoidCurvePose(c, *clothoid_, arc[std::size_t(i - 1)]); };
        if (!free(from, int(arc.size()), poseAt, cancelled)) continue;
        poses.clear();
        for (int i = 1; i <= int(arc.size()); ++i) poses.push_back(poseAt(i));
        length = c.length;
        turn = c.turning();
        return true;
    }
    return false;
}

}  // namespace gridcar
