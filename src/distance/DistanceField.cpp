#include "gridcar/distance/DistanceField.h"

#include "gridcar/core/Memory.h"
#include "distance/detail/Envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace gridcar
{
namespace
{
using detail::Envelope;
using detail::kInf;
using detail::parallelRanges;

/// Reusable buffers of edt2d() (the transform runs twice per field: allocate once).
struct EdtWorkspace
{
    std::vector<int> nearRow, nearCol, tmp;
};

/// Exact 2D EDT of a site mask over a W x H grid, in metres (cells * res) into @p out. With
/// @p borderSites the ring just outside the grid is made of sites too. With @p wantNearest the
/// workspace's nearCol / nearRow hold each cell's nearest site afterwards (-1 / W / H for
/// border sites); otherwise they are not used. Columns, then rows, are shared among threads.
void edt2d(const std::vector<std::uint8_t> &site, int W, int H, bool borderSites, double res,
           std::vector<float> &out, EdtWorkspace &ws, bool wantNearest)
{
    const std::size_t N = std::size_t(W) * H;
    std::vector<int> &nearRow = ws.nearRow, &nearCol = ws.nearCol;
    const int none = 1 << 29;
    // column pass, row-major friendly: forward and backward sweeps keep the last site per
    // column (each thread its own band of columns). Each cell's nearest site row goes to
    // nearRow where the nearest sites are wanted, else into out itself (floats hold these
    // integers exactly), which the row pass then overwrites row by row: one grid-sized array
    // fewer to commit (97 MB on a 24 M-cell map)
    auto columnPass = [&](auto *rows) {
        parallelRanges(W, N, [&](int c0, int c1) {
            std::vector<int> last(std::size_t(W), borderSites ? -1 : -none);
            for (int r = 0; r < H; ++r)
            {
                const std::uint8_t *srow = site.data() + std::size_t(r) * W;
                auto *nrow = rows + std::size_t(r) * W;
                for (int c = c0; c < c1; ++c)
                {
                    if (srow[c]) last[std::size_t(c)] = r;
                    nrow[c] = last[std::size_t(c)];
                }
            }
            std::fill(last.begin(), last.end(), borderSites ? H : none);
            for (int r = H - 1; r >= 0; --r)
            {
                const std::uint8_t *srow = site.data() + std::size_t(r) * W;
                auto *nrow = rows + std::size_t(r) * W;
                for (int c = c0; c < c1; ++c)
                {
                    if (srow[c]) last[std::size_t(c)] = r;
                    const int down = last[std::size_t(c)];
                    if (down - r < r - int(nrow[c])) nrow[c] = down;
                }
            }
        });
    };
    reserveHuge(out, N);
    out.resize(N);
    if (wantNearest)
    {
        reserveHuge(nearRow, N);
        nearRow.resize(N);
        columnPass(nearRow.data());
        reserveHuge(nearCol, N);
        nearCol.resize(N);
    }
    else
        columnPass(out.data());
    // row pass: FH envelope over W (+2 border sites at -1 and W), each thread its own rows
    parallelRanges(H, N, [&](int r0, int r1) {
        const int n = W + 2;
        std::vector<std::int64_t> f(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n));
        std::vector<int> arg(static_cast<std::size_t>(n));
        Envelope env;
        env.resize(n);
        for (int r = r0; r < r1; ++r)
        {
            f[0] = borderSites ? 0 : kInf;
            f[std::size_t(n) - 1] = borderSites ? 0 : kInf;
            float *orow = out.data() + std::size_t(r) * W;
            for (int c = 0; c < W; ++c)
            {
                const int near = wantNearest ? nearRow[std::size_t(r) * W + c] : int(orow[c]);
                const std::int64_t dy = std::int64_t(near) - r;
                f[std::size_t(c) + 1] = std::abs(dy) >= (1 << 28) ? kInf : dy * dy;
            }
            env.run(f.data(), n, d.data(), arg.data());
            for (int c = 0; c < W; ++c)
            {
                const std::int64_t v = d[std::size_t(c) + 1];
                orow[c] = v >= kInf ? std::numeric_limits<float>::infinity() : float(std::sqrt(double(v)) * res);
            }
            if (wantNearest)
                for (int c = 0; c < W; ++c) nearCol[std::size_t(r) * W + c] = arg[std::size_t(c) + 1] - 1;
        }
    });
    if (!wantNearest) return;
    // resolve the nearest row for each cell from the column pass of its nearest column
    reserveHuge(ws.tmp, N);
    ws.tmp.resize(N);
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c)
        {
            const std::size_t i = std::size_t(r) * W + c;
            const int nc = nearCol[i];
            ws.tmp[i] = (nc < 0 || nc >= W) ? r : nearRow[std::size_t(r) * W + nc];
        }
    nearRow.swap(ws.tmp);
}
}  // namespace

DistanceField::DistanceField(const OccupancyGrid &grid)
  : width_(grid.width())
  , height_(grid.height())
  , resolution_(grid.resolution())
  , originX_(grid.originX())
  , originY_(grid.originY())
{
    const int W = width_, H = height_;
    const std::size_t N = std::size_t(W) * H;
    if (N == 0) return;
    std::vector<std::uint8_t> blocked;
    reserveHuge(blocked, N);
    blocked.resize(N);
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c) blocked[std::size_t(r) * W + c] = grid.isBlocked(c, r) ? 1 : 0;
    EdtWorkspace ws;
    edt2d(blocked, W, H, true, resolution_, dist_, ws, false);
    for (std::size_t i = 0; i < N; ++i) maxDist_ = std::max(maxDist_, double(dist_[i]));
}

void DistanceField::voronoiReady() const
{
    std::call_once(*voronoiOnce_, [this] { buildVoronoi(); });
}

void DistanceField::buildVoronoi() const
{
    const int W = width_, H = height_;
    const std::size_t N = std::size_t(W) * H;
    if (N == 0) return;
    // the blocked cells are those at distance 0 (a free cell is at least a cell from one)
    std::vector<std::uint8_t> blocked;
    reserveHuge(blocked, N);
    blocked.resize(N);
    for (std::size_t i = 0; i < N; ++i) blocked[i] = dist_[i] > 0.0f ? 0 : 1;
    // the transform again, for each cell's nearest obstacle cell
    EdtWorkspace ws;
    std::vector<float> again;
    edt2d(blocked, W, H, true, resolution_, again, ws, true);

    // ---- generalized Voronoi diagram: 4-neighbours whose nearest obstacles lie on opposite
    // sides (cell -> obstacle vectors more than 90 degrees apart) and are not next to each other
    const std::vector<int> &nearCol = ws.nearCol, &nearRow = ws.nearRow;
    const double sep2 = voronoiSeparationCells * voronoiSeparationCells;
    reserveHuge(voronoi_, N);
    voronoi_.assign(N, 0);
    auto consider = [&](std::size_t i, std::size_t j) {
        if (blocked[i] || blocked[j]) return;
        const double dc = nearCol[i] - nearCol[j], dr = nearRow[i] - nearRow[j];
        if (dc * dc + dr * dr <= sep2) return;
        const int ci = int(i % std::size_t(W)), ri = int(i / std::size_t(W));
        const int cj = int(j % std::size_t(W)), rj = int(j / std::size_t(W));
        const double ax = nearCol[i] - ci, ay = nearRow[i] - ri, bx = nearCol[j] - cj, by = nearRow[j] - rj;
        if (ax * bx + ay * by >= 0.0) return;
        const std::size_t mark = (dist_[i] > dist_[j] || (dist_[i] == dist_[j] && i < j)) ? i : j;
        voronoi_[mark] = 1;
    };
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c)
        {
            const std::size_t i = std::size_t(r) * W + c;
            if (c + 1 < W) consider(i, i + 1);
            if (r + 1 < H) consider(i, i + W);
        }
    voronoiCount_ = std::size_t(std::count(voronoi_.begin(), voronoi_.end(), std::uint8_t(1)));

    // ---- distance to the GVD (+inf everywhere when there is none)
    reserveHuge(vdist_, N);
    if (voronoiCount_ > 0)
        edt2d(voronoi_, W, H, false, resolution_, vdist_, ws, false);
    else
        vdist_.assign(N, std::numeric_limits<float>::infinity());
}

bool DistanceField::bilinearCorners(double x, double y, double corner[4], double &fu, double &fv) const
{
    const double u = (x - originX_) / resolution_ - 0.5;  // column-centre coordinates
    const double v = (y - originY_) / resolution_ - 0.5;  // from the bottom
    if (!(u >= -0.5 && v >= -0.5 && u <= width_ - 0.5 && v <= height_ - 0.5)) return false;
    const int c0 = int(std::floor(u)), v0 = int(std::floor(v));
    fu = u - c0;
    fv = v - v0;
    // past the outermost cell centres, clamp to the edge cell (it already carries its
    // distance to the border obstacle half a cell beyond)
    auto at = [&](int c, int vv) {
        c = std::clamp(c, 0, width_ - 1);
        vv = std::clamp(vv, 0, height_ - 1);
        return double(dist_[idx(c, height_ - 1 - vv)]);
    };
    corner[0] = at(c0, v0);
    corner[1] = at(c0 + 1, v0);
    corner[2] = at(c0, v0 + 1);
    corner[3] = at(c0 + 1, v0 + 1);
    return true;
}

double DistanceField::distance(double x, double y) const
{
    double k[4], fu, fv;
    if (!bilinearCorners(x, y, k, fu, fv)) return 0.0;
    return (1 - fv) * ((1 - fu) * k[0] + fu * k[1]) + fv * ((1 - fu) * k[2] + fu * k[3]);
}

void DistanceField::gradient(double x, double y, double &gx, double &gy) const
{
    gx = gy = 0.0;
    double k[4], fu, fv;
    if (!bilinearCorners(x, y, k, fu, fv)) return;
    gx = ((1 - fv) * (k[1] - k[0]) + fv * (k[3] - k[2])) / resolution_;
    gy = ((1 - fu) * (k[2] - k[0]) + fu * (k[3] - k[1])) / resolution_;
}

double DistanceField::voronoiDistance(double x, double y) const
{
    const int c = int(std::floor((x - originX_) / resolution_));
    const int vv = int(std::floor((y - originY_) / resolution_));
    return cellVoronoiDistance(c, height_ - 1 - vv);
}

double DistanceField::voronoiField(double x, double y, const VoronoiFieldParams &p) const
{
    const double dO = distance(x, y);
    if (dO <= 0.0) return 1.0;
    if (dO > p.dOMax) return 0.0;
    const double dV = voronoiDistance(x, y);
    const double mid = std::isinf(dV) ? 1.0 : dV / (dO + dV);
    const double t = (dO - p.dOMax) / p.dOMax;
    return (p.alpha / (p.alpha + dO)) * mid * t * t;
}

}  // namespace gridcar
