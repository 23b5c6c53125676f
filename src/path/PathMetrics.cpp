#include "gridcar/path/PathMetrics.h"

#include "gridcar/path/PostProcess.h"

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
namespace
{
double dist(const Pose2 &a, const Pose2 &b) { return std::hypot(b.x - a.x, b.y - a.y); }
}  // namespace

namespace
{
PathMetrics pieceMetrics(const std::vector<Pose2> &path, const FootprintChecker *checker, const TurnParams &tp,
                         bool backward)
{
    PathMetrics m;
    if (path.empty()) return m;
    // distinct points
    std::vector<Pose2> pts;
    for (const Pose2 &p : path)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    m.length = pathLength(pts);
    m.maxCurvature = maxMengerCurvature(pts);

    // turning points and the largest heading change at one of them
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double h0 = std::atan2(pts[i].y - pts[i - 1].y, pts[i].x - pts[i - 1].x);
        const double h1 = std::atan2(pts[i + 1].y - pts[i].y, pts[i + 1].x - pts[i].x);
        const double d = std::abs(wrapAngle(h1 - h0));
        if (d > 1e-6)
        {
            ++m.turningPoints;
            m.maxTurnDeg = std::max(m.maxTurnDeg, d * 180.0 / M_PI);
        }
    }

    // turns: resample by arc length, compare the chord over the window before each sample
    // with the chord over the window after it
    if (pts.size() >= 2 && m.length > 0)
    {
        std::vector<Pose2> res;
        std::size_t seg = 1;
        double segStart = 0.0;
        const int n = int(std::floor(m.length / tp.sampleStep)) + 1;
        for (int k = 0; k < n; ++k)
        {
            const double s = std::min(m.length, k * tp.sampleStep);
            while (seg + 1 < pts.size() && segStart + dist(pts[seg - 1], pts[seg]) < s)
            {
                segStart += dist(pts[seg - 1], pts[seg]);
                ++seg;
            }
            const double len = dist(pts[seg - 1], pts[seg]);
            const double t = len > 0 ? std::clamp((s - segStart) / len, 0.0, 1.0) : 0.0;
            res.push_back({pts[seg - 1].x + t * (pts[seg].x - pts[seg - 1].x),
                           pts[seg - 1].y + t * (pts[seg].y - pts[seg - 1].y), 0.0});
        }
        const int w = std::max(1, int(std::lround(tp.window / tp.sampleStep)));
        const double thr = tp.thresholdDeg * M_PI / 180.0;
        // the chord over the window ending at sample k
        const auto chordBefore = [&](int k) { return std::atan2(res[k].y - res[k - w].y, res[k].x - res[k - w].x); };
        // a turn's angle: the heading turned from the chord before its first sample to the
        // chord after its last, summed chord by chord (a loop turns more than 180 degrees)
        const auto turnAngle = [&](int first, int last) {
            double sum = 0.0;
            for (int k = first; k < last + w; ++k) sum += wrapAngle(chordBefore(k + 1) - chordBefore(k));
            return std::abs(sum);
        };
        bool inTurn = false;
        int turnStart = 0;
        const int end = int(res.size()) - w;  // samples k with k + w < res.size()
        for (int k = w; k < end; ++k)
        {
            const double a1 = chordBefore(k);
            const double a2 = chordBefore(k + w);
            const bool turning = std::abs(wrapAngle(a2 - a1)) > thr;
            if (turning && !inTurn)
            {
                ++m.turns;
                turnStart = k;
            }
            if (!turning && inTurn) m.maxTurnAngleDeg = std::max(m.maxTurnAngleDeg, turnAngle(turnStart, k - 1) * 180.0 / M_PI);
            inTurn = turning;
        }
        if (inTurn) m.maxTurnAngleDeg = std::max(m.maxTurnAngleDeg, turnAngle(turnStart, end - 1) * 180.0 / M_PI);
    }

    // clearance along the path
    if (checker)
    {
        double best = std::numeric_limits<double>::infinity();
        double bestLine = best;
        const DistanceField &field = checker->field();
        const double step = checker->grid().resolution() / 2;
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            best = std::min(best, checker->clearance(pts[i].x, pts[i].y, pts[i].yaw));
            bestLine = std::min(bestLine, field.distance(pts[i].x, pts[i].y));
            if (i + 1 == pts.size()) break;
            const double len = dist(pts[i], pts[i + 1]);
            const double yaw = std::atan2(pts[i + 1].y - pts[i].y, pts[i + 1].x - pts[i].x) + (backward ? M_PI : 0.0);
            const int k = int(std::ceil(len / step));
            for (int j = 1; j < k; ++j)
            {
                const double t = double(j) / k;
                const double x = pts[i].x + t * (pts[i + 1].x - pts[i].x), y = pts[i].y + t * (pts[i + 1].y - pts[i].y);
                best = std::min(best, checker->clearance(x, y, yaw));
                bestLine = std::min(bestLine, field.distance(x, y));
            }
        }
        m.minClearance = std::isfinite(best) ? best : 0.0;
        m.minPathDistance = std::isfinite(bestLine) ? bestLine : 0.0;
    }
    return m;
}

}  // namespace

PathMetrics computePathMetrics(const std::vector<Pose2> &path, const FootprintChecker *checker, const TurnParams &tp,
                               bool reversing)
{
    if (!reversing) return pieceMetrics(path, checker, tp, false);
    const std::vector<PathPiece> pieces = splitAtCusps(path);
    if (pieces.size() == 1) return pieceMetrics(pieces[0].poses, checker, tp, pieces[0].backward);
    PathMetrics m;
    m.minClearance = m.minPathDistance = std::numeric_limits<double>::infinity();
    for (const PathPiece &piece : pieces)
    {
        const PathMetrics q = pieceMetrics(piece.poses, checker, tp, piece.backward);
        m.length += q.length;
        m.turns += q.turns;
        m.maxTurnDeg = std::max(m.maxTurnDeg, q.maxTurnDeg);
        m.maxTurnAngleDeg = std::max(m.maxTurnAngleDeg, q.maxTurnAngleDeg);
        m.turningPoints += q.turningPoints;
        m.minClearance = std::min(m.minClearance, q.minClearance);
        m.minPathDistance = std::min(m.minPathDistance, q.minPathDistance);
        m.maxCurvature = std::max(m.maxCurvature, q.maxCurvature);
    }
    if (!checker) m.minClearance = m.minPathDistance = 0.0;
    m.cusps = int(pieces.size()) - 1;
    return m;
}

double pathLength(const std::vector<Pose2> &path)
{
    double l = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) l += dist(path[i - 1], path[i]);
    return l;
}

}  // namespace gridcar
