#pragma once
/// @file AStar.h
/// @brief The one A* search loop shared by every grid planner.

#include "gridcar/planners/search/detail/OpenList.h"
#include "gridcar/planners/search/detail/PollSchedule.h"
#include "gridcar/planners/search/SearchSpace.h"

#include <atomic>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace gridcar
{
/// True if the expander defines `double priority(double g, double h, std::uint32_t s) const`.
template <class E, class = void>
struct HasPriority : std::false_type
{
};
template <class E>
struct HasPriority<E, std::void_t<decltype(std::declval<const E &>().priority(0.0, 0.0, std::uint32_t(0)))>>
  : std::true_type
{
};

/// True if the expander defines `double closeness(std::uint32_t s) const`: how near a state
/// is to the goal, for the approximate answer (the least is kept).
template <class E, class = void>
struct HasCloseness : std::false_type
{
};
template <class E>
struct HasCloseness<E, std::void_t<decltype(std::declval<const E &>().closeness(std::uint32_t(0)))>> : std::true_type
{
};

/// The order of the approximate answer: the expander's closeness() of @p s, else its h.
template <class E>
double closenessOf(const E &ex, std::uint32_t s, double h)
{
    if constexpr (HasCloseness<E>::value)
        return ex.closeness(s);
    else
    {
        (void)ex;
        (void)s;
        return h;
    }
}

/// True if the expander has an analytic expansion step (`bool analyticExpansion(uint32_t)`).
template <class E, class = void>
struct HasAnalyticExpansion : std::false_type
{
};
template <class E>
struct HasAnalyticExpansion<E, std::void_t<decltype(std::declval<E &>().analyticExpansion(std::uint32_t(0)))>>
  : std::true_type
{
};

/// The goal test of an expanded state: the expander's isGoal(), then its analytic expansion
/// step if it has one (shared by astar() and lazyAstar()).
template <class Expander>
bool reachesGoal(Expander &ex, std::uint32_t s)
{
    if (ex.isGoal(s)) return true;
    if constexpr (HasAnalyticExpansion<Expander>::value)
        return ex.analyticExpansion(s);
    else
        return false;
}

/// How a search ended.
enum class SearchOutcome
{
    Found,      ///< a goal state was expanded
    Exhausted,  ///< the open list ran empty: no goal is reachable
    Cancelled   ///< the termination condition fired
};

/// Counters and the result state of one search.
struct SearchResult
{
    SearchOutcome outcome{SearchOutcome::Exhausted};
    std::uint32_t goal{SearchSpace::kNoParent};     ///< the goal state reached (Found)
    /// The expanded state nearest the goal: of least closeness() where the expander defines
    /// it, else of least heuristic.
    std::uint32_t closest{SearchSpace::kNoParent};
    std::uint64_t expanded{0};
    std::uint64_t generated{0};
};

/**
 * @brief A* over the states of @p space.
 *
 * The expander supplies the problem:
 * - `double heuristic(uint32_t s) const` (admissible for an optimal search; 0 gives Dijkstra),
 * - `bool isGoal(uint32_t s)` (tested when a state is expanded, so any goal region works),
 * - `template <class Emit> void successors(uint32_t s, Emit &&emit)` calling
 *   `emit(uint32_t next, double stepCost, hNext)` for every valid successor, with hNext =
 *   heuristic(next) or a callable returning it (then evaluated only when the successor's g
 *   improves; the expander knows the successor's coordinates, so it computes h without
 *   decoding the state index again).
 *
 * An expander may also define `bool analyticExpansion(uint32_t s)`: the analytic expansion
 * step, called after each popped state that is not a goal (before its successors). It tries
 * to join the state to the goal by a curve (the car lattice: a Dubins curve, its footprint
 * checked); returning true ends the search Found at @p s, the expander holding the curve.
 *
 * An expander may also define `double priority(double g, double h, uint32_t s) const`: the
 * open list is then ordered by it instead of f = g + h (paper I's f = g' + h (1 + o) + s).
 * The closest state for an approximate solution is the one of least `closeness(s)` where the
 * expander defines it (the grid family: nearest the goal's position), else of least heuristic.
 * @p reopen: with an inconsistent heuristic or priority, a closed state reached again with a
 * cheaper g (by more than kReopenTolerance relative: not rounding noise) is reopened (default)
 * or left closed (a best-first search that keeps its first parent).
 *
 * Works on a SearchSpace (dense arrays) or a GrowingSearchSpace (chunks by dense state id).
 *
 * Open list: with f = g + h on a SearchSpace, IndexedOpenList (one entry per state,
 * decrease-key); otherwise OpenList (a binary heap with lazy deletion: stale entries are
 * skipped when popped). Both pop in the same order. Tie-breaking is deterministic: lower f first, then higher g (deeper states, fewer
 * re-expansions on plateaus), then lower state index. @p cancelled is polled whenever the
 * expansion count & the mask of a PollSchedule is 0: every expansion at first, every 256 by
 * default (@p pollMask) once polls come fast, fewer again while they come slowly (the car lattice, whose
 * expansions check whole primitives, polls every 16). With a consistent heuristic each state is expanded at most once; with an
 * inconsistent one (paper I's mode) a closed state is reopened when a cheaper g reaches it.
 */
/// Relative improvement of g below which astar() does not reopen a closed state.
constexpr double kReopenTolerance = 1e-9;

template <class Space, class Expander, class Cancelled>
SearchResult astar(Space &space, const std::vector<std::uint32_t> &starts, Expander &ex, Cancelled &&cancelled,
                   std::atomic<std::uint64_t> *progress = nullptr, bool reopen = true, std::uint64_t pollMask = 255u)
{
    constexpr bool custom = HasPriority<Expander>::value;
    auto priorityOf = [&](double g, double h, std::uint32_t s) {
        if constexpr (custom)
            return ex.priority(g, h, s);
        else
        {
            (void)s;
            return g + h;
        }
    };
    // f = g + h on dense arrays: decrease-key heap; otherwise (a custom priority may rise when g
    // falls, or a hash space without positions) lazy deletion
    constexpr bool indexed = !custom && HasHeapPositions<Space>::value;
    SearchResult res;
    space.reset();
    auto heap = [&] {
        if constexpr (indexed)
            return IndexedOpenList(space.heapPositions());
        else
            return OpenList();
    }();
    for (std::uint32_t s : starts)
    {
        if (space.seen(s)) continue;
        space.open(s, 0.0, SearchSpace::kNoParent);
        heap.push({priorityOf(0.0, ex.heuristic(s), s), 0.0f, s});
    }
    double bestH = std::numeric_limits<double>::infinity();
    PollSchedule poll(pollMask);
    while (!heap.empty())
    {
        const OpenEntry e = heap.pop();
        // Stale entries (lazy deletion only): h is fixed per state, so of a state's entries the
        // one with the least g has the least f and pops first; the state is closed then, and
        // later (stale) entries of it are skipped here. A reopened state (cheaper g found) pops
        // its new entry first too.
        const std::uint32_t es = e.s();
        if (space.closed(es)) continue;
        const double g = space.g(es);
        space.close(es);
        ++res.expanded;
        if (progress) progress->store(res.expanded, std::memory_order_relaxed);  // read by OMPL's progress thread
        double h;
        if constexpr (custom)
            h = ex.heuristic(es);
        else
            h = e.f() - g;
        if (const double c = closenessOf(ex, es, h); c < bestH)
        {
            bestH = c;
            res.closest = es;
        }
        if (reachesGoal(ex, es))
        {
            res.outcome = SearchOutcome::Found;
            res.goal = es;
            return res;
        }
        if (poll.due(res.expanded))
        {
            poll.polled();
            if (cancelled())
            {
                res.outcome = SearchOutcome::Cancelled;
                return res;
            }
        }
        ex.successors(es, [&](std::uint32_t n, double cost, auto &&hn) {
            const double ng = g + cost;
            const double gn = space.g(n);  // +inf if not seen in this search
            if (!(ng < gn)) return;
            // a closed state is reopened only for a real improvement: equal-cost paths summed in
            // a different order differ in the last bits, and that noise must not re-expand it
            const bool wasClosed = space.closed(n);
            if (wasClosed && (!reopen || ng >= gn - kReopenTolerance * gn)) return;
            space.open(n, ng, es);
            double h;
            if constexpr (std::is_invocable_v<decltype(hn)>)
                h = hn();  // evaluated only for successors whose g improved
            else
                h = hn;
            const OpenEntry entry(priorityOf(ng, h, n), float(ng), n);
            if constexpr (indexed)
            {
                if (gn < std::numeric_limits<double>::infinity() && !wasClosed)
                    heap.decrease(entry);  // in the list: same h, lower g, a lower key
                else
                    heap.push(entry);
            }
            else
                heap.push(entry);
            ++res.generated;
        });
    }
    res.outcome = SearchOutcome::Exhausted;
    return res;
}

}  // namespace gridcar
