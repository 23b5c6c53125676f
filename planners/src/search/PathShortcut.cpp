/// @file PathShortcut.cpp
/// @brief A found path shortened by the analytic expansion's curves (PathShortcut::apply()).
#include "gridcar/planners/search/PathShortcut.h"

#include "gridcar/core/Angles.h"
#include "gridcar/curves/CarCurves.h"
#include "gridcar/curves/ClothoidTurns.h"
#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/planners/search/detail/CurveSampling.h"
#include "gridcar/planners/search/detail/StretchCost.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace gridcar
{
namespace
{
using detail::stepGear;
using detail::stretchCost;

/// Anchors (the poses a shortcut may start or end at) about this far apart along the path.
constexpr double kAnchorStep = 0.3;
constexpr double kMaxAnchors = 80;
/// On a forward route (a lattice that does not reverse): fewer anchors, shorter shortcuts. The
/// pairs tried grow as the anchors' square and most long curves across a route are blocked:
/// with 80 anchors and any span the shortcut took 20-60 ms on Tsudanuma's 80-340 m routes
/// (bench_native), with these 3-10 ms, for the same lengths within 0.1 %.
constexpr double kRouteAnchors = 40;
constexpr double kRouteSpan = 12;  // turning radii
/// Free curves from one anchor that are no better (by cost or cusps) before the next anchor is
/// tried: where the farthest free ones are costlier the path is already good there (an
/// obstacle-distance cost in open space), and each such test costs a pass over the curve.
constexpr int kRefusals = 4;
/// Room (m) a shortcut leaves between the body and the map beyond the search's own margin.
constexpr double kClearance = 0.05;
/// With clothoid turns the shortcut tries turns of these multiples of R_min too.
constexpr double kWideTurns[] = {2.0, 4.0};
/// An arc between arcs of the other side is at least min(this, a quarter circle) long (m).
constexpr double kMaxFlick = 2.0;

/// One shortcut run over a path (PathShortcut::apply()): the candidate curves between
/// two of its poses, their tests, one pass along the path.
class Shortcutter
{
public:
    struct Geometry
    {
        const CarCollision &col;
        const ClothoidTurn *clothoid;  ///< the lattice's clothoid turns (null: arcs)
        double radius, spacing, reach, margin;
        bool reverse;
    };
    Shortcutter(const Geometry &g, const CarLatticeQuery &q, const LatticeCostModel &cost,
                const std::function<bool()> &cancelled, int maxCurves, ShortcutReport &rep)
      : g_(g), q_(q), cost_(cost), cancelled_(cancelled), maxCurves_(maxCurves), rep_(rep),
        minFlick_(std::min(kMaxFlick, M_PI / 2 * g.radius))
    {
        if (!g_.clothoid) return;
        turns_.push_back(g_.clothoid);
        for (const double k : kWideTurns)
        {
            wide_.push_back(std::make_unique<ClothoidTurn>(k * g_.clothoid->radius(), g_.clothoid->sigma()));
            turns_.push_back(wide_.back().get());
        }
    }

    bool stopped() const { return rep_.curves >= maxCurves_ || (cancelled_ && cancelled_()); }

    /// One pass along @p path; true if it replaced a stretch.
    bool pass(std::vector<Pose2> &path)
    {
        const std::size_t n = path.size();
        std::vector<double> s(n, 0.0);
        std::vector<int> gear(n, 0);  // gear of the step from pose k to k + 1 (last: 0)
        for (std::size_t k = 1; k < n; ++k) s[k] = s[k - 1] + std::hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
        for (std::size_t k = 0; k + 1 < n; ++k)
        {
            gear[k] = stepGear(path[k], path[k + 1]);
            if (gear[k] == 0 && k > 0) gear[k] = gear[k - 1];
        }
        // anchors: every kAnchorStep (at most about maxAnchors_ of them on a long path: the
        // pairs tried grow as their square), every cusp, both ends; with clothoid turns only
        // where the path runs straight (a curve starts and ends at curvature 0: joined
        // mid-turn the curvature would jump there, beyond the rate the turns keep)
        const double step = std::max(kAnchorStep, s[n - 1] / maxAnchors_);
        std::vector<std::size_t> anchor{0};
        for (std::size_t k = 1; k + 1 < n; ++k)
        {
            const bool cusp = gear[k] != 0 && gear[k - 1] != 0 && gear[k] != gear[k - 1];
            if (!cusp && g_.clothoid && !(straightStep(path, k - 1) && straightStep(path, k))) continue;
            if (cusp || s[k] - s[anchor.back()] >= step) anchor.push_back(k);
        }
        anchor.push_back(n - 1);

        std::vector<Pose2> out{path[0]};
        int arrive = 0;  // the gear of out's last step
        bool changed = false;
        std::size_t ia = 0;
        while (ia + 1 < anchor.size() && !stopped())
        {
            const std::size_t i = anchor[ia];
            std::size_t next = ia + 1;
            refused_ = 0;
            for (std::size_t ja = anchor.size() - 1; ja >= ia + 2 && next == ia + 1 && refused_ < kRefusals && !stopped(); --ja)
            {
                const std::size_t j = anchor[ja];
                const double oldLength = s[j] - s[i];
                if (oldLength > maxSpan_) continue;
                // no curve is shorter: none is shorter than the chord, nor than R x the heading
                // change (only its arcs turn)
                const double chord = std::hypot(path[j].x - path[i].x, path[j].y - path[i].y);
                const double turn = g_.radius * std::abs(wrapAngle(path[j].yaw - path[i].yaw));
                if (std::max(chord, turn) >= oldLength - 1e-3) continue;
                if (replace(path, i, j, oldLength, arrive, j + 1 < n ? gear[j] : 0, out)) next = ja;
            }
            if (next == ia + 1)
                out.insert(out.end(), path.begin() + std::ptrdiff_t(i) + 1, path.begin() + std::ptrdiff_t(anchor[ia + 1]) + 1);
            else
            {
                ++rep_.replaced;
                changed = true;
            }
            ia = next;
            for (std::size_t k = out.size() - 1; k > 0; --k)
                if (const int gr = stepGear(out[k - 1], out[k]); gr != 0)
                {
                    arrive = gr;
                    break;
                }
        }
        if (ia + 1 < anchor.size())  // stopped: the rest as it was
            out.insert(out.end(), path.begin() + std::ptrdiff_t(anchor[ia]) + 1, path.end());
        if (changed) path = std::move(out);
        return changed;
    }

private:
    /// With clothoid turns: the step from path[k] to path[k + 1] turns by at most twice what a
    /// clothoid turns in its first step from curvature 0 (sigma ds^2 / 2), so a curve that
    /// starts or ends at curvature 0 joins it within the rate.
    bool straightStep(const std::vector<Pose2> &path, std::size_t k) const
    {
        const double ds = std::hypot(path[k + 1].x - path[k].x, path[k + 1].y - path[k].y);
        return std::abs(wrapAngle(path[k + 1].yaw - path[k].yaw)) <= g_.clothoid->sigma() * ds * ds + 1e-9;
    }

    /// With clothoid turns: the curvature rate (curvatureRateProfile(), as the independent
    /// check measures it) stays within sigma where the candidate curve_ joins the path: the
    /// last poses of @p out before it, and path[j] onwards after it.
    bool joinsWithinRate(const std::vector<Pose2> &out, const std::vector<Pose2> &path, std::size_t j)
    {
        constexpr std::size_t kAround = 3;
        const double sigma = g_.clothoid->sigma();
        window_.assign(out.end() - std::ptrdiff_t(std::min(out.size(), kAround)), out.end());
        window_.insert(window_.end(), curve_.begin(), curve_.begin() + std::ptrdiff_t(std::min(curve_.size(), kAround)));
        if (curvatureRateProfile(window_).maxRate > sigma) return false;
        window_.assign(curve_.end() - std::ptrdiff_t(std::min(curve_.size(), kAround)), curve_.end());
        window_.insert(window_.end(), path.begin() + std::ptrdiff_t(j) + 1,
                       path.begin() + std::ptrdiff_t(std::min(path.size(), j + 1 + kAround)));
        return curvatureRateProfile(window_).maxRate <= sigma;
    }

    /// The first candidate curve from path[i] to path[j] that passes every test, appended to
    /// @p out (its first pose left out); false if none does.
    bool replace(const std::vector<Pose2> &path, std::size_t i, std::size_t j, double oldLength, int arrive, int leave,
                 std::vector<Pose2> &out)
    {
        const Pose2 &a = path[i], &b = path[j];
        double oldCost = -1;
        int oldCusps = 0;
        bool found = false;
        forCurves(a, b, oldLength - 1e-3, [&] {
            ++rep_.curves;
            if (!free(a, b)) return !stopped();
            if (oldCost < 0)
            {
                old_.assign(path.begin() + std::ptrdiff_t(i), path.begin() + std::ptrdiff_t(j) + 1);
                oldCost = stretchCost(old_, arrive, leave, q_, cost_, oldCusps);
            }
            if (g_.clothoid && !(joinsWithinRate(out, path, j))) return !stopped();
            joined_.assign(1, a);
            joined_.insert(joined_.end(), curve_.begin(), curve_.end());
            int newCusps = 0;
            const double newCost = stretchCost(joined_, arrive, leave, q_, cost_, newCusps);
            if (newCusps > oldCusps || !(newCost < oldCost - 1e-9))
            {
                ++refused_;  // free but no better
                return !stopped();
            }
            out.insert(out.end(), curve_.begin(), curve_.end());
            found = true;
            return false;
        });
        return found;
    }

    /// The candidate's body free with the grown margin: every 8th pose first (a blocked curve
    /// is mostly refused by one of those; the Reeds-Shepp / Dubins poses are computed only as
    /// far as needed), then every pose (certifying the motion as the search's own test does).
    bool free(const Pose2 &a, const Pose2 &b)
    {
        const bool lazy = curve_.empty();
        const int m = lazy ? int(refs_.size()) : int(curve_.size());
        const auto poseAt = [&](int k) {
            if (!lazy) return curve_[std::size_t(k - 1)];
            if (k == m) return b;
            Pose2 p = driveSegment(refs_[std::size_t(k - 1)].from, refs_[std::size_t(k - 1)].part, g_.radius);
            p.yaw = wrapYaw(p.yaw);
            return p;
        };
        if (m / 8 > 1 && !g_.col.curveFree(a, m / 8, [&](int k) { return poseAt(8 * k); }, g_.margin)) return false;
        if (lazy)
            for (int k = 1; k <= m; ++k) curve_.push_back(poseAt(k));
        return g_.col.curveFree(a, m, [&](int k) { return curve_[std::size_t(k - 1)]; }, g_.margin);
    }

    /// Calls @p take() for the curves of the lattice's family from @p a to @p b shorter than
    /// @p shorterThan, shortest first (curve_ holds the clothoid candidate's poses, refs_ the
    /// Reeds-Shepp / Dubins candidate's samples), until it returns false.
    template <class Take>
    void forCurves(const Pose2 &a, const Pose2 &b, double shorterThan, const Take &take)
    {
        if (g_.clothoid)
        {
            // the lattice's turns and the wider ones, the shortest curves first: a wider turn
            // cuts a corner shorter where it is free, and is driven faster
            cands_.clear();
            for (const ClothoidTurn *t : turns_)
                for (const ClothoidCurve &c : clothoidCurves(a, b, *t, 2))
                    if (c.length < shorterThan) cands_.push_back({c, t});
            std::sort(cands_.begin(), cands_.end(),
                      [](const Candidate &x, const Candidate &y) { return x.curve.length < y.curve.length; });
            for (const Candidate &cand : cands_)
            {
                const ClothoidCurve &c = cand.curve;
                const ClothoidTurn &turn = *cand.turn;
                arc_.clear();
                double at = 0;
                for (const double l : {turn.length(c.delta1), c.straight, turn.length(c.delta2)})
                {
                    if (l < 1e-6)
                    {
                        at += l;
                        continue;
                    }
                    detail::appendArcs(l, l * (1.0 + g_.reach / turn.radius()), g_.spacing, at, arc_);
                }
                curve_.clear();
                for (const double sa : arc_) curve_.push_back(clothoidCurvePose(c, turn, sa));
                if (curve_.empty()) continue;
                curve_.back() = b;
                if (!take()) return;
            }
            return;
        }
        for (const CarCurve &c : g_.reverse ? reedsSheppCurves(a, b, g_.radius, 2) : dubinsCurves(a, b, g_.radius, 2))
        {
            if (!(c.length < shorterThan)) break;
            if (flicks(c)) continue;
            // where each sample lies: its segment's start pose and the signed length into it
            // (the arc lengths of detail::sampleArcs(), computed one segment at a time)
            refs_.clear();
            Pose2 at = a;
            for (int seg = 0; seg < c.count; ++seg)
            {
                const CurveSegment &sg = c.segments[std::size_t(seg)];
                const double l = std::abs(sg.length);
                if (l <= 0) continue;
                double zero = 0;
                arc_.clear();
                detail::appendArcs(l, sg.steer == Steer::Straight ? l : l * (1.0 + g_.reach / g_.radius), g_.spacing, zero, arc_);
                for (const double d : arc_) refs_.push_back({at, {sg.steer, std::copysign(d, sg.length)}});
                at = driveSegment(at, sg, g_.radius);
            }
            if (refs_.empty()) continue;
            curve_.clear();
            if (!take()) return;
        }
    }

    /// A flick of the wheels from one lock to the other: an arc next to one of the other side
    /// (within the curve) shorter than minFlick_.
    bool flicks(const CarCurve &c) const
    {
        Steer last = Steer::Straight;
        for (int seg = 0; seg < c.count; ++seg)
        {
            const CurveSegment &sg = c.segments[std::size_t(seg)];
            const double l = std::abs(sg.length);
            if (l <= 1e-9) continue;
            Steer next = Steer::Straight;  // of the next piece of non-zero length
            for (int t = seg + 1; t < c.count; ++t)
                if (std::abs(c.segments[std::size_t(t)].length) > 1e-9)
                {
                    next = c.segments[std::size_t(t)].steer;
                    break;
                }
            const auto opposite = [&sg](Steer o) { return o != Steer::Straight && o != sg.steer; };
            if (sg.steer != Steer::Straight && l < minFlick_ && (opposite(last) || opposite(next))) return true;
            last = sg.steer;
        }
        return false;
    }

    struct SampleRef
    {
        Pose2 from;
        CurveSegment part;
    };
    struct Candidate
    {
        ClothoidCurve curve;
        const ClothoidTurn *turn;
    };
    Geometry g_;
    const CarLatticeQuery &q_;
    const LatticeCostModel &cost_;
    const std::function<bool()> &cancelled_;
    int maxCurves_;
    ShortcutReport &rep_;
    double minFlick_;
    int refused_{0};
    /// A forward route: at most kRouteAnchors anchors, shortcuts over at most kRouteSpan R of it
    /// (its corners); a reversing manoeuvre: kMaxAnchors, any span (its detail is the point).
    double maxAnchors_{g_.reverse ? kMaxAnchors : kRouteAnchors};
    double maxSpan_{g_.reverse ? std::numeric_limits<double>::infinity() : kRouteSpan * g_.radius};  ///< free curves from the current anchor that were no better
    std::vector<double> arc_;
    std::vector<Pose2> curve_, old_, joined_, window_;
    std::vector<SampleRef> refs_;
    std::vector<Candidate> cands_;
    /// With clothoid turns: the lattice's (R_min) and wider ones (kWideTurns x R_min) at the
    /// same curvature rate.
    std::vector<std::unique_ptr<ClothoidTurn>> wide_;
    std::vector<const ClothoidTurn *> turns_;
};
}  // namespace

PathShortcut::PathShortcut(const CarCollision &collision, const CarLattice &lattice, const ClothoidTurn *clothoid)
  : col_(collision), lattice_(lattice), clothoid_(clothoid)
{
}

PathShortcut::PathShortcut(const CarLatticeSearch &search)
  : PathShortcut(search.collision(), search.lattice(), search.clothoidTurns())
{
}

ShortcutReport PathShortcut::apply(std::vector<Pose2> &path, const CarLatticeQuery &q, const LatticeCostModel &cost,
                                   const std::function<bool()> &cancelled, int maxCurves) const
{
    ShortcutReport rep;
    rep.lengthBefore = rep.lengthAfter = pathLength(path);
    int cusps = 0;
    rep.costBefore = rep.costAfter = path.size() > 1 ? stretchCost(path, 0, 0, q, cost, cusps) : 0.0;
    if (path.size() < 3) return rep;
    const CarLatticeConfig &cfg = lattice_.config();
    // the body grown by kClearance beyond the search's margin: a curve is taken where it
    // leaves a follower room, not where it grazes an obstacle
    // where the query reverses near its ends only (reverse=auto), a route: forward curves,
    // which leave the manoeuvres' reversed stretches as they are or drive them forwards
    const bool reeds = cfg.reverse && q.reverseWithin < 0;
    const Shortcutter::Geometry geo{col_, reeds ? nullptr : clothoid_, cfg.turnRadius, cfg.spacing, col_.reach(),
                                    lattice_.margin() + kClearance, reeds};
    Shortcutter sc(geo, q, cost, cancelled, maxCurves, rep);
    for (int pass = 0; pass < 2 && !sc.stopped(); ++pass)
        if (!sc.pass(path)) break;
    rep.lengthAfter = pathLength(path);
    rep.costAfter = stretchCost(path, 0, 0, q, cost, cusps);
    return rep;
}

}  // namespace gridcar
