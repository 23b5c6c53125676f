// VehicleParams' polygon footprint: checked, oriented, its bounding rectangle.
#include "gridcar/vehicle/VehicleParams.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gridcar
{
namespace
{
double cross(const std::array<double, 2> &o, const std::array<double, 2> &a, const std::array<double, 2> &b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// True if closed segments ab and cd share a point.
bool segmentsMeet(const std::array<double, 2> &a, const std::array<double, 2> &b, const std::array<double, 2> &c,
                  const std::array<double, 2> &d)
{
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    const auto on = [](const std::array<double, 2> &p, const std::array<double, 2> &q, const std::array<double, 2> &r) {
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    return (d1 == 0 && on(c, d, a)) || (d2 == 0 && on(c, d, b)) || (d3 == 0 && on(a, b, c)) || (d4 == 0 && on(a, b, d));
}
}  // namespace

void VehicleParams::setFootprint(std::vector<std::array<double, 2>> poly)
{
    const std::size_t n = poly.size();
    if (n < 3) throw std::invalid_argument("vehicle footprint needs at least 3 vertices, got " + std::to_string(n));
    if (n > 1000) throw std::invalid_argument("vehicle footprint has more than 1000 vertices");
    for (const auto &p : poly)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || std::abs(p[0]) > 500 || std::abs(p[1]) > 500)
            throw std::invalid_argument("vehicle footprint vertices must be finite and within 500 m of the reference point");
    double area2 = 0;
    for (std::size_t i = 0; i < n; ++i)
        area2 += poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1];
    if (!(std::abs(area2) > 1e-9)) throw std::invalid_argument("vehicle footprint has no area");
    // simple: no two edges meet except neighbours at their shared vertex
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
        {
            const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
            const auto &a = poly[i], &b = poly[(i + 1) % n], &c = poly[j], &d = poly[(j + 1) % n];
            if (adjacent)
            {
                // neighbours share one vertex; they must not fold back over each other
                const auto &shared = j == i + 1 ? b : a;
                const auto &p = j == i + 1 ? a : b, &q = j == i + 1 ? d : c;
                if (shared == p || shared == q) throw std::invalid_argument("vehicle footprint repeats a vertex");
                if (cross(shared, p, q) == 0 && (p[0] - shared[0]) * (q[0] - shared[0]) + (p[1] - shared[1]) * (q[1] - shared[1]) > 0)
                    throw std::invalid_argument("vehicle footprint folds back on itself at vertex " +
                                                std::to_string((j == i + 1 ? j : i) + 1));
                continue;
            }
            if (segmentsMeet(a, b, c, d))
                throw std::invalid_argument("vehicle footprint is not a simple polygon: edge " + std::to_string(i + 1) +
                                            " meets edge " + std::to_string(j + 1));
        }
    if (area2 < 0) std::reverse(poly.begin(), poly.end());
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, yAbs = 0;
    for (const auto &p : poly)
    {
        x0 = std::min(x0, p[0]);
        x1 = std::max(x1, p[0]);
        yAbs = std::max(yAbs, std::abs(p[1]));
    }
    length = x1 - x0;
    width = 2 * yAbs;
    rearOverhang = -x0;  // may be negative when the reference point lies behind the body
    footprint = std::move(poly);
}

std::vector<std::array<double, 2>> VehicleParams::outline() const
{
    if (hasPolygon()) return footprint;
    if (isPoint()) return {};
    const double xr = -rearOverhang, xf = length - rearOverhang, hw = width / 2;
    return {{xr, -hw}, {xf, -hw}, {xf, hw}, {xr, hw}};
}

}  // namespace gridcar
