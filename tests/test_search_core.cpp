// The search core's building blocks: the open list's order and the integer keys it sorts by.
// (The A* loop itself is tested through the planners: test_planners.cpp, test_improved_astar.cpp.)
#include "gridcar/planners/search/AStar.h"
#include "gridcar/planners/search/detail/StateInterner.h"

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

// The lazy open list must pop exactly as one priority queue over (f, -g, state), with ties on f
// (plateaus, and f values one ulp apart) and pushes below the last popped f (an inconsistent
// heuristic or priority).
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

TEST(SearchCore, IndexedOpenListPopsInOrderWithDecreaseKey)
{
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> fi(0, 400), gi(0, 50), op(0, 9);
    const std::uint32_t n = 500;
    std::vector<std::uint32_t> pos(n);
    IndexedOpenList open(pos.data());
    std::vector<int> inList(n, 0);
    std::vector<OpenEntry> current(n);  // the key each state in the list has now
    int pops = 0, decreases = 0;
    for (int i = 0; i < 30000; ++i)
    {
        const int o = op(rng);
        std::uint32_t s = std::uint32_t(rng() % n);
        if (o < 4 && !inList[s])
        {
            const OpenEntry e(fi(rng) * 0.5, float(gi(rng)), s);
            open.push(e);
            current[s] = e;
            inList[s] = 1;
        }
        else if (o < 7)
        {
            std::uint32_t t = s;  // a state in the list, if any
            while (!inList[t] && (t = (t + 1) % n) != s)
            {
            }
            if (!inList[t]) continue;
            s = t;
            // a lower key: lower f (and any g)
            const OpenEntry old = current[s];
            const double f = old.f() - 0.5 * (1 + fi(rng) % 5);
            const OpenEntry e(f, float(gi(rng)), s);
            open.decrease(e);
            current[s] = e;
            ++decreases;
        }
        else if (!open.empty())
        {
            const OpenEntry e = open.pop();
            // the least key among the states in the list
            std::uint32_t best = n;
            for (std::uint32_t t = 0; t < n; ++t)
                if (inList[t] && (best == n || openBefore(current[t], current[best]))) best = t;
            ASSERT_EQ(e.s(), best) << "pop " << pops;
            ASSERT_EQ(e.key, current[best].key);
            inList[best] = 0;
            ++pops;
        }
    }
    EXPECT_GT(pops, 5000);
    EXPECT_GT(decreases, 3000);
}

namespace
{
// 8-connected random grid with octile costs, no corner cutting: a small expander for astar()
struct RandomGridExpander
{
    int W, H;
    std::vector<char> blocked;
    std::uint32_t goal;
    double octile(int c, int r) const
    {
        const int dx = std::abs(int(goal % W) - c), dy = std::abs(int(goal / W) - r);
        return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
    }
    double heuristic(std::uint32_t s) const { return octile(int(s % W), int(s / W)); }
    bool isGoal(std::uint32_t s) const { return s == goal; }
    bool free(int c, int r) const { return c >= 0 && r >= 0 && c < W && r < H && !blocked[r * W + c]; }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        const int c = int(s % W), r = int(s / W);
        for (int dc = -1; dc <= 1; ++dc)
            for (int dr = -1; dr <= 1; ++dr)
            {
                if ((dc == 0 && dr == 0) || !free(c + dc, r + dr)) continue;
                if (dc != 0 && dr != 0 && (!free(c + dc, r) || !free(c, r + dr))) continue;
                emit(std::uint32_t((r + dr) * W + c + dc), (dc != 0 && dr != 0) ? std::sqrt(2.0) : 1.0,
                     heuristic(std::uint32_t((r + dr) * W + c + dc)));
            }
    }
};
}  // namespace

// The dense space searches with the decrease-key open list, the growing space with lazy deletion:
// both must expand the same states in the same order and agree on every g and parent.
TEST(SearchCore, DecreaseKeyAndLazyDeletionSearchesAreIdentical)
{
    int compared = 0;
    for (unsigned seed = 1; seed <= 12; ++seed)
    {
        std::mt19937 rng(seed);
        RandomGridExpander ex{60, 45, {}, 0};
        ex.blocked.resize(std::size_t(ex.W) * ex.H);
        for (auto &b : ex.blocked) b = (rng() % 100) < 25;
        const std::uint32_t start = rng() % (ex.W * ex.H), goal = rng() % (ex.W * ex.H);
        ex.blocked[start] = ex.blocked[goal] = 0;
        ex.goal = goal;
        SearchSpace dense(std::size_t(ex.W) * ex.H);
        GrowingSearchSpace hash;
        const auto never = [] { return false; };
        const SearchResult a = astar(dense, {start}, ex, never);
        const SearchResult b = astar(hash, {start}, ex, never);
        ASSERT_EQ(a.outcome, b.outcome) << "seed " << seed;
        EXPECT_EQ(a.expanded, b.expanded) << "seed " << seed;
        EXPECT_EQ(a.goal, b.goal);
        EXPECT_EQ(a.closest, b.closest);
        std::size_t closed = 0;
        for (std::uint32_t s = 0; s < std::uint32_t(ex.W * ex.H); ++s)
        {
            ASSERT_EQ(dense.closed(s), hash.closed(s)) << "seed " << seed << " state " << s;
            if (!dense.seen(s)) continue;
            ASSERT_EQ(dense.g(s), hash.g(s)) << "seed " << seed << " state " << s;
            ASSERT_EQ(dense.parent(s), hash.parent(s)) << "seed " << seed << " state " << s;
            closed += dense.closed(s);
        }
        EXPECT_EQ(closed, a.expanded);
        if (a.outcome == SearchOutcome::Found) ++compared;
    }
    EXPECT_GE(compared, 6);
}

TEST(SearchCore, StateInternerFindsOnlyKeysItHasSeen)
{
    // find() adds nothing and answers as intern() would, also while a doubling is under way
    StateInterner s;
    std::mt19937_64 rng(3);
    std::vector<std::uint64_t> keys;
    for (int i = 0; i < 20000; ++i)
    {
        const std::uint64_t k = rng();
        EXPECT_EQ(s.find(k), StateInterner::kNone);
        EXPECT_EQ(s.size(), std::size_t(i));  // the miss added nothing
        EXPECT_EQ(s.intern(k), std::uint32_t(i));
        keys.push_back(k);
        const std::uint64_t old = keys[std::size_t(rng() % keys.size())];
        EXPECT_EQ(s.find(old), s.intern(old));
    }
    for (std::size_t i = 0; i < keys.size(); ++i) EXPECT_EQ(s.find(keys[i]), std::uint32_t(i));
    s.clear();
    EXPECT_EQ(s.find(keys[0]), StateInterner::kNone);
}
