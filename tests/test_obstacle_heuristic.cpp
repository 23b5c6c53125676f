/// @file test_obstacle_heuristic.cpp
/// @brief ObstacleHeuristic (the car lattice's 2D distance, resumed on demand towards a target)
/// against a plain Dijkstra over the same graph: its guide, its resumption and its per-node
/// tests (asked once, all axes at once) change the order of work, never a distance; its
/// lowerBound() never exceeds one.
#include "gridcar/planners/search/ObstacleHeuristic.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <vector>

using namespace gridcar;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<std::array<int, 2>> stepsOf(int headings)
{
    // the lattices' 2D steps: 8 (axes and diagonals) or 16 (with the knight's moves)
    std::vector<std::array<int, 2>> s{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    if (headings == 16)
        s = {{1, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 1}, {-1, 2}, {-1, 1}, {-2, 1},
             {-1, 0}, {-2, -1}, {-1, -1}, {-1, -2}, {0, -1}, {1, -2}, {1, -1}, {2, -1}};
    return s;
}

struct Graph
{
    int i0, j0, ni, nj;
    std::vector<char> free;            ///< per node
    std::vector<std::uint16_t> axes;   ///< per node: the axes the car fits on
    std::vector<double> weight;        ///< per node, >= 1
    bool at(int i, int j) const { return free[std::size_t(j - j0) * ni + (i - i0)] != 0; }
    std::size_t idx(int i, int j) const { return std::size_t(j - j0) * ni + (i - i0); }
};

/// Plain Dijkstra from the seeds over the graph ObstacleHeuristic documents.
std::vector<double> dijkstra(const Graph &g, const std::vector<std::array<int, 2>> &steps, double cell,
                             const std::vector<std::pair<std::array<int, 2>, double>> &seeds, bool useAxes,
                             bool useWeights)
{
    const int H = int(steps.size());
    std::vector<double> d(std::size_t(g.ni) * g.nj, kInf);
    using E = std::pair<double, std::size_t>;
    std::priority_queue<E, std::vector<E>, std::greater<E>> pq;
    for (const auto &s : seeds)
        if (d[g.idx(s.first[0], s.first[1])] > s.second)
        {
            d[g.idx(s.first[0], s.first[1])] = s.second;
            pq.push({s.second, g.idx(s.first[0], s.first[1])});
        }
    while (!pq.empty())
    {
        const auto [dist, n] = pq.top();
        pq.pop();
        if (dist > d[n]) continue;
        const int i = int(n % std::size_t(g.ni)) + g.i0, j = int(n / std::size_t(g.ni)) + g.j0;
        for (int k = 0; k < H; ++k)
        {
            const int a = i + steps[std::size_t(k)][0], b = j + steps[std::size_t(k)][1];
            if (a < g.i0 || b < g.j0 || a >= g.i0 + g.ni || b >= g.j0 + g.nj) continue;
            const std::size_t m = g.idx(a, b);
            if (useAxes)
            {
                const int axis = k % (H / 2);
                if (!((g.axes[n] >> axis) & 1u) || !((g.axes[m] >> axis) & 1u)) continue;
            }
            else if (!g.at(a, b))
                continue;
            double len = cell * std::hypot(double(steps[std::size_t(k)][0]), double(steps[std::size_t(k)][1]));
            if (useWeights) len *= std::min(g.weight[n], g.weight[m]);
            if (dist + len < d[m])
            {
                d[m] = dist + len;
                pq.push({d[m], m});
            }
        }
    }
    return d;
}
}  // namespace

TEST(ObstacleHeuristic, ResumedDistancesAreDijkstrasForEveryNodeAndOrder)
{
    int compared = 0, unreachable = 0, informative = 0;
    for (int headings : {8, 16})
        for (unsigned seed = 1; seed <= 6; ++seed)
        {
            const bool useAxes = seed % 2 == 0, useWeights = seed % 3 == 0;
            std::mt19937 rng(seed * 31 + unsigned(headings));
            Graph g{-7, -4, 46, 38, {}, {}, {}};
            std::bernoulli_distribution blocked(0.25), axisOk(0.8);
            std::uniform_real_distribution<double> w(1.0, 3.0);
            const std::size_t N = std::size_t(g.ni) * g.nj;
            for (std::size_t n = 0; n < N; ++n)
            {
                g.free.push_back(!blocked(rng));
                std::uint16_t m = 0;
                for (int a = 0; a < headings / 2; ++a)
                    if (g.free.back() && axisOk(rng)) m = std::uint16_t(m | (1u << a));
                g.axes.push_back(m);
                g.weight.push_back(double(float(w(rng))));  // (the heuristic keeps weights as floats)
            }
            const auto steps = stepsOf(headings);
            const double cell = 0.45;
            std::vector<std::pair<std::array<int, 2>, double>> seeds{{{30, 25}, 0.1}, {{31, 25}, 0.3}};
            for (const auto &s : seeds)  // (the goal's nodes: where the car stands)
            {
                g.free[g.idx(s.first[0], s.first[1])] = 1;
                g.axes[g.idx(s.first[0], s.first[1])] = 0xffff;
            }
            const auto want = dijkstra(g, steps, cell, seeds, useAxes, useWeights);

            ObstacleHeuristic h(steps, cell, [&g](int i, int j) { return g.at(i, j); });
            if (useAxes)
            {
                std::vector<int> axis;
                for (int k = 0; k < headings; ++k) axis.push_back(k % (headings / 2));
                h.setAxisTest(axis, [&g](int i, int j) { return g.axes[g.idx(i, j)]; });
            }
            if (useWeights) h.setWeight([&g](int i, int j) { return g.weight[g.idx(i, j)]; });
            // the target is the query's start; every node is then asked in a random order
            h.reset(g.i0, g.j0, g.ni, g.nj, seeds, 0, 0);
            std::vector<std::size_t> order(N);
            for (std::size_t n = 0; n < N; ++n) order[n] = n;
            std::shuffle(order.begin(), order.end(), rng);
            std::swap(order[0], *std::find(order.begin(), order.end(), g.idx(0, 0)));
            for (std::size_t n : order)
            {
                const int i = int(n % std::size_t(g.ni)) + g.i0, j = int(n / std::size_t(g.ni)) + g.j0;
                // a node the car does not fit at is unreachable for the heuristic
                const double expect = g.at(i, j) ? want[n] : kInf;
                // the bound that resumes nothing: never above the distance, and the distance
                // itself once the node is closed
                const double below = h.lowerBound(i, j);
                if (below == kInf) EXPECT_EQ(expect, kInf) << i << "," << j;
                else EXPECT_LE(below, expect * (1 + 1e-12)) << headings << " seed " << seed << " node " << i << "," << j;
                informative += below > 0 && below < kInf;
                const double got = h.distance(i, j);
                if (got < kInf) EXPECT_EQ(h.lowerBound(i, j), got);
                if (expect == kInf)
                {
                    EXPECT_EQ(got, kInf) << i << "," << j;
                    ++unreachable;
                }
                else
                    EXPECT_NEAR(got, expect, 1e-9 * (1 + expect)) << headings << " seed " << seed << " node " << i << "," << j;
                ++compared;
            }
        }
    EXPECT_GT(compared, 10000);
    EXPECT_GT(unreachable, 1000);
    EXPECT_GT(informative, 1000);
}
