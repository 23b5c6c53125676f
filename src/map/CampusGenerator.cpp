#include "gridcar/map/CampusGenerator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <stdexcept>
#include <vector>

namespace gridcar
{
namespace
{
/// Portable random numbers: mt19937_64 output is fixed by the standard; the mapping to
/// doubles/ints below is ours, so the map does not depend on the library's distributions.
class Rng
{
public:
    explicit Rng(std::uint64_t seed) : g_(seed) {}
    double uniform() { return double(g_() >> 11) * (1.0 / 9007199254740992.0); }  // [0, 1)
    double uniform(double a, double b) { return a + (b - a) * uniform(); }
    int index(int n) { return int(uniform() * n) % n; }
    bool chance(double p) { return uniform() < p; }

private:
    std::mt19937_64 g_;
};

struct Vec
{
    double x, y;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y}; }
double norm(Vec a) { return std::hypot(a.x, a.y); }

/// Rasteriser over the grid in metres (map frame: origin at the lower-left corner, y up).
class Painter
{
public:
    explicit Painter(OccupancyGrid &g) : g_(g), res_(g.resolution()) {}

    template <class Inside>
    void fill(double minX, double minY, double maxX, double maxY, CellState s, Inside inside)
    {
        const int c0 = std::max(0, int(std::floor(minX / res_)));
        const int c1 = std::min(g_.width() - 1, int(std::ceil(maxX / res_)));
        const int v0 = std::max(0, int(std::floor(minY / res_)));
        const int v1 = std::min(g_.height() - 1, int(std::ceil(maxY / res_)));
        for (int v = v0; v <= v1; ++v)
        {
            const double y = (v + 0.5) * res_;
            const int row = g_.height() - 1 - v;
            for (int c = c0; c <= c1; ++c)
            {
                const double x = (c + 0.5) * res_;
                if (inside(x, y)) g_.set(c, row, s);
            }
        }
    }

    void capsule(Vec a, Vec b, double r, CellState s)
    {
        const Vec d = b - a;
        const double len2 = d.x * d.x + d.y * d.y;
        fill(std::min(a.x, b.x) - r, std::min(a.y, b.y) - r, std::max(a.x, b.x) + r, std::max(a.y, b.y) + r, s,
             [&](double x, double y) {
                 double t = len2 > 0 ? ((x - a.x) * d.x + (y - a.y) * d.y) / len2 : 0.0;
                 t = std::clamp(t, 0.0, 1.0);
                 const double px = a.x + t * d.x - x, py = a.y + t * d.y - y;
                 return px * px + py * py <= r * r;
             });
    }

    void disc(Vec c, double r, CellState s) { capsule(c, c, r, s); }

    void rect(double x0, double y0, double x1, double y1, CellState s)
    {
        fill(x0, y0, x1, y1, s, [&](double x, double y) { return x >= x0 && x <= x1 && y >= y0 && y <= y1; });
    }

    /// Oriented box: centre, unit direction of the length axis, half length, half width.
    void box(Vec c, Vec dir, double hl, double hw, CellState s)
    {
        const double r = std::hypot(hl, hw);
        fill(c.x - r, c.y - r, c.x + r, c.y + r, s, [&](double x, double y) {
            const double dx = x - c.x, dy = y - c.y;
            const double along = dx * dir.x + dy * dir.y, across = -dx * dir.y + dy * dir.x;
            return std::abs(along) <= hl && std::abs(across) <= hw;
        });
    }

private:
    OccupancyGrid &g_;
    double res_;
};

struct Road
{
    int a, b;      // junction indices
    double width;  // metres
    Vec ctrl;      // Bezier control point (the midpoint for a straight road)
};

Vec bezier(Vec p0, Vec p1, Vec p2, double t)
{
    const double u = 1 - t;
    return (u * u) * p0 + (2 * u * t) * p1 + (t * t) * p2;
}

int findRoot(std::vector<int> &parent, int i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

/// The campus under construction: the junction grid, the roads and the painter. Each step
/// draws from the one random generator in a fixed order, so a seed always gives the same map.
struct CampusBuilder
{
    const CampusParams &p;
    OccupancyGrid &grid;
    Rng rng;
    Painter paint;
    double sx, sy, inner;
    int nx{0}, ny{0};
    double dx{0}, dy{0};
    std::vector<Vec> node;
    std::vector<Road> roads;

    CampusBuilder(const CampusParams &params, OccupancyGrid &g, double inner_)
      : p(params), grid(g), rng(params.seed), paint(g), sx(params.width * params.resolution),
        sy(params.height * params.resolution), inner(inner_)
    {
    }
    int id(int i, int j) const { return j * nx + i; }

    void placeJunctions()
    {
        // ---- junctions on a jittered grid
        nx = std::max(2, int(std::lround((sx - 2 * inner) / p.blockSize)) + 1);
        ny = std::max(2, int(std::lround((sy - 2 * inner) / p.blockSize)) + 1);
        dx = (sx - 2 * inner) / (nx - 1), dy = (sy - 2 * inner) / (ny - 1);
        node.assign(std::size_t(nx) * ny, Vec{});
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                const bool edgeX = i == 0 || i == nx - 1, edgeY = j == 0 || j == ny - 1;
                const double jx = edgeX ? 0.0 : rng.uniform(-0.18, 0.18) * dx;
                const double jy = edgeY ? 0.0 : rng.uniform(-0.18, 0.18) * dy;
                node[id(i, j)] = {inner + i * dx + jx, inner + j * dy + jy};
            }
    }

    void linkRoads()
    {
        // ---- candidate links, random spanning tree (Kruskal over shuffled links) + extras
        std::vector<std::array<int, 2>> links;
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
            {
                if (i + 1 < nx) links.push_back({id(i, j), id(i + 1, j)});
                if (j + 1 < ny) links.push_back({id(i, j), id(i, j + 1)});
            }
        for (std::size_t k = links.size(); k > 1; --k) std::swap(links[k - 1], links[std::size_t(rng.index(int(k)))]);
        std::vector<int> parent(node.size());
        std::iota(parent.begin(), parent.end(), 0);
        for (const auto &l : links)
    {
            const int ra = findRoot(parent, l[0]), rb = findRoot(parent, l[1]);
            const bool tree = ra != rb;
            if (tree) parent[ra] = rb;
            if (!tree && !rng.chance(0.7)) continue;  // drop some non-tree links: irregular blocks
            Road r;
            r.a = l[0];
            r.b = l[1];
            r.width = rng.uniform(p.roadMinWidth, p.roadMaxWidth);
            const Vec A = node[r.a], B = node[r.b];
            const Vec mid = 0.5 * (A + B);
            const Vec d = B - A;
            const double len = norm(d);
            const Vec nrm = {-d.y / len, d.x / len};
            const double bend = rng.chance(0.35) ? rng.uniform(-0.22, 0.22) * len : 0.0;
            r.ctrl = mid + bend * nrm;
            roads.push_back(r);
        }
        // one diagonal avenue across an interior block, when there is one
        if (nx >= 3 && ny >= 3)
    {
            Road r;
            const int i = 1 + rng.index(nx - 2), j = rng.index(ny - 1);
            r.a = id(i, j);
            r.b = id(i - 1, j + 1);
            r.width = p.roadMaxWidth;
            r.ctrl = 0.5 * (node[r.a] + node[r.b]);
            roads.push_back(r);
    }
    }

    void drawRoads()
    {
        // ---- draw roads (free), junction fillets
        std::vector<double> nodeWidth(node.size(), 0.0);
        for (const Road &r : roads)
    {
            const Vec A = node[r.a], B = node[r.b];
            const int segs = 24;
            Vec prev = A;
            for (int k = 1; k <= segs; ++k)
            {
                const Vec cur = bezier(A, r.ctrl, B, double(k) / segs);
                paint.capsule(prev, cur, r.width / 2, CellState::Free);
                prev = cur;
            }
            nodeWidth[r.a] = std::max(nodeWidth[r.a], r.width);
            nodeWidth[r.b] = std::max(nodeWidth[r.b], r.width);
        }
        for (std::size_t k = 0; k < node.size(); ++k)
            if (nodeWidth[k] > 0) paint.disc(node[k], 0.5 * nodeWidth[k] + 3.0, CellState::Free);
    }

    void addLotAndPlaza()
    {
        // ---- blocks: pick distinct interior blocks for the parking lot and the plaza
        struct Block
    {
            double x0, y0, x1, y1;
        };
        auto blockOf = [&](int i, int j) {
            const Vec a = node[id(i, j)], b = node[id(i + 1, j + 1)];
            const double pad = p.roadMaxWidth / 2 + 0.18 * std::max(dx, dy) * 0.5 + 4.0;
            return Block{a.x + pad, a.y + pad, b.x - pad, b.y - pad};
        };
        const int nBlocks = (nx - 1) * (ny - 1);
        const int lotBlock = rng.index(nBlocks);
        int plazaBlock = rng.index(nBlocks);
        if (nBlocks > 1 && plazaBlock == lotBlock) plazaBlock = (plazaBlock + 1) % nBlocks;

        // access road (7 m) from a point to its nearest junction: keeps lot and plaza connected
        auto accessRoad = [&](Vec from) {
            std::size_t best = 0;
            for (std::size_t k = 1; k < node.size(); ++k)
                if (norm(node[k] - from) < norm(node[best] - from)) best = k;
            paint.capsule(from, node[best], 3.5, CellState::Free);
        };
        // parking lot: free rectangle near the block's lower edge road, rows of islands
    {
            Block b = blockOf(lotBlock % (nx - 1), lotBlock / (nx - 1));
            const double w = std::min(90.0, b.x1 - b.x0), h = std::min(60.0, b.y1 - b.y0);
            if (w > 30 && h > 25)
            {
                const double x0 = 0.5 * (b.x0 + b.x1) - w / 2, y0 = b.y0 - p.roadMaxWidth;  // reaches the road
                paint.rect(x0, y0, x0 + w, b.y0 + h, CellState::Free);
                for (double y = b.y0 + 12.0; y + 2 < b.y0 + h - 6.0; y += 16.0)
                    paint.rect(x0 + 8.0, y, x0 + w - 8.0, y + 1.5, CellState::Occupied);
                // parked-car islands near the far edge
                for (double x = x0 + 10.0; x + 2.0 < x0 + w - 10.0; x += 6.0)
                    if (rng.chance(0.5)) paint.rect(x, b.y0 + h - 5.0, x + 2.0, b.y0 + h - 0.5, CellState::Occupied);
                accessRoad({x0 + 4.0, y0 + 4.0});
            }
        }
        // plaza: free square with buildings; the gaps between buildings are narrow walkways
        if (nBlocks > 1)
    {
            Block b = blockOf(plazaBlock % (nx - 1), plazaBlock / (nx - 1));
            const double x0 = b.x0 - p.roadMaxWidth, y0 = b.y0 - p.roadMaxWidth;
            const double x1 = b.x1 + p.roadMaxWidth, y1 = b.y1 + p.roadMaxWidth;
            if (x1 - x0 > 50 && y1 - y0 > 50)
            {
                paint.rect(x0, y0, x1, y1, CellState::Free);
                const double bx0 = b.x0 + 10, by0 = b.y0 + 10, bx1 = b.x1 - 10, by1 = b.y1 - 10;
                const int cols = std::max(1, int((bx1 - bx0) / 40.0)), rows = std::max(1, int((by1 - by0) / 35.0));
                const double cw = (bx1 - bx0) / cols, ch = (by1 - by0) / rows;
                for (int r = 0; r < rows; ++r)
                    for (int c = 0; c < cols; ++c)
                    {
                        const double gap = rng.uniform(3.0, 4.5);  // walkway width between buildings
                        paint.rect(bx0 + c * cw + gap / 2, by0 + r * ch + gap / 2, bx0 + (c + 1) * cw - gap / 2,
                                   by0 + (r + 1) * ch - gap / 2, CellState::Occupied);
                    }
                accessRoad({x0 + 4.0, y0 + 4.0});
            }
        }
    }

    void addRoundaboutAndGates()
    {
        // roundabout at an interior junction (or any junction on small maps)
    {
            const int i = nx > 2 ? 1 + rng.index(nx - 2) : 0, j = ny > 2 ? 1 + rng.index(ny - 2) : 0;
            const Vec c = node[id(i, j)];
            paint.disc(c, 20.0, CellState::Free);
            paint.disc(c, 8.0, CellState::Occupied);
        }
        // gates: narrow a few straight stretches of road to narrowWidth
        for (int k = 0; k < p.narrowPassages && !roads.empty(); ++k)
    {
            const Road &r = roads[std::size_t(rng.index(int(roads.size())))];
            const Vec A = node[r.a], B = node[r.b];
            const Vec c = bezier(A, r.ctrl, B, 0.5);
            const Vec t = bezier(A, r.ctrl, B, 0.52) - bezier(A, r.ctrl, B, 0.48);
            const Vec dir = (1.0 / norm(t)) * t;
            const Vec nrm = {-dir.y, dir.x};
            const double side = (r.width + 4.0) / 2;  // covers past the curb
            const double hw = (side - p.narrowWidth / 2) / 2;
            const double off = p.narrowWidth / 2 + hw;
            paint.box(c + off * nrm, dir, 2.0, hw, CellState::Occupied);
            paint.box(c - off * nrm, dir, 2.0, hw, CellState::Occupied);
        }
    }
};

/// Curbs: unknown cells within curbWidth of free space become occupied.
void addCurbs(OccupancyGrid &grid, const CampusParams &p)
{
    const int w = grid.width(), h = grid.height();
    const int rad = std::max(1, int(std::lround(p.curbWidth / p.resolution)));
    std::vector<CellState> &cells = grid.cells();
    std::vector<std::uint8_t> nearFree(cells.size(), 0);
    // horizontal then vertical dilation of the free set by rad cells (a square curb profile)
    for (int row = 0; row < h; ++row)
    {
        int last = -1000000;
        for (int c = 0; c < w; ++c)
        {
            if (cells[grid.index(c, row)] == CellState::Free) last = c;
            if (c - last <= rad) nearFree[grid.index(c, row)] = 1;
        }
        last = 1000000;
        for (int c = w - 1; c >= 0; --c)
        {
            if (cells[grid.index(c, row)] == CellState::Free) last = c;
            if (last - c <= rad) nearFree[grid.index(c, row)] = 1;
        }
    }
    std::vector<std::uint8_t> curb(nearFree);
    for (int c = 0; c < w; ++c)
    {
        int last = -1000000;
        for (int row = 0; row < h; ++row)
        {
            if (nearFree[grid.index(c, row)]) last = row;
            if (row - last <= rad) curb[grid.index(c, row)] = 1;
        }
        last = 1000000;
        for (int row = h - 1; row >= 0; --row)
        {
            if (nearFree[grid.index(c, row)]) last = row;
            if (last - row <= rad) curb[grid.index(c, row)] = 1;
        }
    }
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (curb[i] && cells[i] == CellState::Unknown) cells[i] = CellState::Occupied;
    }
}  // namespace

OccupancyGrid generateCampus(const CampusParams &p)
{
    if (!(p.resolution > 0) || !std::isfinite(p.resolution))
    throw std::invalid_argument("campus resolution must be positive");
    OccupancyGrid grid(p.width, p.height, p.resolution, CellState::Unknown);  // validates size
    const double sx = p.width * p.resolution, sy = p.height * p.resolution;
    const double inner = p.margin + 8.0;
    if (sx - 2 * inner < 40.0 || sy - 2 * inner < 40.0)
    throw std::invalid_argument("campus map too small: need at least about " +
                                std::to_string(int(2 * inner + 40)) + " m per side");
    if (!(p.roadMinWidth > 0) || p.roadMaxWidth < p.roadMinWidth || !(p.blockSize > 20))
    throw std::invalid_argument("campus road widths / block size are inconsistent");
    CampusBuilder b(p, grid, inner);
    b.placeJunctions();
    b.linkRoads();
    b.drawRoads();
    b.addLotAndPlaza();
    b.addRoundaboutAndGates();
    addCurbs(grid, p);
    // ---- unknown margin band (outside the surveyed area)
    {
    const int m = int(std::lround(p.margin / p.resolution));
    for (int row = 0; row < grid.height(); ++row)
        for (int c = 0; c < grid.width(); ++c)
            if (row < m || c < m || row >= grid.height() - m || c >= grid.width() - m)
                grid.set(c, row, CellState::Unknown);
    }
    return grid;
}

}  // namespace gridcar
