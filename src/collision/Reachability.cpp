/// @file Reachability.cpp
/// @brief FootprintChecker::reachability(): the fast-failure proof that no motion of the body
/// joins two poses (8-connected cells where its inscribed disc is not proven blocked).
#include "gridcar/collision/FootprintChecker.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gridcar
{
namespace
{
/// One end's breadth-first search over the cells where the disc is not proven blocked.
struct Front
{
    std::vector<std::uint64_t> seen;  ///< a bit per cell
    std::vector<std::uint32_t> queue;
    std::size_t head{0};
    bool has(std::size_t k) const { return (seen[k / 64] >> (k % 64)) & 1u; }
    void mark(std::size_t k) { seen[k / 64] |= std::uint64_t(1) << (k % 64); }
};
}  // namespace

FootprintChecker::Reach FootprintChecker::reachability(const Pose2 &a, bool anyYawA, const Pose2 &b, bool anyYawB,
                                                       std::size_t maxCells) const
{
    std::vector<std::array<double, 2>> offsets;
    discOffsetsInto(0.0, offsets);
    if (offsets.empty()) return {};
    // the disc nearest the reference point: the smallest circle of cells for a free heading
    std::array<double, 2> o = offsets.front();
    for (const auto &d : offsets)
        if (std::hypot(d[0], d[1]) < std::hypot(o[0], o[1])) o = d;
    const OccupancyGrid &g = *grid_;
    const int W = g.width(), H = g.height();
    const std::size_t cells = std::size_t(W) * std::size_t(H);
    if (cells == 0 || cells > std::size_t(UINT32_MAX)) return {};
    const auto open = [&](int c, int r) {
        return c >= 0 && r >= 0 && c < W && r < H && !cellBit(discBits_, std::size_t(r) * std::size_t(W) + std::size_t(c));
    };
    Front f[2];
    for (Front &x : f) x.seen.assign((cells + 63) / 64, 0);
    // the cells the disc's centre can lie in at each end: one pose, or every yaw (the circle
    // sampled finer than half a cell)
    const auto seed = [&](Front &x, const Pose2 &p, bool anyYaw) {
        const double rad = std::hypot(o[0], o[1]);
        const int n = anyYaw ? std::max(1, int(std::ceil(2 * M_PI * rad / (0.5 * g.resolution())))) : 1;
        for (int k = 0; k < n; ++k)
        {
            const double yaw = anyYaw ? 2 * M_PI * k / n : p.yaw;
            const double cs = std::cos(yaw), sn = std::sin(yaw);
            const Cell c = g.worldToCell(p.x + cs * o[0] - sn * o[1], p.y + sn * o[0] + cs * o[1]);
            if (!open(c.col, c.row)) continue;  // the body does not fit at that yaw
            const std::size_t id = std::size_t(c.row) * std::size_t(W) + std::size_t(c.col);
            if (x.has(id)) continue;
            x.mark(id);
            x.queue.push_back(std::uint32_t(id));
        }
    };
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return {};
    seed(f[0], a, anyYawA);
    seed(f[1], b, anyYawB);
    if (f[0].queue.empty() || f[1].queue.empty()) return {};  // an end where the body fits nowhere
    for (const std::uint32_t id : f[0].queue)
        if (f[1].has(id)) return {Reach::Joined};
    std::size_t visited = f[0].queue.size() + f[1].queue.size();
    while (visited < maxCells)
    {
        // the end that has visited fewer cells: a small shut room is run out of first
        const int s = f[0].queue.size() <= f[1].queue.size() ? 0 : 1;
        Front &me = f[s], &other = f[1 - s];
        if (me.head == me.queue.size()) return {Reach::Separated, s, me.queue.size()};  // all its cells seen, none of the other's
        const std::uint32_t id = me.queue[me.head++];
        const int c = int(id % std::uint32_t(W)), r = int(id / std::uint32_t(W));
        for (int dr = -1; dr <= 1; ++dr)
            for (int dc = -1; dc <= 1; ++dc)
            {
                if ((dr == 0 && dc == 0) || !open(c + dc, r + dr)) continue;
                const std::size_t k = std::size_t(r + dr) * std::size_t(W) + std::size_t(c + dc);
                if (me.has(k)) continue;
                if (other.has(k)) return {Reach::Joined};
                me.mark(k);
                me.queue.push_back(std::uint32_t(k));
                ++visited;
            }
    }
    return {};
}

}  // namespace gridcar
