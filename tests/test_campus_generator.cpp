#include "gridcar/map/CampusGenerator.h"

#include "gridcar/distance/DistanceField.h"

#include <gtest/gtest.h>

#include <queue>

using namespace gridcar;

namespace
{
/// Number of free cells 4-connected to the first free cell found.
std::size_t largestFreeComponentFrom(const OccupancyGrid &g, std::size_t &totalFree)
{
    totalFree = 0;
    std::vector<std::uint8_t> seen(g.size(), 0);
    std::size_t best = 0;
    for (int r = 0; r < g.height(); ++r)
        for (int c = 0; c < g.width(); ++c)
        {
            if (g.isBlocked(c, r)) continue;
            ++totalFree;
            if (seen[g.index(c, r)]) continue;
            std::size_t n = 0;
            std::queue<Cell> q;
            q.push({c, r});
            seen[g.index(c, r)] = 1;
            while (!q.empty())
            {
                const Cell x = q.front();
                q.pop();
                ++n;
                const int dc[4] = {1, -1, 0, 0}, dr[4] = {0, 0, 1, -1};
                for (int k = 0; k < 4; ++k)
                {
                    const int cc = x.col + dc[k], rr = x.row + dr[k];
                    if (!g.isBlocked(cc, rr) && !seen[g.index(cc, rr)])
                    {
                        seen[g.index(cc, rr)] = 1;
                        q.push({cc, rr});
                    }
                }
            }
            best = std::max(best, n);
        }
    return best;
}
}  // namespace

TEST(CampusGenerator, DeterministicFromSeed)
{
    CampusParams p;
    p.width = 900;
    p.height = 600;
    p.resolution = 0.5;
    p.seed = 42;
    const OccupancyGrid a = generateCampus(p), b = generateCampus(p);
    EXPECT_EQ(a.cells(), b.cells());
    p.seed = 43;
    const OccupancyGrid c = generateCampus(p);
    EXPECT_NE(a.cells(), c.cells());
}

TEST(CampusGenerator, DefaultIsPaperSizedWithConnectedRoadsOfCarWidth)
{
    const OccupancyGrid g = generateCampus();
    EXPECT_EQ(g.width(), 4846);
    EXPECT_EQ(g.height(), 2816);
    EXPECT_DOUBLE_EQ(g.resolution(), 0.298);
    const auto counts = g.counts();
    EXPECT_GT(counts.free, g.size() / 20);      // a real road network
    EXPECT_GT(counts.occupied, g.size() / 200);  // curbs and buildings
    EXPECT_GT(counts.unknown, g.size() / 4);     // block interiors and the margin
    // almost all free space is one connected road network
    std::size_t total = 0;
    const std::size_t biggest = largestFreeComponentFrom(g, total);
    EXPECT_GT(double(biggest) / total, 0.97);
    // road widths: the widest clear spot on a road is at least half the minimum road width;
    // the maximum clearance stays campus-like (plaza / lot), not an open field
    const DistanceField f(g);
    EXPECT_GT(f.maxDistance(), 2.5);
    EXPECT_LT(f.maxDistance(), 60.0);
}

TEST(CampusGenerator, RejectsTooSmallOrAbsurdMaps)
{
    CampusParams p;
    p.width = 50;
    p.height = 50;
    p.resolution = 0.5;
    EXPECT_THROW(generateCampus(p), std::invalid_argument);
    p.width = 1000000000;
    p.height = 1000000000;
    EXPECT_THROW(generateCampus(p), std::invalid_argument);
    p.width = 500;
    p.height = 500;
    p.resolution = -1;
    EXPECT_THROW(generateCampus(p), std::invalid_argument);
}
