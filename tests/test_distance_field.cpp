#include "gridcar/distance/DistanceField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace gridcar;

namespace
{
OccupancyGrid randomGrid(int w, int h, double density, unsigned seed, double res = 0.3)
{
    OccupancyGrid g(w, h, res);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
        {
            const double x = u(rng);
            g.set(c, r, x < density ? CellState::Occupied : x < density * 1.1 ? CellState::Unknown : CellState::Free);
        }
    return g;
}

/// Distance from cell (c, r) to the nearest blocked cell centre or border ring cell, by search.
double bruteForce(const OccupancyGrid &g, int c, int r)
{
    if (g.isBlocked(c, r)) return 0.0;
    double best = 1e300;
    for (int rr = -1; rr <= g.height(); ++rr)
        for (int cc = -1; cc <= g.width(); ++cc)
            if (g.isBlocked(cc, rr))  // off-map cells are blocked: the border ring
                best = std::min(best, std::hypot(double(cc - c), double(rr - r)));
    return best * g.resolution();
}
/// Two separate walls (rows 0 and 20, columns 5..74), unknown free: a corridor 19 cells wide.
OccupancyGrid corridor()
{
    OccupancyGrid g(80, 21, 0.2);
    g.setUnknownIsFree(true);
    for (int c = 5; c < 75; ++c)
    {
        g.set(c, 0, CellState::Occupied);
        g.set(c, 20, CellState::Occupied);
    }
    return g;
}
}  // namespace

TEST(DistanceField, ExactAgainstBruteForceOnRandomGrids)
{
    for (double density : {0.0, 0.01, 0.05, 0.2, 0.5, 0.9})
        for (unsigned seed : {1u, 2u})
        {
            const OccupancyGrid g = randomGrid(37, 23, density, seed);
            const DistanceField f(g);
            for (int r = 0; r < g.height(); ++r)
                for (int c = 0; c < g.width(); ++c)
                    ASSERT_NEAR(f.cellDistance(c, r), bruteForce(g, c, r), 1e-5)
                        << "density " << density << " cell " << c << "," << r;
        }
}

// A map of 1.2 M cells: the transform shares its columns and rows among threads; cells
// sampled across the whole map, the border rows and columns among them, against brute force.
TEST(DistanceField, ThreadedTransformOnALargeGridIsExact)
{
    const OccupancyGrid g = randomGrid(1200, 1000, 0.0005, 3u, 0.05);
    const DistanceField f(g);
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> uc(0, g.width() - 1), ur(0, g.height() - 1);
    for (int k = 0; k < 120; ++k)
    {
        const int c = k < 20 ? (k % 2 ? 0 : g.width() - 1) : uc(rng), r = k < 20 ? ur(rng) : k < 40 ? (k % 2 ? 0 : g.height() - 1) : ur(rng);
        ASSERT_NEAR(f.cellDistance(c, r), bruteForce(g, c, r), 1e-4) << "cell " << c << "," << r;
    }
}

TEST(DistanceField, BorderIsAnObstacleAndUnknownFollowsTheGrid)
{
    OccupancyGrid g(9, 5, 1.0);
    g.set(4, 2, CellState::Unknown);
    const DistanceField f(g);
    EXPECT_DOUBLE_EQ(f.cellDistance(0, 0), 1.0);  // next to the border ring
    EXPECT_DOUBLE_EQ(f.cellDistance(4, 2), 0.0);  // unknown is blocked
    EXPECT_DOUBLE_EQ(f.cellDistance(2, 2), 2.0);
    g.setUnknownIsFree(true);
    const DistanceField h(g);
    EXPECT_DOUBLE_EQ(h.cellDistance(4, 2), 3.0);  // centre: 3 cells to the top/bottom border ring
    EXPECT_DOUBLE_EQ(h.maxDistance(), 3.0);
}

TEST(DistanceField, BilinearInterpolationAndGradient)
{
    // one long wall along the bottom: d grows linearly with y, gradient (0, 1)
    OccupancyGrid g(60, 40, 0.5);
    g.setOrigin(10.0, 20.0);
    for (int c = 0; c < 60; ++c) g.set(c, 39, CellState::Occupied);
    g.setUnknownIsFree(true);
    const DistanceField f(g);
    // at cell centres the interpolation is exact
    EXPECT_NEAR(f.distance(g.cellCenterX(30), g.cellCenterY(35)), f.cellDistance(30, 35), 1e-6);
    // between centres, linear in y for a point well inside (nearest obstacle is the wall)
    const double x = g.cellCenterX(30), y0 = g.cellCenterY(36), y1 = g.cellCenterY(35);
    EXPECT_NEAR(f.distance(x, 0.5 * (y0 + y1)), 0.5 * (f.cellDistance(30, 36) + f.cellDistance(30, 35)), 1e-6);
    double gx, gy;
    f.gradient(x + 0.1, 0.5 * (y0 + y1), gx, gy);
    EXPECT_NEAR(gx, 0.0, 1e-6);
    EXPECT_NEAR(gy, 1.0, 1e-6);
    // off the map: distance 0
    EXPECT_EQ(f.distance(0.0, 0.0), 0.0);
}

TEST(DistanceField, VoronoiIsTheCorridorCentreline)
{
    const OccupancyGrid g = corridor();
    const DistanceField f(g);
    ASSERT_GT(f.voronoiCellCount(), 0u);
    // in the middle of the corridor the GVD lies on row 10 (equidistant), one cell thick
    for (int c = 20; c < 60; ++c)
    {
        int count = 0, row = -1;
        for (int r = 1; r < 20; ++r)
            if (f.isVoronoi(c, r))
            {
                ++count;
                row = r;
            }
        EXPECT_EQ(count, 1) << "column " << c;
        EXPECT_NEAR(row, 10, 1) << "column " << c;
    }
    EXPECT_NEAR(f.cellVoronoiDistance(40, 10), 0.0, 1.5 * 0.2);
    EXPECT_NEAR(f.cellVoronoiDistance(40, 4), 6 * 0.2, 1.5 * 0.2);
}

TEST(DistanceField, VoronoiFieldFollowsDolgov)
{
    const OccupancyGrid g = corridor();
    const DistanceField f(g);
    VoronoiFieldParams p;
    p.alpha = 1.0;
    p.dOMax = 3.0;
    const double x = g.cellCenterX(40), y = g.cellCenterY(5);
    const double dO = f.distance(x, y), dV = f.voronoiDistance(x, y);
    const double expect = (1.0 / (1.0 + dO)) * (dV / (dO + dV)) * std::pow((dO - 3.0) / 3.0, 2);
    EXPECT_NEAR(f.voronoiField(x, y, p), expect, 1e-9);
    EXPECT_DOUBLE_EQ(f.voronoiField(g.cellCenterX(40), g.cellCenterY(0), p), 1.0);  // inside an obstacle
    // on the GVD the field is 0 (d_V = 0): the safest place
    int vr = 1;
    while (!f.isVoronoi(40, vr)) ++vr;
    EXPECT_NEAR(f.voronoiField(g.cellCenterX(40), g.cellCenterY(vr), p), 0.0, 1e-9);
}

// update(): after random edits (obstacles added and removed, rectangles and single cells, a
// map with unknown cells, one wider than 64 columns), the field equals a full recomputation
// cell for cell, the window returned holds every cell that changed, and the GVD follows.
TEST(DistanceField, UpdateAfterRandomEditsEqualsAFullRecomputation)
{
    for (unsigned seed : {1u, 2u, 3u})
    {
        SCOPED_TRACE(seed);
        OccupancyGrid g = randomGrid(seed == 3 ? 150 : 61, seed == 2 ? 90 : 47, 0.02 * seed, seed);
        DistanceField f(g);
        if (seed == 1) ASSERT_GT(f.voronoiCellCount(), 0u);  // built before the edits: built again after
        std::mt19937 rng(seed * 7919u);
        for (int edit = 0; edit < 12; ++edit)
        {
            std::uniform_int_distribution<int> col(0, g.width() - 1), row(0, g.height() - 1), size(0, 9);
            CellWindow w;
            w.col0 = col(rng);
            w.row0 = row(rng);
            w.col1 = std::min(g.width() - 1, w.col0 + size(rng));
            w.row1 = std::min(g.height() - 1, w.row0 + size(rng));
            const CellState to = edit % 3 == 2 ? CellState::Free : CellState::Occupied;
            for (int r = w.row0; r <= w.row1; ++r)
                for (int c = w.col0; c <= w.col1; ++c) g.set(c, r, (c + r + edit) % 4 == 0 ? CellState::Unknown : to);
            std::vector<float> before(std::size_t(g.width() * g.height()));
            for (int r = 0; r < g.height(); ++r)
                for (int c = 0; c < g.width(); ++c) before[std::size_t(r * g.width() + c)] = float(f.cellDistance(c, r));
            const CellWindow moved = f.update(g, w);
            const DistanceField full(g);
            for (int r = 0; r < g.height(); ++r)
                for (int c = 0; c < g.width(); ++c)
                {
                    ASSERT_EQ(f.cellDistance(c, r), full.cellDistance(c, r)) << "edit " << edit << " cell " << c << "," << r;
                    const bool inside = c >= moved.col0 && c <= moved.col1 && r >= moved.row0 && r <= moved.row1;
                    if (!inside) ASSERT_EQ(float(f.cellDistance(c, r)), before[std::size_t(r * g.width() + c)]);
                }
            EXPECT_EQ(f.maxDistance(), full.maxDistance());
        }
        const DistanceField full(g);
        EXPECT_EQ(f.voronoiCellCount(), full.voronoiCellCount());
        for (int r = 0; r < g.height(); ++r)
            for (int c = 0; c < g.width(); ++c) ASSERT_EQ(f.cellVoronoiDistance(c, r), full.cellVoronoiDistance(c, r));
    }
}

TEST(DistanceField, UpdateRejectsAnotherSizeAndAWindowOffTheMap)
{
    OccupancyGrid g = randomGrid(20, 10, 0.1, 4);
    DistanceField f(g);
    EXPECT_THROW(f.update(randomGrid(21, 10, 0.1, 4), {0, 0, 1, 1}), std::invalid_argument);
    EXPECT_THROW(f.update(g, {0, 0, 20, 3}), std::invalid_argument);
    EXPECT_THROW(f.update(g, {-1, 0, 2, 3}), std::invalid_argument);
    EXPECT_TRUE(f.update(g, {}).empty());
    EXPECT_TRUE(f.update(g, {0, 0, 19, 9}).empty());  // nothing changed
}
