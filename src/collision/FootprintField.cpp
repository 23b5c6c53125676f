/// @file FootprintField.cpp
/// @brief FootprintChecker's tests on the distance field: the grown bodies, the quick verdicts
/// (circumscribed circle, disc cover, inscribed discs) and the exact halving test.
#include "gridcar/collision/FootprintChecker.h"

#include <algorithm>
#include <cmath>

namespace gridcar
{
FootprintChecker::Body FootprintChecker::makeBody(const VehicleParams &v, double margin)
{
    Body b{};
    b.length = v.length + 2 * margin;
    b.width = v.width + 2 * margin;
    b.rear = v.rearOverhang + margin;
    b.rIn = 0.5 * std::min(b.length, b.width);
    b.rOut = 0.5 * std::hypot(b.length, b.width);
    b.discs = std::max(1, int(std::ceil(2 * b.length / std::max(b.width, 1e-9) - 1e-9)));
    b.discStep = b.length / b.discs;
    b.discR = std::hypot(b.width / 2, b.discStep / 2);
    b.firstDisc = -b.rear + b.discStep / 2;
    return b;
}

int FootprintChecker::quickBody(const Body &b, double x, double y, double yaw, double cs, double sn) const
{
    (void)yaw;
    const double off = b.length / 2 - b.rear;
    const Cell c = grid_->worldToCell(x + off * cs, y + off * sn);
    if (grid_->isBlocked(c.col, c.row)) return 0;
    const double d = field_->cellDistance(c.col, c.row);
    if (d - 2.0 * halfDiag_ > b.rOut) return 1;
    if (d + halfDiag_ < b.rIn) return 0;
    for (int k = 0; k < b.discs; ++k)
    {
        const double along = b.firstDisc + k * b.discStep;
        const Cell dc = grid_->worldToCell(x + along * cs, y + along * sn);
        if (!(field_->cellDistance(dc.col, dc.row) - 2.0 * halfDiag_ > b.discR)) return -1;
    }
    return 2;  // proven free by the discs
}

bool FootprintChecker::rectFree(double cx, double cy, double cs, double sn, double a, double b) const
{
    const Cell c = grid_->worldToCell(cx, cy);
    if (grid_->isBlocked(c.col, c.row)) return false;  // the centre lies in a blocked cell
    if (field_->cellDistance(c.col, c.row) - 2.0 * halfDiag_ > std::sqrt(a * a + b * b)) return true;
    const double res = grid_->resolution();
    if (a > res || b > res)
    {
        if (a >= b)
            return rectFree(cx - cs * a / 2, cy - sn * a / 2, cs, sn, a / 2, b) &&
                   rectFree(cx + cs * a / 2, cy + sn * a / 2, cs, sn, a / 2, b);
        return rectFree(cx + sn * b / 2, cy - cs * b / 2, cs, sn, a, b / 2) &&
               rectFree(cx - sn * b / 2, cy + cs * b / 2, cs, sn, a, b / 2);
    }
    // a piece at most a cell long: separating axes against each blocked square in reach
    const double ex = a * std::abs(cs) + b * std::abs(sn), ey = a * std::abs(sn) + b * std::abs(cs);
    const Cell lo = grid_->worldToCell(cx - ex, cy + ey), hi = grid_->worldToCell(cx + ex, cy - ey);
    const double s = res / 2, su = s * (std::abs(cs) + std::abs(sn));
    for (int row = std::min(lo.row, hi.row); row <= std::max(lo.row, hi.row); ++row)
        for (int col = std::min(lo.col, hi.col); col <= std::max(lo.col, hi.col); ++col)
        {
            if (!grid_->isBlocked(col, row)) continue;
            const double dx = grid_->cellCenterX(col) - cx, dy = grid_->cellCenterY(row) - cy;
            if (std::abs(dx) > s + ex || std::abs(dy) > s + ey) continue;          // square's axes
            if (std::abs(dx * cs + dy * sn) > a + su) continue;                     // rectangle's length
            if (std::abs(-dx * sn + dy * cs) > b + su) continue;                    // rectangle's width
            return false;
        }
    return true;
}

const FootprintChecker::Body &FootprintChecker::bodyFor(double margin) const
{
    // the car lattice asks for two margins over and over: the last two bodies per thread, keyed
    // by everything a body depends on (not by checker address, which a new checker may reuse)
    struct Slot
    {
        double length{-1}, width{-1}, rear{-1}, margin{-1};
        Body body{};
    };
    thread_local Slot slots[2];
    thread_local int next = 0;
    const VehicleParams &v = vehicle_;
    for (Slot &s : slots)
        if (s.margin == margin && s.length == v.length && s.width == v.width && s.rear == v.rearOverhang) return s.body;
    Slot &s = slots[next];
    next = 1 - next;
    s.length = v.length;
    s.width = v.width;
    s.rear = v.rearOverhang;
    s.margin = margin;
    s.body = makeBody(vehicle_, margin);
    return s.body;
}

std::vector<std::array<double, 2>> FootprintChecker::inscribedDiscOffsets(double yaw) const
{
    std::vector<std::array<double, 2>> out;
    if (vehicle_.isPoint()) return {{0.0, 0.0}};
    const double cs = std::cos(yaw), sn = std::sin(yaw);
    const double L = vehicle_.length, W = vehicle_.width, rear = vehicle_.rearOverhang;
    const double r = std::min(L, W) / 2;
    // centres along the longer axis where the disc of radius r stays inside the rectangle
    const double span = std::max(L, W) - 2 * r;
    const int n = 1 + int(std::ceil(span / std::max(2 * r, 1e-9)));  // discs at most 2 r apart: any subset proves
    for (int k = 0; k < n; ++k)
    {
        const double t = n == 1 ? 0.5 : double(k) / (n - 1);
        double bx = L / 2 - rear, by = 0;  // centre
        if (L >= W)
            bx = -rear + r + t * span;
        else
            by = -W / 2 + r + t * span;
        out.push_back({cs * bx - sn * by, sn * bx + cs * by});
    }
    return out;
}

bool FootprintChecker::provenBlockedAt(double x, double y, const std::vector<std::array<double, 2>> &offsets) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return true;
    const double r = vehicle_.isPoint() ? 0.0 : std::min(vehicle_.length, vehicle_.width) / 2;
    for (const auto &o : offsets)
    {
        const Cell c = grid_->worldToCell(x + o[0], y + o[1]);
        if (grid_->isBlocked(c.col, c.row)) return true;
        if (field_->cellDistance(c.col, c.row) + halfDiag_ < r) return true;
    }
    return false;
}

bool FootprintChecker::provenBlocked(const Pose2 &p) const
{
    if (!std::isfinite(p.yaw)) return true;
    return provenBlockedAt(p.x, p.y, inscribedDiscOffsets(p.yaw));
}

bool FootprintChecker::provenFree(const Pose2 &p, double margin) const
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw) || !std::isfinite(margin)) return false;
    if (vehicle_.isPoint()) return !cellBlockedAt(p.x, p.y) && !(margin > 0);
    const Body &b = margin > 0 ? bodyFor(margin) : body_;
    return quickBody(b, p.x, p.y, p.yaw, std::cos(p.yaw), std::sin(p.yaw)) >= 1;
}

}  // namespace gridcar
