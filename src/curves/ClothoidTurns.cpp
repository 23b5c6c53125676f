/// @file ClothoidTurns.cpp
/// @brief Clothoid turns and turn-straight-turn curves between two poses (ClothoidTurns.h).
#include "gridcar/curves/ClothoidTurns.h"

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gridcar
{
namespace
{
constexpr double kTwoPi = 2.0 * M_PI;

/// @p rel driven from @p a (rel in a's frame).
Pose2 compose(const Pose2 &a, const Pose2 &rel)
{
    const double c = std::cos(a.yaw), s = std::sin(a.yaw);
    return {a.x + c * rel.x - s * rel.y, a.y + s * rel.x + c * rel.y, a.yaw + rel.yaw};
}
}  // namespace

ClothoidTurn::ClothoidTurn(double radius, double sigma) : radius_(radius), sigma_(sigma)
{
    if (!(radius > 0) || !(sigma > 0) || !std::isfinite(radius) || !std::isfinite(sigma))
        throw std::invalid_argument("ClothoidTurn needs a finite radius > 0 and curvature rate > 0");
    const double top = 1.0 / (radius * sigma);  // arc length of the clothoid up to curvature 1 / R
    h_ = std::max(1e-3, top / 200000.0);
    const std::size_t n = std::size_t(std::ceil(top / h_)) + 2;
    x_.assign(n, 0.0);
    y_.assign(n, 0.0);
    // Simpson's rule on four sub-steps per entry (error far below the interpolation's)
    const auto th = [this](double u) { return 0.5 * sigma_ * u * u; };
    for (std::size_t i = 1; i < n; ++i)
    {
        const double u0 = double(i - 1) * h_, q = h_ / 4.0;
        double sx = 0, sy = 0;
        for (int k = 0; k <= 4; ++k)
        {
            const double w = (k == 0 || k == 4) ? 1.0 : (k % 2 ? 4.0 : 2.0), t = th(u0 + k * q);
            sx += w * std::cos(t);
            sy += w * std::sin(t);
        }
        x_[i] = x_[i - 1] + sx * q / 3.0;
        y_[i] = y_[i - 1] + sy * q / 3.0;
    }
}

void ClothoidTurn::clothoid(double u, double &x, double &y) const
{
    u = std::max(u, 0.0);
    const std::size_t i = std::min(std::size_t(u / h_), x_.size() - 2);
    const double t = (u - double(i) * h_) / h_;
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    const double a0 = 0.5 * sigma_ * std::pow(double(i) * h_, 2), a1 = 0.5 * sigma_ * std::pow(double(i + 1) * h_, 2);
    x = h00 * x_[i] + h10 * h_ * std::cos(a0) + h01 * x_[i + 1] + h11 * h_ * std::cos(a1);
    y = h00 * y_[i] + h10 * h_ * std::sin(a0) + h01 * y_[i + 1] + h11 * h_ * std::sin(a1);
}

double ClothoidTurn::length(double delta) const
{
    const double d = std::abs(delta), K = 1.0 / radius_;
    if (d * sigma_ <= K * K) return 2.0 * std::sqrt(d / sigma_);  // two clothoids, peak below 1 / R
    return 2.0 * K / sigma_ + (d - K * K / sigma_) / K;            // clothoid, arc at 1 / R, clothoid
}

double ClothoidTurn::curvature(double delta, double s) const
{
    const double d = std::abs(delta), K = 1.0 / radius_, L = length(delta);
    const double peak = d * sigma_ <= K * K ? std::sqrt(d * sigma_) : K;
    s = std::clamp(s, 0.0, L);
    const double k = std::min({sigma_ * s, peak, sigma_ * (L - s)});
    return delta >= 0 ? k : -k;
}

Pose2 ClothoidTurn::pose(double delta, double s) const
{
    const double d = std::abs(delta), K = 1.0 / radius_, L = length(delta);
    const double peak = d * sigma_ <= K * K ? std::sqrt(d * sigma_) : K;
    const double rise = peak / sigma_, hold = L - 2.0 * rise, t1 = 0.5 * sigma_ * rise * rise;
    s = std::clamp(s, 0.0, L);
    Pose2 p;
    if (s <= rise)
    {
        clothoid(s, p.x, p.y);
        p.yaw = 0.5 * sigma_ * s * s;
    }
    else
    {
        double bx, by;
        clothoid(rise, bx, by);
        const double v = std::min(s - rise, hold), phi = t1 + peak * v;
        // the arc at the peak about its centre, left of the clothoid's end
        Pose2 c{bx + (std::sin(phi) - std::sin(t1)) / peak, by - (std::cos(phi) - std::cos(t1)) / peak, phi};
        if (hold <= 0) c = {bx, by, t1};
        p = c;
        if (s > rise + hold)
        {
            // the falling clothoid: the rising one read backwards, turned by its end heading
            const double w = s - rise - hold;
            double xr, yr;
            clothoid(rise - w, xr, yr);
            const double lx = bx - xr, ly = -(by - yr);
            const Pose2 rel{std::cos(t1) * lx - std::sin(t1) * ly, std::sin(t1) * lx + std::cos(t1) * ly,
                            t1 - 0.5 * sigma_ * (rise - w) * (rise - w)};
            p = compose(c, rel);
        }
    }
    if (delta < 0)
    {
        p.y = -p.y;
        p.yaw = -p.yaw;
    }
    return p;
}

double ClothoidCurve::turning() const { return std::abs(delta1) + std::abs(delta2); }

Pose2 clothoidCurvePose(const ClothoidCurve &curve, const ClothoidTurn &turn, double s)
{
    const double l1 = turn.length(curve.delta1), l2 = turn.length(curve.delta2);
    s = std::clamp(s, 0.0, l1 + curve.straight + l2);
    Pose2 p;
    if (s <= l1)
        p = compose(curve.start, turn.pose(curve.delta1, s));
    else
    {
        Pose2 e = compose(curve.start, turn.pose(curve.delta1, l1));
        const double along = std::min(s - l1, curve.straight);
        e.x += along * std::cos(e.yaw);
        e.y += along * std::sin(e.yaw);
        p = s > l1 + curve.straight ? compose(e, turn.pose(curve.delta2, s - l1 - curve.straight)) : e;
    }
    p.yaw = wrapYaw(p.yaw);
    return p;
}

std::vector<ClothoidCurve> clothoidCurves(const Pose2 &a, const Pose2 &b, const ClothoidTurn &turn, int maxCount)
{
    std::vector<ClothoidCurve> out;
    if (maxCount <= 0 || !std::isfinite(a.x + a.y + a.yaw + b.x + b.y + b.yaw)) return out;
    // for each word (the two turns' directions) the first deflection d1 in [0, 2 pi) fixes the
    // second (the headings must add up) and the straight line's heading; the goal must then
    // lie on that line: f(d1), the goal's offset across the line, is 0. Roots are bracketed on
    // a grid of d1 and bisected; a bracket round a jump of f (where the second deflection
    // wraps) fails the check and is dropped.
    for (const auto &word : {std::pair{1, 1}, std::pair{-1, -1}, std::pair{1, -1}, std::pair{-1, 1}})
    {
        const double s1 = word.first, s2 = word.second;
        const auto eval = [&](double d1, double &ell, ClothoidCurve &c) {
            c.start = a;
            c.delta1 = s1 * d1;
            const double h = a.yaw + c.delta1;
            double d2 = std::fmod(s2 * (b.yaw - h), kTwoPi);
            if (d2 < 0) d2 += kTwoPi;
            c.delta2 = s2 * d2;
            const Pose2 e1 = compose(a, turn.pose(c.delta1, turn.length(c.delta1)));
            const Pose2 e2 = turn.pose(c.delta2, turn.length(c.delta2));
            const double ch = std::cos(h), sh = std::sin(h);
            const double rx = b.x - e1.x - (ch * e2.x - sh * e2.y), ry = b.y - e1.y - (sh * e2.x + ch * e2.y);
            ell = ch * rx + sh * ry;
            return ch * ry - sh * rx;
        };
        constexpr int N = 48;
        double ell, prevD = 0.0;
        ClothoidCurve c;
        double prevF = eval(0.0, ell, c);
        for (int k = 1; k <= N; ++k)
        {
            const double d = kTwoPi * k / N - (k == N ? 1e-12 : 0.0);
            const double f = eval(d, ell, c);
            if ((prevF <= 0) != (f <= 0) || prevF == 0)
            {
                double lo = prevD, hi = d, flo = prevF;
                for (int it = 0; it < 60 && flo != 0; ++it)
                {
                    const double mid = 0.5 * (lo + hi), fm = eval(mid, ell, c);
                    if ((flo <= 0) == (fm <= 0))
                        lo = mid, flo = fm;
                    else
                        hi = mid;
                }
                const double fr = eval(lo, ell, c);
                c.straight = ell;
                if (std::abs(fr) < 1e-8 && ell > -1e-9)
                {
                    c.straight = std::max(ell, 0.0);
                    c.length = turn.length(c.delta1) + c.straight + turn.length(c.delta2);
                    const Pose2 end = clothoidCurvePose(c, turn, c.length);
                    if (std::hypot(end.x - b.x, end.y - b.y) < 1e-7 && std::abs(wrapAngle(end.yaw - b.yaw)) < 1e-7)
                        out.push_back(c);
                }
            }
            prevD = d;
            prevF = f;
        }
    }
    std::sort(out.begin(), out.end(), [](const ClothoidCurve &x, const ClothoidCurve &y) { return x.length < y.length; });
    out.erase(std::unique(out.begin(), out.end(),
                          [](const ClothoidCurve &x, const ClothoidCurve &y) {
                              return std::abs(x.length - y.length) < 1e-9 && std::abs(x.delta1 - y.delta1) < 1e-9;
                          }),
              out.end());
    if (out.size() > std::size_t(maxCount)) out.resize(std::size_t(maxCount));
    return out;
}

}  // namespace gridcar
