#pragma once
/// @file Polygon.h
/// @brief Plane polygon helpers of the footprint checker (private): ear-clipping triangulation
/// of a simple counter-clockwise polygon, point in polygon, distance to the boundary, a
/// triangle grown by a margin, and the separating-axis test of a triangle and a square.

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gridcar::detail
{
using Pt = std::array<double, 2>;

/// A triangle, counter-clockwise.
struct Tri
{
    Pt a, b, c;
};

inline double cross(const Pt &o, const Pt &a, const Pt &b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// True if @p p lies in the closed triangle.
inline bool inTriangle(const Pt &p, const Tri &t)
{
    return cross(t.a, t.b, p) >= 0 && cross(t.b, t.c, p) >= 0 && cross(t.c, t.a, p) >= 0;
}

/// Ear clipping of a simple counter-clockwise polygon into n - 2 counter-clockwise triangles.
inline std::vector<Tri> triangulate(std::vector<Pt> poly)
{
    std::vector<Tri> out;
    std::size_t guard = 0;
    while (poly.size() > 3)
    {
        const std::size_t n = poly.size();
        bool clipped = false;
        for (std::size_t i = 0; i < n && !clipped; ++i)
        {
            const Pt &p = poly[(i + n - 1) % n], &q = poly[i], &r = poly[(i + 1) % n];
            if (cross(p, q, r) <= 0) continue;  // reflex or flat: not an ear
            const Tri t{p, q, r};
            bool empty = true;
            for (std::size_t k = 0; k < n && empty; ++k)
            {
                if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) continue;
                if (poly[k] != p && poly[k] != q && poly[k] != r && inTriangle(poly[k], t)) empty = false;
            }
            if (!empty) continue;
            out.push_back(t);
            poly.erase(poly.begin() + long(i));
            clipped = true;
        }
        if (!clipped)
        {
            // only collinear vertices left between ears: drop one flat vertex
            bool dropped = false;
            for (std::size_t i = 0; i < n && !dropped; ++i)
                if (cross(poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]) == 0)
                {
                    poly.erase(poly.begin() + long(i));
                    dropped = true;
                }
            if (!dropped || ++guard > 10000) throw std::invalid_argument("footprint polygon cannot be triangulated");
        }
    }
    if (poly.size() == 3 && cross(poly[0], poly[1], poly[2]) > 0) out.push_back({poly[0], poly[1], poly[2]});
    return out;
}

/// True if @p p lies inside the simple polygon (even-odd rule).
inline bool inPolygon(const Pt &p, const std::vector<Pt> &poly)
{
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i][1] > p[1]) != (poly[j][1] > p[1]) &&
            p[0] < (poly[j][0] - poly[i][0]) * (p[1] - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0])
            in = !in;
    return in;
}

/// Distance from @p p to the polygon's boundary.
inline double boundaryDistance(const Pt &p, const std::vector<Pt> &poly)
{
    double best = HUGE_VAL;
    for (std::size_t i = 0; i < poly.size(); ++i)
    {
        const Pt &a = poly[i], &b = poly[(i + 1) % poly.size()];
        const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
        const double t = l2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
    }
    return best;
}

/// The triangle with every edge moved out by @p m (mitred corners): it contains every point
/// within @p m of the triangle.
inline Tri grown(const Tri &t, double m)
{
    if (!(m > 0)) return t;
    const Pt v[3] = {t.a, t.b, t.c};
    // each edge i (v[i] -> v[i+1]) as a point and a direction, moved along its outward normal
    Pt p[3], d[3];
    for (int i = 0; i < 3; ++i)
    {
        const Pt &a = v[i], &b = v[(i + 1) % 3];
        const double dx = b[0] - a[0], dy = b[1] - a[1], l = std::hypot(dx, dy);
        d[i] = {dx / l, dy / l};
        p[i] = {a[0] + m * d[i][1], a[1] - m * d[i][0]};  // outward normal of a CCW edge: (dy, -dx)
    }
    Pt out[3];
    for (int i = 0; i < 3; ++i)
    {
        // vertex i + 1 = intersection of edge i and edge i + 1
        const int j = (i + 1) % 3;
        const double den = d[i][0] * d[j][1] - d[i][1] * d[j][0];
        const double s = ((p[j][0] - p[i][0]) * d[j][1] - (p[j][1] - p[i][1]) * d[j][0]) / den;
        out[j] = {p[i][0] + s * d[i][0], p[i][1] + s * d[i][1]};
    }
    return {out[0], out[1], out[2]};
}

/// Separating-axis test: do the closed triangle and the axis-aligned square of half side @p s
/// centred at (@p cx, @p cy) overlap?
inline bool triangleMeetsSquare(const Tri &t, double cx, double cy, double s)
{
    const Pt v[3] = {t.a, t.b, t.c};
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (const Pt &p : v)
    {
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    if (x1 < cx - s || x0 > cx + s || y1 < cy - s || y0 > cy + s) return false;  // the square's axes
    for (int i = 0; i < 3; ++i)
    {
        const Pt &a = v[i], &b = v[(i + 1) % 3];
        const double nx = b[1] - a[1], ny = -(b[0] - a[0]);  // outward normal
        const double edge = nx * a[0] + ny * a[1];
        const double square = nx * cx + ny * cy - s * (std::abs(nx) + std::abs(ny));  // the square's nearest extent
        if (square > edge) return false;
    }
    return true;
}

}  // namespace gridcar::detail
