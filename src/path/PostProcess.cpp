#include "gridcar/path/PostProcess.h"

#include "gridcar/core/Angles.h"
#include "detail/Steps.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gridcar
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
double dist(const Pose2 &a, const Pose2 &b) { return std::hypot(b.x - a.x, b.y - a.y); }
double heading(const Pose2 &a, const Pose2 &b) { return std::atan2(b.y - a.y, b.x - a.x); }

/// Straight leg a -> b with the yaw of the leg at both ends, swept.
bool legValid(const FootprintChecker &checker, const Pose2 &a, const Pose2 &b)
{
    const double yaw = heading(a, b);
    return checker.isMotionValid({a.x, a.y, yaw}, {b.x, b.y, yaw});
}

Pose2 bezierAt(const BezierCorner &bc, double t)
{
    const double u = 1.0 - t;
    Pose2 q;
    q.x = u * u * bc.a.x + 2 * t * u * bc.p.x + t * t * bc.c.x;
    q.y = u * u * bc.a.y + 2 * t * u * bc.p.y + t * t * bc.c.y;
    const double dx = 2 * u * (bc.p.x - bc.a.x) + 2 * t * (bc.c.x - bc.p.x);
    const double dy = 2 * u * (bc.p.y - bc.a.y) + 2 * t * (bc.c.y - bc.p.y);
    q.yaw = std::atan2(dy, dx);
    return q;
}
}  // namespace

std::vector<Pose2> turningPoints(const std::vector<Pose2> &path)
{
    std::vector<Pose2> pts;
    for (const Pose2 &p : path)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    if (pts.size() <= 2) return pts;
    std::vector<Pose2> out{pts.front()};
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double turn = wrapAngle(heading(pts[i], pts[i + 1]) - heading(out.back(), pts[i]));
        if (std::abs(turn) > 1e-6) out.push_back(pts[i]);
    }
    out.push_back(pts.back());
    return out;
}

double parabolaCurvature(const Pose2 &p0, const Pose2 &p1, const Pose2 &p2)
{
    // local frame: origin p0, x axis towards p2
    const double L = dist(p0, p2);
    if (L < 1e-12) return kInf;
    const double ux = (p2.x - p0.x) / L, uy = (p2.y - p0.y) / L;
    const double x0 = 0.0, y0 = 0.0, x2 = L, y2 = 0.0;
    const double x1 = (p1.x - p0.x) * ux + (p1.y - p0.y) * uy;
    const double y1 = -(p1.x - p0.x) * uy + (p1.y - p0.y) * ux;
    if (std::abs(y1) < 1e-12) return 0.0;
    if (std::abs(x1 - x0) < 1e-12 || std::abs(x1 - x2) < 1e-12) return kInf;
    // y = a x^2 + b x + c through the three points (Lagrange form)
    const double a = y0 / ((x0 - x1) * (x0 - x2)) + y1 / ((x1 - x0) * (x1 - x2)) + y2 / ((x2 - x0) * (x2 - x1));
    const double b = -y0 * (x1 + x2) / ((x0 - x1) * (x0 - x2)) - y1 * (x0 + x2) / ((x1 - x0) * (x1 - x2)) -
                     y2 * (x0 + x1) / ((x2 - x0) * (x2 - x1));
    const double slope = 2 * a * x1 + b;
    return std::abs(2 * a) / std::pow(1 + slope * slope, 1.5);
}

BezierCorner bezierCorner(const Pose2 &p0, const Pose2 &p1, const Pose2 &p2, bool p0IsEnd, bool p2IsEnd)
{
    BezierCorner bc;
    const double l0 = dist(p0, p1), l2 = dist(p1, p2);
    const double a = std::min(p0IsEnd ? l0 : l0 / 2, p2IsEnd ? l2 : l2 / 2);
    const double h0 = heading(p0, p1), h2 = heading(p1, p2);
    bc.p = p1;
    bc.a = {p1.x - a * std::cos(h0), p1.y - a * std::sin(h0), h0};
    bc.c = {p1.x + a * std::cos(h2), p1.y + a * std::sin(h2), h2};
    const double theta = std::abs(wrapAngle(h2 - h0));
    const double ch = std::cos(theta / 2);
    bc.maxCurvature = theta < 1e-12 ? 0.0 : (a <= 0 || ch < 1e-12) ? kInf : std::sin(theta / 2) / (a * ch * ch);
    return bc;
}

double maxMengerCurvature(const std::vector<Pose2> &path)
{
    std::vector<Pose2> pts;
    for (const Pose2 &p : path)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    double best = 0.0;
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double ab = dist(pts[i - 1], pts[i]), bc = dist(pts[i], pts[i + 1]), ca = dist(pts[i - 1], pts[i + 1]);
        const double cross = (pts[i].x - pts[i - 1].x) * (pts[i + 1].y - pts[i].y) -
                             (pts[i].y - pts[i - 1].y) * (pts[i + 1].x - pts[i].x);
        if (ca < 1e-12) return kInf;  // a reversal
        best = std::max(best, 2.0 * std::abs(cross) / (ab * bc * ca));
    }
    return best;
}

namespace
{
/// Thrown by stopIfCancelled() and caught in smoothPath(): out of the nested loops at once.
struct SmoothingCancelled
{
};
void stopIfCancelled(const SmoothingParams &prm)
{
    if (prm.cancelled && prm.cancelled()) throw SmoothingCancelled();
}

/// Adjustment and smoothing of one set of turning points (steps 2 and 3 of smoothPath()).
void adjustAndSmooth(SmoothingResult &r, std::vector<Pose2> pts, const FootprintChecker &checker,
                     const SmoothingParams &prm, double kmax, double step, const Pose2 &last)
{
    const double res = checker.grid().resolution();
    const std::size_t n = pts.size();
    auto cornerK = [&](std::size_t i, const Pose2 &p) {
        const BezierCorner bc = bezierCorner(pts[i - 1], p, pts[i + 1], i == 1, i + 2 == n);
        return std::max(parabolaCurvature(pts[i - 1], p, pts[i + 1]), bc.maxCurvature);
    };
    std::vector<int> moves(n, 0);
    if (prm.adjust && std::isfinite(kmax) && n >= 3)
    {
        // moving a point changes its neighbours' legs: a few passes until nothing moves
        for (int pass = 0; pass < 3; ++pass)
        {
            bool moved = false;
            for (std::size_t i = 1; i + 1 < n; ++i)
            {
                stopIfCancelled(prm);
                double k = cornerK(i, pts[i]);
                while (k >= kmax && moves[i] < prm.maxAdjustSteps)
                {
                    Pose2 best = pts[i];
                    double bestK = k;
                    for (int dx = -1; dx <= 1; ++dx)
                        for (int dy = -1; dy <= 1; ++dy)
                        {
                            if (!dx && !dy) continue;
                            const Pose2 cand{pts[i].x + dx * res, pts[i].y + dy * res, 0.0};
                            const double kc = cornerK(i, cand);
                            // lower by more than rounding: of the moves that mirror each other
                            // (equal K but for the last bits, which differ with the map's
                            // origin) the first in this order is kept, wherever the map lies
                            if (kc >= bestK - 1e-9 * bestK) continue;
                            if (!legValid(checker, pts[i - 1], cand) || !legValid(checker, cand, pts[i + 1])) continue;
                            best = cand;
                            bestK = kc;
                        }
                    if (bestK >= k) break;  // no one-cell move lowers K: keep the least-curvature placement
                    pts[i] = best;
                    k = bestK;
                    ++moves[i];
                    moved = true;
                }
            }
            if (!moved) break;
        }
    }

    r.adjusted = pts;
    r.corners.clear();
    r.path.clear();
    r.adjustFailures = r.bezierFallbacks = 0;
    auto &out = r.path;
    if (n == 0) return;
    out.push_back({pts[0].x, pts[0].y, n > 1 ? heading(pts[0], pts[1]) : pts[0].yaw});
    for (std::size_t i = 1; i + 1 < n; ++i)
    {
        stopIfCancelled(prm);
        CornerReport cr;
        cr.point = pts[i];
        cr.turnDeg = std::abs(wrapAngle(heading(pts[i], pts[i + 1]) - heading(pts[i - 1], pts[i]))) * 180.0 / M_PI;
        cr.parabolaCurvature = parabolaCurvature(pts[i - 1], pts[i], pts[i + 1]);
        const BezierCorner bc = bezierCorner(pts[i - 1], pts[i], pts[i + 1], i == 1, i + 2 == n);
        cr.bezierCurvature = bc.maxCurvature;
        cr.moves = moves[i];
        cr.curvatureOk = std::max(cr.parabolaCurvature, cr.bezierCurvature) < kmax;
        if (!cr.curvatureOk) ++r.adjustFailures;
        std::vector<Pose2> piece;
        if (prm.bezier && std::isfinite(bc.maxCurvature))
        {
            // the control polygon's length bounds the arc length: enough samples
            const double len = dist(bc.a, bc.p) + dist(bc.p, bc.c);
            const int k = std::max(2, detail::stepsFor(len, step));
            for (int j = 0; j <= k; ++j) piece.push_back(bezierAt(bc, double(j) / k));
            bool ok = checker.isMotionValid(out.back(), piece.front());
            for (std::size_t j = 1; ok && j < piece.size(); ++j) ok = checker.isMotionValid(piece[j - 1], piece[j]);
            cr.smoothed = ok;
            if (!ok)
            {
                piece.clear();
                ++r.bezierFallbacks;
            }
        }
        if (piece.empty())  // the unsmoothed corner
        {
            const double hin = heading(pts[i - 1], pts[i]), hout = heading(pts[i], pts[i + 1]);
            piece = {{pts[i].x, pts[i].y, hin}, {pts[i].x, pts[i].y, hout}};
        }
        for (const Pose2 &q : piece)
            if (dist(q, out.back()) > 1e-9 || std::abs(wrapAngle(q.yaw - out.back().yaw)) > 1e-9) out.push_back(q);
        r.corners.push_back(cr);
    }
    if (n > 1) out.push_back({last.x, last.y, heading(pts[n - 2], pts[n - 1])});
}
}  // namespace

namespace
{
SmoothingResult smoothOrThrow(const std::vector<Pose2> &path, const FootprintChecker &checker, const SmoothingParams &prm);
}

SmoothingResult smoothPath(const std::vector<Pose2> &path, const FootprintChecker &checker, const SmoothingParams &prm)
{
    const auto t0 = std::chrono::steady_clock::now();
    try
    {
        return smoothOrThrow(path, checker, prm);
    }
    catch (const SmoothingCancelled &)
    {
        SmoothingResult r;
        r.path = path;
        r.cancelled = true;
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return r;
    }
}

namespace
{
SmoothingResult smoothOrThrow(const std::vector<Pose2> &path, const FootprintChecker &checker, const SmoothingParams &prm)
{
    const auto t0 = std::chrono::steady_clock::now();
    stopIfCancelled(prm);  // not even started when the condition already says stop
    SmoothingResult r;
    const double kmax = prm.maxCurvature > 0 ? prm.maxCurvature : checker.vehicle().maxCurvature();
    const double step = prm.sampleStep > 0 ? prm.sampleStep : checker.grid().resolution() / 4;
    const std::vector<Pose2> lattice = turningPoints(path);
    r.latticeTurningPoints = int(lattice.size());
    // kept: indices into the lattice turning points
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < lattice.size(); ++i) kept.push_back(i);
    if (prm.lineOfSight && lattice.size() > 2)
    {
        kept = {0};
        std::size_t i = 0;
        while (i + 1 < lattice.size())
        {
            std::size_t j = i + 1;  // the next point is always reachable (the input leg)
            while (j + 1 < lattice.size() && legValid(checker, lattice[i], lattice[j + 1]))
            {
                ++j;
                stopIfCancelled(prm);
            }
            kept.push_back(j);
            i = j;
        }
    }
    const Pose2 last = lattice.empty() ? Pose2{} : lattice.back();
    for (int round = 0;; ++round)
    {
        std::vector<Pose2> pts;
        for (std::size_t k : kept) pts.push_back(lattice[k]);
        r.turningPoints = pts;
        adjustAndSmooth(r, pts, checker, prm, kmax, step, last);
        if (round >= 8) break;
        // a failed corner made by the line-of-sight pass gets its lattice points back
        std::vector<std::size_t> next{kept.front()};
        bool restored = false;
        for (std::size_t m = 1; m < kept.size(); ++m)
        {
            // corner at kept position pos (1 .. n-2) is r.corners[pos - 1]
            auto bad = [&](std::size_t pos) {
                return pos >= 1 && pos + 1 < kept.size() && (!r.corners[pos - 1].curvatureOk || !r.corners[pos - 1].smoothed);
            };
            const bool failedNeighbour = bad(m - 1) || bad(m);
            if (failedNeighbour && kept[m] - kept[m - 1] > 1)
            {
                for (std::size_t k = kept[m - 1] + 1; k < kept[m]; ++k) next.push_back(k);
                restored = true;
            }
            next.push_back(kept[m]);
        }
        if (!restored) break;
        kept = next;
    }
    r.maxCurvature = maxMengerCurvature(r.path);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace

}  // namespace gridcar
