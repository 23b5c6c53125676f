/// @file DistanceFieldUpdate.cpp
/// @brief DistanceField::update(): d_O after a few cells changed, the separable transform
/// redone where its inputs moved (the changed columns' column pass, then the rows it changed).
#include "gridcar/distance/DistanceField.h"

#include "gridcar/core/Memory.h"
#include "distance/detail/Envelope.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gridcar
{
/// Each cell's distance in cells to the nearest blocked cell of its column (the rows just
/// outside the map count as blocked), 16 bits where the map's height allows it.
struct DistanceField::Columns
{
    int W{0}, H{0};
    std::vector<std::uint16_t> g16;
    std::vector<std::uint32_t> g32;
    std::vector<float> rowMax;  ///< largest d_O per row

    bool wide() const { return H >= 65535; }
    std::uint32_t get(std::size_t i) const { return wide() ? g32[i] : std::uint32_t(g16[i]); }
    void set(std::size_t i, std::uint32_t v)
    {
        if (wide())
            g32[i] = v;
        else
            g16[i] = std::uint16_t(v);
    }
    /// The column pass of columns [c0, c1] of @p grid, row by row, into @p out(index, value).
    template <class Out>
    static void pass(const OccupancyGrid &grid, int c0, int c1, const Out &out)
    {
        const int H = grid.height(), n = c1 - c0 + 1;
        std::vector<int> last(std::size_t(n), -1);
        std::vector<std::uint32_t> up(std::size_t(n) * std::size_t(H));
        for (int r = 0; r < H; ++r)
            for (int c = c0; c <= c1; ++c)
            {
                if (grid.isBlocked(c, r)) last[std::size_t(c - c0)] = r;
                up[std::size_t(r) * std::size_t(n) + std::size_t(c - c0)] = std::uint32_t(r - last[std::size_t(c - c0)]);
            }
        std::fill(last.begin(), last.end(), H);
        for (int r = H - 1; r >= 0; --r)
            for (int c = c0; c <= c1; ++c)
            {
                if (grid.isBlocked(c, r)) last[std::size_t(c - c0)] = r;
                const std::uint32_t down = std::uint32_t(last[std::size_t(c - c0)] - r);
                out(r, c, std::min(down, up[std::size_t(r) * std::size_t(n) + std::size_t(c - c0)]));
            }
    }
};

void DistanceField::prepareUpdates(const OccupancyGrid &grid)
{
    const int W = width_, H = height_;
    if (grid.width() != W || grid.height() != H)
        throw std::invalid_argument("DistanceField::prepareUpdates: the grid is " + std::to_string(grid.width()) + " x " +
                                    std::to_string(grid.height()) + " cells, the field " + std::to_string(W) + " x " +
                                    std::to_string(H));
    const std::size_t N = std::size_t(W) * std::size_t(H);
    if (N == 0) return;
    {
        // every column's pass (the constructor's is overwritten by its row pass) and each
        // row's largest distance
        auto cols = std::make_shared<Columns>();
        cols->W = W;
        cols->H = H;
        if (cols->wide())
        {
            reserveHuge(cols->g32, N);
            cols->g32.resize(N);
        }
        else
        {
            reserveHuge(cols->g16, N);
            cols->g16.resize(N);
        }
        detail::parallelRanges(W, N, [&](int c0, int c1) {
            for (int b = c0; b < c1; b += 64)  // bands of 64 columns: a small buffer each
                Columns::pass(grid, b, std::min(c1, b + 64) - 1,
                              [&](int r, int c, std::uint32_t v) { cols->set(std::size_t(r) * W + c, v); });
        });
        cols->rowMax.assign(std::size_t(H), 0.0f);
        for (int r = 0; r < H; ++r)
            cols->rowMax[std::size_t(r)] = *std::max_element(dist_.begin() + std::ptrdiff_t(r) * W, dist_.begin() + std::ptrdiff_t(r + 1) * W);
        columns_ = std::move(cols);
    }
}

CellWindow DistanceField::update(const OccupancyGrid &grid, const CellWindow &changed)
{
    const int W = width_, H = height_;
    if (grid.width() != W || grid.height() != H)
        throw std::invalid_argument("DistanceField::update: the grid is " + std::to_string(grid.width()) + " x " +
                                    std::to_string(grid.height()) + " cells, the field " + std::to_string(W) + " x " +
                                    std::to_string(H) + ": a map of another size needs a new DistanceField");
    if (changed.empty() || W == 0 || H == 0) return {};
    if (changed.col0 < 0 || changed.row0 < 0 || changed.col1 >= W || changed.row1 >= H)
        throw std::invalid_argument("DistanceField::update: the changed window (columns " + std::to_string(changed.col0) +
                                    ".." + std::to_string(changed.col1) + ", rows " + std::to_string(changed.row0) +
                                    ".." + std::to_string(changed.row1) + ") leaves the " + std::to_string(W) + " x " +
                                    std::to_string(H) + "-cell map");
    // without prepareUpdates() (before the cells changed), every row is done again
    const bool fresh = !columns_;
    if (fresh) prepareUpdates(grid);
    Columns &cols = *columns_;
    // the changed columns' pass again: the rows where it moved are the rows to redo
    std::vector<char> dirty(std::size_t(H), fresh ? 1 : 0);
    for (int b = changed.col0; b <= changed.col1; b += 64)
        Columns::pass(grid, b, std::min(changed.col1, b + 63), [&](int r, int c, std::uint32_t v) {
            const std::size_t i = std::size_t(r) * W + c;
            if (cols.get(i) != v)
            {
                cols.set(i, v);
                dirty[std::size_t(r)] = 1;
            }
        });
    std::vector<int> rows;
    for (int r = 0; r < H; ++r)
        if (dirty[std::size_t(r)]) rows.push_back(r);
    // the row pass of those rows, as the constructor's (the same arithmetic: the same floats)
    CellWindow out{W, H, -1, -1};
    std::mutex merge;
    detail::parallelRanges(int(rows.size()), rows.size() * std::size_t(W), [&](int k0, int k1) {
        const int n = W + 2;
        std::vector<std::int64_t> f(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n));
        std::vector<int> arg(static_cast<std::size_t>(n));
        detail::Envelope env;
        env.resize(n);
        CellWindow mine{W, H, -1, -1};
        for (int k = k0; k < k1; ++k)
        {
            const int r = rows[std::size_t(k)];
            f[0] = 0;
            f[std::size_t(n) - 1] = 0;
            for (int c = 0; c < W; ++c)
            {
                const std::int64_t g = cols.get(std::size_t(r) * W + c);
                f[std::size_t(c) + 1] = g * g;
            }
            env.run(f.data(), n, d.data(), arg.data());
            float *orow = dist_.data() + std::size_t(r) * W;
            float rowMax = 0.0f;
            for (int c = 0; c < W; ++c)
            {
                const float v = float(std::sqrt(double(d[std::size_t(c) + 1])) * resolution_);
                if (v != orow[c])
                {
                    orow[c] = v;
                    mine.col0 = std::min(mine.col0, c);
                    mine.col1 = std::max(mine.col1, c);
                    mine.row0 = std::min(mine.row0, r);
                    mine.row1 = std::max(mine.row1, r);
                }
                rowMax = std::max(rowMax, v);
            }
            cols.rowMax[std::size_t(r)] = rowMax;
        }
        const std::lock_guard<std::mutex> lock(merge);
        out.col0 = std::min(out.col0, mine.col0);
        out.col1 = std::max(out.col1, mine.col1);
        out.row0 = std::min(out.row0, mine.row0);
        out.row1 = std::max(out.row1, mine.row1);
    });
    maxDist_ = H > 0 ? double(*std::max_element(cols.rowMax.begin(), cols.rowMax.end())) : 0.0;
    if (out.empty()) return {};
    // the GVD and d_V again on next use
    voronoiOnce_ = std::make_unique<std::once_flag>();
    std::vector<float>().swap(vdist_);
    std::vector<std::uint8_t>().swap(voronoi_);
    voronoiCount_ = 0;
    return out;
}

}  // namespace gridcar
