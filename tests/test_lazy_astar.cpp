// lazyAstar(): motions checked when they come off the open list, keys from a lower bound of h.
// Against astar() with the checks at generation (reopen = false) on random grids whose edges,
// not cells, are blocked: the same states closed in the same order with the same g and parent.
#include "gridcar/planners/search/LazyAStar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace gridcar;

namespace
{
/// 8-connected grid, octile costs; an edge is blocked by a hash of its two ends (both ways).
struct EdgeGrid
{
    int W{50}, H{40};
    std::uint32_t goal{0};
    unsigned salt{0};
    int blockedPercent{30};
    bool cutGoal{false};  ///< every motion into the goal blocked
    double hScale{1.0};  ///< lazy keys: h x this (a lower bound for <= 1)
    mutable long checks{0};
    mutable long failed{0};
    std::vector<std::uint32_t> closedOrder;

    double octile(std::uint32_t s) const
    {
        const int dx = std::abs(int(goal % W) - int(s % W)), dy = std::abs(int(goal / W) - int(s / W));
        return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
    }
    bool blocked(std::uint32_t a, std::uint32_t b) const
    {
        if (cutGoal && (a == goal || b == goal)) return true;
        std::uint64_t k = (std::uint64_t(std::min(a, b)) << 32) ^ std::max(a, b) ^ (std::uint64_t(salt) << 20);
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdULL;
        k ^= k >> 33;
        return int(k % 100) < blockedPercent;
    }
    double heuristic(std::uint32_t s) const { return octile(s); }
    bool isGoal(std::uint32_t s)
    {
        closedOrder.push_back(s);
        return s == goal;
    }
    template <class Fn>
    void neighbours(std::uint32_t s, Fn &&fn) const
    {
        const int c = int(s % W), r = int(s / W);
        for (int dc = -1; dc <= 1; ++dc)
            for (int dr = -1; dr <= 1; ++dr)
            {
                if ((dc == 0 && dr == 0) || c + dc < 0 || r + dr < 0 || c + dc >= W || r + dr >= H) continue;
                fn(std::uint32_t((r + dr) * W + c + dc), (dc != 0 && dr != 0) ? std::sqrt(2.0) : 1.0,
                   std::uint32_t((dc + 1) * 3 + dr + 1));
            }
    }
    // astar(): checked at generation
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        neighbours(s, [&](std::uint32_t n, double cost, std::uint32_t) {
            ++checks;
            if (!blocked(s, n)) emit(n, cost, octile(n));
        });
    }
    // lazyAstar(): unchecked, keys from a lower bound
    template <class Emit>
    void lazySuccessors(std::uint32_t s, Emit &&emit) const
    {
        neighbours(s, [&](std::uint32_t n, double cost, std::uint32_t edge) { emit(n, cost, hScale * octile(n), edge); });
    }
    bool edgeFree(std::uint32_t parent, std::uint32_t next, std::uint32_t) const
    {
        ++checks;
        const bool ok = !blocked(parent, next);
        failed += !ok;
        return ok;
    }
    void accept(std::uint32_t, std::uint32_t, std::uint32_t) {}
};
}  // namespace

TEST(LazyAStar, ClosesWhatTheSearchWithChecksAtGenerationCloses)
{
    long eagerChecks = 0, lazyChecks = 0, failures = 0;
    int found = 0, exhausted = 0;
    for (unsigned seed = 1; seed <= 24; ++seed)
    {
        std::mt19937 rng(seed);
        EdgeGrid base;
        base.salt = seed;
        base.blockedPercent = 20 + int(seed % 4) * 10;  // up to 50 %
        base.goal = rng() % std::uint32_t(base.W * base.H);
        base.cutGoal = seed % 8 == 0;
        base.hScale = (seed % 3 == 0) ? 1.0 : (seed % 3 == 1 ? 0.5 : 0.0);
        const std::uint32_t start = rng() % std::uint32_t(base.W * base.H);
        const auto never = [] { return false; };
        EdgeGrid eager = base, lazy = base;
        GrowingSearchSpace se, sl;
        const SearchResult a = astar(se, {start}, eager, never, nullptr, /*reopen=*/false);
        const SearchResult b = lazyAstar(sl, {start}, lazy, never);
        ASSERT_EQ(a.outcome, b.outcome) << "seed " << seed;
        EXPECT_EQ(a.expanded, b.expanded) << "seed " << seed;
        EXPECT_EQ(a.goal, b.goal);
        EXPECT_EQ(a.closest, b.closest);
        ASSERT_EQ(eager.closedOrder, lazy.closedOrder) << "seed " << seed;
        for (std::uint32_t s : eager.closedOrder)
        {
            ASSERT_TRUE(sl.closed(s));
            ASSERT_EQ(se.g(s), sl.g(s)) << "seed " << seed << " state " << s;
            ASSERT_EQ(se.parent(s), sl.parent(s)) << "seed " << seed << " state " << s;
            const std::uint32_t p = sl.parent(s);
            if (p == SearchSpace::kNoParent) continue;
            ASSERT_FALSE(base.blocked(p, s));
            ASSERT_TRUE(sl.closed(p));
        }
        eagerChecks += eager.checks;
        lazyChecks += lazy.checks;
        failures += lazy.failed;
        found += a.outcome == SearchOutcome::Found;
        exhausted += a.outcome == SearchOutcome::Exhausted;
    }
    EXPECT_GE(found, 10);
    EXPECT_GE(exhausted, 2);
    EXPECT_GT(failures, 100);  // blocked best motions met, the next best taken
    EXPECT_LT(lazyChecks, eagerChecks);
    std::printf("lazy A*: %ld motion checks against %ld checked at generation\n", lazyChecks, eagerChecks);
}

TEST(LazyAStar, HonoursTheTerminationCondition)
{
    EdgeGrid ex;
    ex.W = 200;
    ex.H = 200;
    ex.goal = 199 * 200 + 199;
    ex.blockedPercent = 10;
    int polls = 0;
    GrowingSearchSpace space;
    const SearchResult r = lazyAstar(space, {0}, ex, [&] { return ++polls > 50; }, nullptr, 0u);
    EXPECT_EQ(r.outcome, SearchOutcome::Cancelled);
    EXPECT_EQ(polls, 51);
    EXPECT_LT(r.expanded, 51u);
}
