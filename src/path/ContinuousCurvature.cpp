/// @file ContinuousCurvature.cpp
/// @brief G2 quintics and the curvature-rate smoothing of a sampled path.
#include "gridcar/path/ContinuousCurvature.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Cusps.h"
#include "detail/CurvatureStretch.h"
#include "detail/Steps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
G2Quintic::G2Quintic(const Pose2 &a, double ka, const Pose2 &b, double kb, double eta)
{
    // end conditions: p, p' = eta t, p'' = eta^2 kappa n (n the left normal)
    const double ta[2] = {std::cos(a.yaw), std::sin(a.yaw)}, tb[2] = {std::cos(b.yaw), std::sin(b.yaw)};
    const double p0[2] = {a.x, a.y}, p1[2] = {b.x, b.y};
    for (int k = 0; k < 2; ++k)
    {
        const double na = k == 0 ? -ta[1] : ta[0], nb = k == 0 ? -tb[1] : tb[0];
        const double v0 = eta * ta[k], v1 = eta * tb[k];
        const double a0 = eta * eta * ka * na, a1 = eta * eta * kb * nb;
        const double d = p1[k] - p0[k];
        c_[0][k] = p0[k];
        c_[1][k] = v0;
        c_[2][k] = a0 / 2;
        c_[3][k] = 10 * d - 6 * v0 - 4 * v1 - (3 * a0 - a1) / 2;
        c_[4][k] = -15 * d + 8 * v0 + 7 * v1 + (3 * a0 - 2 * a1) / 2;
        c_[5][k] = 6 * d - 3 * (v0 + v1) - (a0 - a1) / 2;
    }
}

std::array<std::array<double, 2>, 4> G2Quintic::derivatives(double u) const
{
    std::array<std::array<double, 2>, 4> d{};
    for (std::size_t k = 0; k < 2; ++k)
    {
        double p0 = 0, p1 = 0, p2 = 0, p3 = 0;  // Horner for p and its derivatives
        for (int i = 5; i >= 0; --i) p0 = p0 * u + c_[std::size_t(i)][k];
        for (int i = 5; i >= 1; --i) p1 = p1 * u + c_[std::size_t(i)][k] * i;
        for (int i = 5; i >= 2; --i) p2 = p2 * u + c_[std::size_t(i)][k] * i * (i - 1);
        for (int i = 5; i >= 3; --i) p3 = p3 * u + c_[std::size_t(i)][k] * i * (i - 1) * (i - 2);
        d[0][k] = p0;
        d[1][k] = p1;
        d[2][k] = p2;
        d[3][k] = p3;
    }
    return d;
}

double G2Quintic::curvature(double u) const
{
    const auto d = derivatives(u);
    const double sp = std::hypot(d[1][0], d[1][1]);
    return (d[1][0] * d[2][1] - d[1][1] * d[2][0]) / (sp * sp * sp);
}

double G2Quintic::curvatureRate(double u) const
{
    const auto d = derivatives(u);
    const double x1 = d[1][0], y1 = d[1][1], x2 = d[2][0], y2 = d[2][1], x3 = d[3][0], y3 = d[3][1];
    const double sp2 = x1 * x1 + y1 * y1, sp = std::sqrt(sp2);
    const double cross = x1 * y2 - y1 * x2;
    const double dk = (x1 * y3 - y1 * x3) / (sp2 * sp) - 3 * cross * (x1 * x2 + y1 * y2) / (sp2 * sp2 * sp);
    return dk / sp;
}

std::array<std::array<double, 2>, 6> G2Quintic::bezierPoints() const
{
    // power basis -> Bernstein: b_j = sum_{i <= j} C(j, i) / C(5, i) c_i
    static const double C[6][6] = {{1, 0, 0, 0, 0, 0},  {1, 1, 0, 0, 0, 0},   {1, 2, 1, 0, 0, 0},
                                   {1, 3, 3, 1, 0, 0},  {1, 4, 6, 4, 1, 0},   {1, 5, 10, 10, 5, 1}};
    std::array<std::array<double, 2>, 6> b{};
    for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 2; ++k)
        {
            double v = 0;
            for (int i = 0; i <= j; ++i) v += C[j][i] / C[5][i] * c_[std::size_t(i)][std::size_t(k)];
            b[std::size_t(j)][std::size_t(k)] = v;
        }
    return b;
}

CurvatureProfile curvatureRateProfile(const std::vector<Pose2> &piece, double s0)
{
    CurvatureProfile prof;
    std::vector<Pose2> pts;
    for (const Pose2 &p : piece)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    if (pts.size() < 3) return prof;
    std::vector<double> len(pts.size() - 1);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) len[i] = std::hypot(pts[i + 1].x - pts[i].x, pts[i + 1].y - pts[i].y);
    double s = s0 + len[0];
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
    {
        const double turn = wrapAngle(headingOf(pts[i], pts[i + 1]) - headingOf(pts[i - 1], pts[i]));
        const double k = turn / (0.5 * (len[i - 1] + len[i]));
        prof.maxCurvature = std::max(prof.maxCurvature, std::abs(k));
        if (!prof.curvature.empty())
        {
            const double rate = std::abs(k - prof.curvature.back()) / len[i - 1];
            if (rate > prof.maxRate)
            {
                prof.maxRate = rate;
                prof.maxRateAt = s;
            }
        }
        prof.curvature.push_back(k);
        s += len[i];
    }
    return prof;
}

namespace detail
{
Piece makePiece(const std::vector<Pose2> &poses, bool backward, double sigma)
{
    Piece p;
    for (const Pose2 &q : poses)
        if (p.pts.empty() || !samePosition(q, p.pts.back()))
            p.pts.push_back({q.x, q.y, wrapAngle(q.yaw + (backward ? M_PI : 0.0))});
    const std::size_t n = p.pts.size();
    p.s.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
        p.s[i] = p.s[i - 1] + std::hypot(p.pts[i].x - p.pts[i - 1].x, p.pts[i].y - p.pts[i - 1].y);
    p.k.assign(n > 1 ? n - 1 : 0, 0.0);
    for (std::size_t i = 0; i + 1 < n; ++i)
        p.k[i] = wrapAngle(p.pts[i + 1].yaw - p.pts[i].yaw) / (p.s[i + 1] - p.s[i]);
    p.bad.assign(n, 0);
    for (std::size_t i = 1; i + 1 < n; ++i)
    {
        const double rate = std::abs(p.k[i] - p.k[i - 1]) / (0.5 * (p.s[i + 1] - p.s[i - 1]));
        p.bad[i] = rate > 1.02 * sigma;
    }
    return p;
}

/// A candidate replacement of pts[a..b]: its poses strictly between a and b (motion yaws), or
/// empty when it breaks a limit.
std::vector<Pose2> fitStretch(const Piece &p, std::size_t a, std::size_t b, double ka, double kb, double eta,
                              const CurvatureSmoothingOptions &o)
{
    const G2Quintic q(p.pts[a], ka, p.pts[b], kb, eta);
    const double stretch = p.s[b] - p.s[a];
    double turn = 0;
    for (std::size_t i = a; i < b; ++i) turn += wrapAngle(p.pts[i + 1].yaw - p.pts[i].yaw);
    // the limits are checked every 4 cm (a quintic's curvature varies over metres), the
    // written poses then come from the same table
    const int m = std::clamp(stepsFor(stretch, 0.04), 32, 5000);
    std::vector<double> u(std::size_t(m) + 1), len(std::size_t(m) + 1, 0.0), yaw(std::size_t(m) + 1);
    const double kLimit = o.maxCurvature * (1.0 + 1e-4), rLimit = 0.97 * o.maxCurvatureRate;
    double qturn = 0;
    std::array<double, 2> prev{};
    for (int j = 0; j <= m; ++j)
    {
        u[std::size_t(j)] = double(j) / m;
        const auto d = q.derivatives(u[std::size_t(j)]);
        const double x1 = d[1][0], y1 = d[1][1], x2 = d[2][0], y2 = d[2][1];
        const double sp2 = x1 * x1 + y1 * y1, sp = std::sqrt(sp2);
        if (!(sp > 1e-6 * eta)) return {};
        const double cross = x1 * y2 - y1 * x2;
        if (!(std::abs(cross) <= kLimit * sp2 * sp)) return {};  // |k| = |cross| / sp^3
        const double dk = (x1 * d[3][1] - y1 * d[3][0]) / (sp2 * sp) - 3 * cross * (x1 * x2 + y1 * y2) / (sp2 * sp2 * sp);
        if (!(std::abs(dk) <= rLimit * sp)) return {};  // rate = dk / sp
        yaw[std::size_t(j)] = std::atan2(d[1][1], d[1][0]);
        if (j > 0)
        {
            len[std::size_t(j)] = len[std::size_t(j) - 1] + std::hypot(d[0][0] - prev[0], d[0][1] - prev[1]);
            qturn += wrapAngle(yaw[std::size_t(j)] - yaw[std::size_t(j) - 1]);
        }
        prev = d[0];
    }
    if (std::abs(qturn - turn) > 0.02) return {};  // wound the other way
    if (len.back() > stretch * (1.0 + o.maxLengthGrowth) + 1e-3) return {};  // longer than allowed
    const int count = std::max(1, stepsFor(len.back(), o.step));
    std::vector<Pose2> out;
    std::size_t j = 0;
    for (int i = 1; i < count; ++i)
    {
        const double target = len.back() * i / count;
        while (j + 1 < len.size() && len[j + 1] < target) ++j;
        const double t = (target - len[j]) / std::max(1e-12, len[j + 1] - len[j]);
        const double uu = u[j] + t * (u[j + 1] - u[j]);
        const auto d = q.derivatives(uu);
        out.push_back({d[0][0], d[0][1], std::atan2(d[1][1], d[1][0])});
    }
    return out;
}

}  // namespace detail

namespace
{
using namespace detail;

/// Smooths one piece; returns the body poses (yaw turned back for a backward piece).
std::vector<Pose2> smoothPiece(const std::vector<Pose2> &poses, bool backward, const CurvatureSmoothingOptions &o,
                               CurvatureSmoothing &r)
{
    const Piece p = makePiece(poses, backward, o.maxCurvatureRate);
    const std::size_t n = p.pts.size();
    PieceWriter writer(p, backward);
    std::size_t v = 1;
    while (v + 1 < n)
    {
        if (!p.bad[v])
        {
            ++v;
            continue;
        }
        if (o.cancelled && o.cancelled())
        {
            r.cancelled = true;
            break;
        }
        // the stretch: the jumps within reach of each other, each wanting |dk| / sigma of room.
        // A jump near the piece's end has its room on one side only, which a stretch placed
        // before it may have taken (a Reeds-Shepp shot's last 2 cm at full lock, a metre past
        // a turn): where one follows within the widest room a jump may want, it is tried
        // together with this one first, then this one alone
        const auto need = [&](std::size_t i) { return 0.95 * std::abs(p.k[i] - p.k[i - 1]) / o.maxCurvatureRate; };
        const double lo = p.s[v] - need(v);
        double hiOwn = p.s[v] + need(v), hiJoined = hiOwn;
        for (std::size_t w = v + 1; w + 1 < n && p.s[w] <= hiOwn + kArcTie; ++w)
            if (p.bad[w]) hiOwn = std::max(hiOwn, p.s[w] + need(w));
        const double widest = 2 * 0.95 * 2 * o.maxCurvature / o.maxCurvatureRate;  // |dk| <= 2 K_max
        bool nearEnd = p.s[n - 1] - p.s[v] < need(v);
        for (std::size_t w = v + 1; w + 1 < n && p.s[w] <= hiJoined + widest + kArcTie; ++w)
            if (p.bad[w])
            {
                hiJoined = std::max(hiJoined, p.s[w] + need(w));
                nearEnd = nearEnd || p.s[n - 1] - p.s[w] < need(w);
            }
        if (!nearEnd) hiJoined = hiOwn;
        ++r.stretches;
        bool placed = false;
        for (int joined = 1; joined >= 0 && !placed; --joined)
        {
        const double hi = joined ? hiJoined : hiOwn;
        if (!joined && hiOwn == hiJoined) break;
        for (double f : {1.0, 1.5, 2.2, 3.2, 4.5, 6.5})
        {
            const double c = 0.5 * (lo + hi), h = 0.5 * (hi - lo) * f;
            std::size_t a = v - 1, b = v + 1;
            while (a > writer.done() && p.s[a] > c - h + kArcTie) --a;
            while (b + 1 < n && p.s[b] < c + h - kArcTie) ++b;
            while (a > writer.done() && p.bad[a]) --a;
            while (b + 1 < n && p.bad[b]) ++b;
            // the curvature where the stretch meets the rest of the path is kept; at a piece's
            // ends (start, goal, cusp: the car stands) the wheels may be set to any angle, so
            // the curvature on the stretch's other side is tried there too
            const double kaIn = a > 0 ? p.k[a - 1] : p.k[0], kbIn = b + 1 < n ? p.k[b] : p.k[n - 2];
            const double kaFree = a == 0 ? p.k[std::min(v, n - 2)] : kaIn, kbFree = b + 1 == n ? p.k[v - 1] : kbIn;
            const double kas[2] = {kaIn, kaFree}, kbs[2] = {kbIn, kbFree};
            for (int variant = 0; variant < 16 && !placed; ++variant)
            {
                const double e = std::array<double, 4>{1.0, 0.8, 1.25, 0.65}[std::size_t(variant % 4)];
                const double ka = kas[(variant / 4) % 2], kb = kbs[variant / 8];
                if ((variant / 4) % 2 == 1 && ka == kaIn) continue;
                if (variant / 8 == 1 && kb == kbIn) continue;
                const std::vector<Pose2> mid = fitStretch(p, a, b, ka, kb, e * (p.s[b] - p.s[a]), o);
                placed = !mid.empty() && writer.replace(a, b, mid, o.free);
            }
            if (placed || (a <= writer.done() && b + 1 >= n)) break;
        }
        }
        if (placed)
            ++r.replaced;
        else
            writer.copyTo(v);  // keep this jump as it was; the next one is tried on its own
        v = std::max(v + 1, writer.done() + 1);
    }
    return writer.finish();
}
}  // namespace

CurvatureSmoothing smoothCurvature(const std::vector<Pose2> &path, const CurvatureSmoothingOptions &o)
{
    return detail::byPieces(path, o, "smoothCurvature", smoothPiece);
}

}  // namespace gridcar
