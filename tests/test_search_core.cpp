// The search core's building blocks: the open list's order and the integer keys it sorts by.
// (The A* loop itself is tested through the planners: test_planners.cpp, test_improved_astar.cpp.)
#include "gridcar/planners/SearchCore.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

using namespace gridcar;

TEST(SearchCore, OrderedBitsKeepTheOrderOfDoublesAndFloats)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1e6, 1e6);
    std::vector<double> xs = {0.0, -0.0, 1e-300, -1e-300, 1.0, -1.0, 1e300, -1e300, 0.5, 2.0 / 3.0};
    for (int i = 0; i < 2000; ++i) xs.push_back(u(rng));
    for (double a : xs)
    {
        EXPECT_EQ(fromOrderedBits(orderedBits(a)), a);
        for (int j = 0; j < 20; ++j)
        {
            const double b = xs[std::size_t(j * 97 + 3) % xs.size()];
            if (a < b) EXPECT_LT(orderedBits(a), orderedBits(b)) << a << " " << b;
            if (a > b) EXPECT_GT(orderedBits(a), orderedBits(b)) << a << " " << b;
            const float fa = float(a), fb = float(b);
            if (fa < fb) EXPECT_LT(orderedBits(fa), orderedBits(fb)) << fa << " " << fb;
            if (fa > fb) EXPECT_GT(orderedBits(fa), orderedBits(fb)) << fa << " " << fb;
        }
    }
}

TEST(SearchCore, OpenEntryOrderIsLowerFThenHigherGThenLowerState)
{
    EXPECT_TRUE(openBefore(OpenEntry(1.0, 5.0f, 9), OpenEntry(2.0, 9.0f, 0)));   // f first
    EXPECT_TRUE(openBefore(OpenEntry(1.0, 6.0f, 9), OpenEntry(1.0, 5.0f, 0)));   // then higher g
    EXPECT_TRUE(openBefore(OpenEntry(1.0, 5.0f, 3), OpenEntry(1.0, 5.0f, 4)));   // then lower index
    EXPECT_FALSE(openBefore(OpenEntry(1.0, 5.0f, 3), OpenEntry(1.0, 5.0f, 3)));  // strict
    const OpenEntry e(12.75, 3.5f, 42);
    EXPECT_EQ(e.f(), 12.75);
    EXPECT_EQ(e.s(), 42u);
}

// The open list keeps plateau entries in a second heap; whatever goes where, the pops must come
// out exactly as from one priority queue, also when pushes fall below the last popped f (an
// inconsistent heuristic or priority).
TEST(SearchCore, OpenListPopsInExactlyTheOrderOfOnePriorityQueue)
{
    for (int seed = 0; seed < 6; ++seed)
    {
        std::mt19937 rng(seed);
        std::uniform_int_distribution<int> step(0, 4), gi(0, 50), op(0, 9);
        std::uniform_int_distribution<std::uint32_t> si(0, 1000);
        OpenList open;
        std::set<std::tuple<double, float, std::uint32_t>> ref;  // (f, -g, s)
        double lastF = 0.0;
        int popped = 0;
        for (int i = 0; i < 20000; ++i)
        {
            if (ref.empty() || op(rng) < 6)
            {
                // mostly f on or just above the last popped one (a plateau: the exact same
                // value, or one that differs in the last bits), sometimes below it
                double f = lastF + 0.25 * step(rng);
                if (op(rng) == 0) f = std::nextafter(f, 1e9);
                if (seed % 2 == 1 && op(rng) == 0) f = lastF - 0.5;
                const float g = float(gi(rng));
                const std::uint32_t s = si(rng);
                if (!ref.emplace(f, -g, s).second) continue;  // one entry per key, as in A*
                open.push(OpenEntry(f, g, s));
            }
            else
            {
                ASSERT_FALSE(open.empty());
                const OpenEntry e = open.pop();
                const auto want = *ref.begin();
                ref.erase(ref.begin());
                ASSERT_EQ(e.f(), std::get<0>(want)) << "pop " << popped;
                ASSERT_EQ(e.s(), std::get<2>(want)) << "pop " << popped;
                lastF = e.f();
                ++popped;
            }
        }
        while (!ref.empty())
        {
            const OpenEntry e = open.pop();
            ASSERT_EQ(e.s(), std::get<2>(*ref.begin()));
            ref.erase(ref.begin());
        }
        EXPECT_TRUE(open.empty());
        EXPECT_GT(popped, 5000);
    }
}
