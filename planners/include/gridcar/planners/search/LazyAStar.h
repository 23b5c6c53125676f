#pragma once
/// @file LazyAStar.h
/// @brief A* whose motions are checked when they are about to be used, not when they are
/// generated (lazy edge evaluation, as in Cohen, Phillips and Likhachev's Lazy Weighted A*).

#include "gridcar/planners/search/AStar.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace gridcar
{
/**
 * @brief A* over @p space whose successors are put on the open list unchecked: the motion
 * into a state is checked only when that (state, parent) entry comes off the list, and only if
 * the state is not closed yet. Where an expansion generates a dozen motions and a search closes
 * a fraction of the states it generates, most motions are never checked.
 *
 * The open list keeps one entry per (state, parent) motion, not one per state: if the best
 * motion into a state turns out blocked, the next best (from another parent) is still there.
 * So, with step costs that do not depend on the check (a motion costs what it costs if it is
 * free), the search closes the same states with the same g as astar() with checks at
 * generation and reopen = false: each state's first entry to pass its check is its best free
 * one (h is fixed per state, so a state's entries pop in order of g). Ties of f are broken as
 * astar() breaks them (higher g as a float, then lower state index), then by the lower exact g
 * and by generation order (astar() keeps the first motion of equal g): deterministic.
 *
 * The expander supplies what astar()'s does (heuristic(), isGoal(), optionally
 * analyticExpansion()), and instead of successors():
 * - `template <class Emit> void lazySuccessors(uint32_t s, Emit &&emit)`, calling
 *   `emit(next, stepCost, hNext, edge)` for every motion not known to be blocked, hNext a value
 *   or a callable giving heuristic(next) or a lower bound of it (the entry is then put back at
 *   its exact key when it comes off, after its check), @p edge (below 2^31) a number the
 *   expander reads the motion back from;
 * - `bool edgeFree(uint32_t parent, uint32_t next, uint32_t edge)`: the check;
 * - `void accept(uint32_t next, uint32_t parent, uint32_t edge)`: @p next is closed, reached
 *   by that motion.
 * States are recorded in @p space only when closed (g and parent). @p cancelled is polled by a
 * PollSchedule counting expansions and checks; @p progress counts expansions.
 */
template <class Space, class Expander, class Cancelled>
SearchResult lazyAstar(Space &space, const std::vector<std::uint32_t> &starts, Expander &ex, Cancelled &&cancelled,
                       std::atomic<std::uint64_t> *progress = nullptr, std::uint64_t pollMask = 255u)
{
    static_assert(!HasPriority<Expander>::value, "lazyAstar() orders by f = g + h");
    constexpr std::uint32_t kNone = SearchSpace::kNoParent;
    struct Entry
    {
        OpenEntry order;
        double g;
        std::uint32_t parent;
        std::uint32_t seq;   ///< pushes before this one (the motion's place in generation order)
        std::uint32_t edge;  ///< the expander's, | kChecked once checked free
    };
    static constexpr std::uint32_t kChecked = 1u << 31;
    struct After
    {
        bool operator()(const Entry &a, const Entry &b) const
        {
            if (openBefore(a.order, b.order)) return false;
            if (openBefore(b.order, a.order)) return true;
            // one state's entries of the same f: the least exact g (sums a rounding apart round
            // to one f), then the motion generated first (astar() keeps the first of equal g)
            if (a.g != b.g) return b.g < a.g;
            return b.seq < a.seq;
        }
    };
    std::vector<Entry> heap;
    std::uint32_t pushes = 0;
    auto push = [&heap](const Entry &e) {
        heap.push_back(e);
        std::push_heap(heap.begin(), heap.end(), After());
    };
    SearchResult res;
    space.reset();
    for (std::uint32_t s : starts)
    {
        if (space.seen(s)) continue;
        space.open(s, 0.0, kNone);
        push({OpenEntry(ex.heuristic(s), 0.0f, s), 0.0, kNone, pushes++, 0});
    }
    double bestH = std::numeric_limits<double>::infinity();
    PollSchedule poll(pollMask);
    std::uint64_t work = 0;  // expansions and checks, for the poll
    auto stopped = [&] {
        if (!poll.due(++work)) return false;
        poll.polled();
        return bool(cancelled());
    };
    while (!heap.empty())
    {
        std::pop_heap(heap.begin(), heap.end(), After());
        const Entry e = heap.back();
        heap.pop_back();
        const std::uint32_t s = e.order.s();
        if (space.closed(s)) continue;
        if (e.parent != kNone)
        {
            if (!(e.edge & kChecked))
            {
                if (stopped())
                {
                    res.outcome = SearchOutcome::Cancelled;
                    return res;
                }
                if (!ex.edgeFree(e.parent, s, e.edge)) continue;
            }
            // the key's h was a lower bound: back in the list at its exact f if that is higher
            const double hx = ex.heuristic(s);
            if (hx == std::numeric_limits<double>::infinity()) continue;
            if (e.order.f() < e.g + hx)
            {
                push({OpenEntry(e.g + hx, float(e.g), s), e.g, e.parent, e.seq, e.edge | kChecked});
                continue;
            }
            ex.accept(s, e.parent, e.edge & ~kChecked);
        }
        space.open(s, e.g, e.parent);
        space.close(s);
        ++res.expanded;
        if (progress) progress->store(res.expanded, std::memory_order_relaxed);
        if (const double c = closenessOf(ex, s, e.order.f() - e.g); c < bestH)
        {
            bestH = c;
            res.closest = s;
        }
        if (reachesGoal(ex, s))
        {
            res.outcome = SearchOutcome::Found;
            res.goal = s;
            return res;
        }
        if (stopped())
        {
            res.outcome = SearchOutcome::Cancelled;
            return res;
        }
        const double g = e.g;
        ex.lazySuccessors(s, [&](std::uint32_t n, double cost, auto &&hn, std::uint32_t edge) {
            if (space.closed(n)) return;
            const double ng = g + cost;
            double hv;
            if constexpr (std::is_invocable_v<decltype(hn)>)
                hv = hn();
            else
                hv = hn;
            push({OpenEntry(ng + hv, float(ng), n), ng, s, pushes++, edge});
            ++res.generated;
        });
    }
    res.outcome = SearchOutcome::Exhausted;
    return res;
}

}  // namespace gridcar
