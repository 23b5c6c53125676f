/// @file FootprintField.cpp
/// @brief FootprintChecker's tests on the distance field: the grown bodies, the quick verdicts
/// (circumscribed circle, disc cover, inscribed discs) and the exact halving test.
#include "gridcar/collision/FootprintChecker.h"

#include "collision/detail/ExactTiles.h"
#include "collision/detail/Polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
namespace
{
/// FootprintChecker::changesSince() answers for this many cellsChanged() calls back.
constexpr std::size_t kChangesKept = 64;
}  // namespace

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
    b.margin = margin;
    b.polygon = v.hasPolygon();
    b.centreInside = true;
    if (b.polygon)
    {
        // a blocked cell at the rectangle's centre proves a collision only if the centre is
        // inside the polygon, and then only within the polygon's own distance to its boundary
        const detail::Pt centre{v.centreOffset(), 0.0};
        b.centreInside = detail::inPolygon(centre, v.footprint);
        b.rIn = b.centreInside ? detail::boundaryDistance(centre, v.footprint) + margin : 0.0;
    }
    return b;
}

int FootprintChecker::quickBody(const Body &b, double x, double y, double yaw, double cs, double sn) const
{
    (void)yaw;
    const double off = b.length / 2 - b.rear;
    const Cell c = grid_->worldToCell(x + off * cs, y + off * sn);
    const double d = field_->cellDistance(c.col, c.row);
    if (!(d > 0)) return b.centreInside ? 0 : -1;  // a blocked cell (distance 0) or off the map
    if (d - 2.0 * halfDiag_ > b.rOut) return 1;
    if (b.centreInside && d + halfDiag_ < b.rIn) return 0;
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
    // distance 0: the centre lies in a blocked cell (or off the map); no second lookup in the grid
    const double d = field_->cellDistance(c.col, c.row);
    if (!(d > 0)) return false;
    if (d - 2.0 * halfDiag_ > std::sqrt(a * a + b * b)) return true;
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

bool FootprintChecker::triangleFree(const std::array<double, 6> &t, int depth) const
{
    const double cx = (t[0] + t[2] + t[4]) / 3, cy = (t[1] + t[3] + t[5]) / 3;
    const Cell c = grid_->worldToCell(cx, cy);
    if (grid_->isBlocked(c.col, c.row)) return false;  // the centroid lies in a blocked cell
    double reach = 0, longest = 0;
    int e = 0;
    for (int i = 0; i < 3; ++i)
    {
        reach = std::max(reach, std::hypot(t[2 * i] - cx, t[2 * i + 1] - cy));
        const int j = (i + 1) % 3;
        const double l = std::hypot(t[2 * j] - t[2 * i], t[2 * j + 1] - t[2 * i + 1]);
        if (l > longest) longest = l, e = i;
    }
    if (field_->cellDistance(c.col, c.row) - 2.0 * halfDiag_ > reach) return true;
    const double res = grid_->resolution();
    if (longest > res && depth < 40)
    {
        // halve at the longest edge's midpoint: two triangles, still counter-clockwise
        const int i = e, j = (e + 1) % 3, k = (e + 2) % 3;
        const double mx = (t[2 * i] + t[2 * j]) / 2, my = (t[2 * i + 1] + t[2 * j + 1]) / 2;
        const std::array<double, 6> t1{t[2 * i], t[2 * i + 1], mx, my, t[2 * k], t[2 * k + 1]};
        const std::array<double, 6> t2{mx, my, t[2 * j], t[2 * j + 1], t[2 * k], t[2 * k + 1]};
        return triangleFree(t1, depth + 1) && triangleFree(t2, depth + 1);
    }
    const detail::Tri tri{{t[0], t[1]}, {t[2], t[3]}, {t[4], t[5]}};
    const double x0 = std::min({t[0], t[2], t[4]}), x1 = std::max({t[0], t[2], t[4]});
    const double y0 = std::min({t[1], t[3], t[5]}), y1 = std::max({t[1], t[3], t[5]});
    const Cell lo = grid_->worldToCell(x0, y1), hi = grid_->worldToCell(x1, y0);
    for (int row = std::min(lo.row, hi.row) - 1; row <= std::max(lo.row, hi.row) + 1; ++row)
        for (int col = std::min(lo.col, hi.col) - 1; col <= std::max(lo.col, hi.col) + 1; ++col)
            if (grid_->isBlocked(col, row) &&
                detail::triangleMeetsSquare(tri, grid_->cellCenterX(col), grid_->cellCenterY(row), res / 2))
                return false;
    return true;
}

bool FootprintChecker::polygonFree(const Body &b, double x, double y, double cs, double sn) const
{
    for (const auto &bt : tris_)
    {
        detail::Tri tri{{bt[0], bt[1]}, {bt[2], bt[3]}, {bt[4], bt[5]}};
        tri = detail::grown(tri, b.margin);
        const detail::Pt v[3] = {tri.a, tri.b, tri.c};
        std::array<double, 6> w{};
        for (int i = 0; i < 3; ++i)
        {
            w[2 * i] = x + cs * v[i][0] - sn * v[i][1];
            w[2 * i + 1] = y + sn * v[i][0] + cs * v[i][1];
        }
        if (!triangleFree(w, 0)) return false;
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
        std::vector<std::array<double, 2>> footprint;
        Body body{};
    };
    thread_local Slot slots[2];
    thread_local int next = 0;
    const VehicleParams &v = vehicle_;
    for (Slot &s : slots)
        if (s.margin == margin && s.length == v.length && s.width == v.width && s.rear == v.rearOverhang &&
            s.footprint == v.footprint)
            return s.body;
    Slot &s = slots[next];
    next = 1 - next;
    s.length = v.length;
    s.width = v.width;
    s.rear = v.rearOverhang;
    s.margin = margin;
    s.footprint = v.footprint;
    s.body = makeBody(vehicle_, margin);
    return s.body;
}

std::vector<std::array<double, 2>> FootprintChecker::inscribedDiscOffsets(double yaw) const
{
    std::vector<std::array<double, 2>> out;
    discOffsetsInto(yaw, out);
    return out;
}

void FootprintChecker::discOffsetsInto(double yaw, std::vector<std::array<double, 2>> &out) const
{
    discOffsetsInto(std::cos(yaw), std::sin(yaw), out);
}

void FootprintChecker::discOffsetsInto(double cs, double sn, std::vector<std::array<double, 2>> &out) const
{
    out.clear();
    if (vehicle_.isPoint())
    {
        out.push_back({0.0, 0.0});
        return;
    }
    if (vehicle_.hasPolygon())
    {
        for (const auto &d : provenDiscs_) out.push_back({cs * d[0] - sn * d[1], sn * d[0] + cs * d[1]});
        return;
    }
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
}

bool FootprintChecker::discBlockedCell(int col, int row) const
{
    // blocked cells (and cells off the map) have distance 0: for discs wider than a half cell
    // diagonal the field's test catches them, and the grid need not be read
    const bool readGrid = !(discR_ > halfDiag_);
    return (readGrid && grid_->isBlocked(col, row)) || field_->cellDistance(col, row) + halfDiag_ < discR_;
}

void FootprintChecker::buildDiscBits()
{
    // one bit per cell: 3 MB for a 24 M-cell map, where the field is 97 MB. The 2D heuristic's
    // standing tests read cells all round each node, and waited on memory for the field's floats
    const int W = grid_->width(), H = grid_->height();
    discBits_.assign((std::size_t(W) * std::size_t(H) + 63) / 64, 0);
    clearBits_.assign(discBits_.size(), 0);
    setDiscBits({0, 0, W - 1, H - 1});
}

void FootprintChecker::setDiscBits(const CellWindow &w)
{
    const int W = grid_->width();
    for (int r = w.row0; r <= w.row1; ++r)
        for (int c = w.col0; c <= w.col1; ++c)
        {
            const std::size_t k = std::size_t(r) * std::size_t(W) + std::size_t(c);
            const std::uint64_t bit = std::uint64_t(1) << (k % 64);
            discBits_[k / 64] = discBlockedCell(c, r) ? discBits_[k / 64] | bit : discBits_[k / 64] & ~bit;
            clearBits_[k / 64] = discsClearAtEveryYaw(field_->cellDistance(c, r)) ? clearBits_[k / 64] | bit : clearBits_[k / 64] & ~bit;
        }
}

void FootprintChecker::cellsChanged(const CellWindow &cells, const CellWindow &field)
{
    ++mapVersion_;
    changes_.emplace_back(cells, field);
    if (changes_.size() > kChangesKept) changes_.pop_front();
    const int W = grid_->width(), H = grid_->height();
    const auto clip = [&](const CellWindow &w) {
        return CellWindow{std::max(0, w.col0), std::max(0, w.row0), std::min(W - 1, w.col1), std::min(H - 1, w.row1)};
    };
    // a cell's bits read its own state and distance
    for (const CellWindow &w : {clip(cells), clip(field)})
        if (!w.empty()) setDiscBits(w);
    // a box covers boundary cells: a change there moves its 4-neighbours' boundary too
    if (exact_ && !cells.empty()) exact_->reset(clip({cells.col0 - 1, cells.row0 - 1, cells.col1 + 1, cells.row1 + 1}));
}

std::optional<std::vector<std::pair<CellWindow, CellWindow>>> FootprintChecker::changesSince(std::uint64_t since) const
{
    if (since > mapVersion_ || mapVersion_ - since > changes_.size()) return std::nullopt;
    return std::vector<std::pair<CellWindow, CellWindow>>(changes_.end() - std::ptrdiff_t(mapVersion_ - since),
                                                          changes_.end());
}

bool FootprintChecker::discsClearAtEveryYawAt(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return false;
    const Cell c = grid_->worldToCell(x, y);
    if (c.col < 0 || c.row < 0 || c.col >= grid_->width() || c.row >= grid_->height()) return discsClearAtEveryYaw(0.0);
    return cellBit(clearBits_, std::size_t(c.row) * std::size_t(grid_->width()) + std::size_t(c.col));
}

bool FootprintChecker::provenBlockedAt(double x, double y, const std::vector<std::array<double, 2>> &offsets) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return true;
    const int W = grid_->width(), H = grid_->height();
    for (const auto &o : offsets)
    {
        const Cell c = grid_->worldToCell(x + o[0], y + o[1]);
        const bool on = c.col >= 0 && c.row >= 0 && c.col < W && c.row < H;
        if (on ? cellBit(discBits_, std::size_t(c.row) * std::size_t(W) + std::size_t(c.col)) : discBlockedCell(c.col, c.row))
            return true;
    }
    return false;
}

bool FootprintChecker::provenBlocked(const Pose2 &p) const
{
    if (!std::isfinite(p.yaw)) return true;
    return provenBlocked(p, std::cos(p.yaw), std::sin(p.yaw));
}

bool FootprintChecker::provenBlocked(const Pose2 &p, double cs, double sn) const
{
    if (!std::isfinite(p.yaw)) return true;
    thread_local std::vector<std::array<double, 2>> offsets;  // the search asks for millions: no allocation each
    discOffsetsInto(cs, sn, offsets);
    return provenBlockedAt(p.x, p.y, offsets);
}

double FootprintChecker::freeSlack(const Pose2 &p, double below) const
{
    if (!std::isfinite(p.yaw)) return 0.0;
    return freeSlack(p, std::cos(p.yaw), std::sin(p.yaw), below);
}

double FootprintChecker::freeSlack(const Pose2 &p, double cs, double sn, double below) const
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw) || vehicle_.isPoint()) return 0.0;
    // the discs of quickBody()'s cover: the rectangle grown by r lies inside the discs grown by r
    const Body &b = body_;
    double slack = std::numeric_limits<double>::infinity();
    // the end discs first: where the body is tight, a corner usually is
    for (int n = 0; n < b.discs && slack > below; ++n)
    {
        const int k = n % 2 == 0 ? n / 2 : b.discs - 1 - n / 2;
        const double along = b.firstDisc + k * b.discStep;
        const Cell dc = grid_->worldToCell(p.x + along * cs, p.y + along * sn);
        slack = std::min(slack, field_->cellDistance(dc.col, dc.row) - 2.0 * halfDiag_ - b.discR);
    }
    return slack;
}

bool FootprintChecker::provenFree(const Pose2 &p, double margin) const
{
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw) || !std::isfinite(margin)) return false;
    if (vehicle_.isPoint()) return !cellBlockedAt(p.x, p.y) && !(margin > 0);
    const Body &b = margin > 0 ? bodyFor(margin) : body_;
    return quickBody(b, p.x, p.y, p.yaw, std::cos(p.yaw), std::sin(p.yaw)) >= 1;
}

}  // namespace gridcar
