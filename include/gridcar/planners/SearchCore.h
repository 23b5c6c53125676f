#pragma once
/// @file SearchCore.h
/// @brief The one A* search loop shared by every grid planner.

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace gridcar
{
/// Dense per-state storage (g, parent, open/closed) over states 0..n-1, reused between
/// searches without clearing: a state's entry is valid only if its stamp equals the current
/// search's. One 16-byte record per state (stamp, parent, g together: one cache line touch per
/// successor instead of three), allocated once with calloc, so pages of states a search never
/// touches are never committed.
class SearchSpace
{
public:
    explicit SearchSpace(std::size_t n);
    ~SearchSpace();
    SearchSpace(const SearchSpace &) = delete;
    SearchSpace &operator=(const SearchSpace &) = delete;

    std::size_t size() const { return n_; }
    /// Starts a new search: every state becomes unseen (O(1) except on stamp wrap-around).
    void reset();

    bool seen(std::uint32_t s) const { return (rec_[s].stamp >> 1) == epoch_; }
    bool closed(std::uint32_t s) const { return rec_[s].stamp == ((epoch_ << 1) | 1u); }
    double g(std::uint32_t s) const { return seen(s) ? rec_[s].g : std::numeric_limits<double>::infinity(); }
    std::uint32_t parent(std::uint32_t s) const { return rec_[s].parent; }
    void open(std::uint32_t s, double g, std::uint32_t parent)
    {
        Record &r = rec_[s];
        r.stamp = epoch_ << 1;
        r.parent = parent;
        r.g = g;
    }
    void close(std::uint32_t s) { rec_[s].stamp = (epoch_ << 1) | 1u; }
    /// Where an open state's entry sits in the open list (IndexedOpenList); meaningless for
    /// states that are not open. A separate array, allocated on first use.
    std::uint32_t *heapPositions()
    {
        if (!pos_)
        {
            pos_ = static_cast<std::uint32_t *>(std::calloc(n_, sizeof(std::uint32_t)));
            if (!pos_) throw std::bad_alloc();
        }
        return pos_;
    }

    static constexpr std::uint32_t kNoParent = std::numeric_limits<std::uint32_t>::max();

private:
    std::size_t n_;
    std::uint32_t epoch_{0};
    std::uint32_t *pos_{nullptr};
    struct Record
    {
        std::uint32_t stamp;
        std::uint32_t parent;
        double g;
    };
    Record *rec_{nullptr};
};

/**
 * @brief The same interface as SearchSpace over a hash table (open addressing, linear probing),
 * for lattices too large for dense arrays (e.g. improved A*'s cell x heading x straight-run
 * states): memory grows with the states a search touches, not with the lattice.
 */
class HashSearchSpace
{
public:
    HashSearchSpace() { rehash(1u << 12); }
    /// Starts a new search (O(table size)).
    void reset()
    {
        if (used_ == 0) return;
        for (Slot &sl : slots_) sl.key = kEmpty;
        used_ = 0;
    }
    bool seen(std::uint32_t s) const { return find(s) != nullptr; }
    bool closed(std::uint32_t s) const
    {
        const Slot *sl = find(s);
        return sl && sl->closed;
    }
    double g(std::uint32_t s) const
    {
        const Slot *sl = find(s);
        return sl ? sl->g : std::numeric_limits<double>::infinity();
    }
    std::uint32_t parent(std::uint32_t s) const
    {
        const Slot *sl = find(s);
        return sl ? sl->parent : SearchSpace::kNoParent;
    }
    void open(std::uint32_t s, double g, std::uint32_t parent)
    {
        Slot &sl = insert(s);
        sl.g = g;
        sl.parent = parent;
        sl.closed = 0;
    }
    void close(std::uint32_t s) { insert(s).closed = 1; }
    /// Number of states the current search has touched.
    std::size_t touched() const { return used_; }
    /// Calls fn(state, closed) for every touched state (in table order).
    template <class Fn>
    void forEach(Fn &&fn) const
    {
        for (const Slot &sl : slots_)
            if (sl.key != kEmpty) fn(sl.key, sl.closed != 0);
    }

private:
    static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
    struct Slot
    {
        std::uint32_t key{kEmpty};
        std::uint32_t parent{0};
        double g{0.0};
        std::uint8_t closed{0};
    };
    std::size_t home(std::uint32_t s) const { return (std::uint64_t(s) * 0x9E3779B97F4A7C15ull) >> shift_; }
    const Slot *find(std::uint32_t s) const
    {
        for (std::size_t i = home(s);; i = (i + 1) & mask_)
        {
            const Slot &sl = slots_[i];
            if (sl.key == s) return &sl;
            if (sl.key == kEmpty) return nullptr;
        }
    }
    Slot &insert(std::uint32_t s)
    {
        if (2 * (used_ + 1) > slots_.size()) rehash(slots_.size() * 2);
        for (std::size_t i = home(s);; i = (i + 1) & mask_)
        {
            Slot &sl = slots_[i];
            if (sl.key == s) return sl;
            if (sl.key == kEmpty)
            {
                sl.key = s;
                ++used_;
                return sl;
            }
        }
    }
    void rehash(std::size_t n)
    {
        std::vector<Slot> old;
        old.swap(slots_);
        slots_.assign(n, Slot());
        mask_ = n - 1;
        shift_ = 64;
        for (std::size_t k = n; k > 1; k >>= 1) --shift_;
        used_ = 0;
        for (const Slot &sl : old)
            if (sl.key != kEmpty)
            {
                Slot &d = insert(sl.key);
                d = sl;
            }
    }
    std::vector<Slot> slots_;
    std::size_t mask_{0};
    int shift_{64};
    std::size_t used_{0};
};

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
    std::uint32_t closest{SearchSpace::kNoParent};  ///< expanded state of least heuristic
    std::uint64_t expanded{0};
    std::uint64_t generated{0};
};

/// Maps a double to an unsigned integer of the same order (negative numbers included).
inline std::uint64_t orderedBits(double x)
{
    std::uint64_t u;
    std::memcpy(&u, &x, sizeof u);
    return (u >> 63) ? ~u : (u | (std::uint64_t(1) << 63));
}
/// Inverse of orderedBits(double).
inline double fromOrderedBits(std::uint64_t u)
{
    u = (u >> 63) ? (u & ~(std::uint64_t(1) << 63)) : ~u;
    double x;
    std::memcpy(&x, &u, sizeof x);
    return x;
}
/// Maps a float to an unsigned integer of the same order.
inline std::uint32_t orderedBits(float x)
{
    std::uint32_t u;
    std::memcpy(&u, &x, sizeof u);
    return (u >> 31) ? ~u : (u | (std::uint32_t(1) << 31));
}

/**
 * @brief Open-list entry: f exact; g (as float) only breaks ties, the exact g is in the
 * SearchSpace. Stored as two integers whose lexicographic order is the open-list order (lower
 * f, then higher g, then lower state index), so a heap comparison is two integer compares
 * without branches on floating-point flags.
 */
struct OpenEntry
{
    std::uint64_t key;  ///< orderedBits(f)
    std::uint64_t tie;  ///< (~orderedBits(float g)) << 32 | state
    OpenEntry() = default;
    OpenEntry(double f, float g, std::uint32_t s)
      : key(orderedBits(f)), tie((std::uint64_t(~orderedBits(g)) << 32) | s)
    {
    }
    double f() const { return fromOrderedBits(key); }
    std::uint32_t s() const { return std::uint32_t(tie); }
};

/// True if @p a must come out of the open list before @p b: lower f, then higher g, then
/// lower state index (deterministic).
inline bool openBefore(const OpenEntry &a, const OpenEntry &b)
{
    return a.key < b.key || (a.key == b.key && a.tie < b.tie);
}

/// The lazy-deletion open list: a binary min-heap of OpenEntry (std::push_heap /
/// std::pop_heap) that may hold several entries of a state; astar() skips the stale ones. A
/// 4-ary heap was tried and cost about 20 % more instructions per expansion on the Moving AI
/// mazes; a second small heap for the f plateau of the last pop gave +13 % on Moving AI before
/// IndexedOpenList existed, and nothing measurable for improved-astar, its only user since,
/// so it was dropped.
class OpenList
{
public:
    bool empty() const { return h_.empty(); }
    void push(const OpenEntry &e)
    {
        h_.push_back(e);
        std::push_heap(h_.begin(), h_.end(), After());
    }
    OpenEntry pop()
    {
        std::pop_heap(h_.begin(), h_.end(), After());
        const OpenEntry e = h_.back();
        h_.pop_back();
        return e;
    }

private:
    struct After
    {
        bool operator()(const OpenEntry &a, const OpenEntry &b) const { return openBefore(b, a); }
    };
    std::vector<OpenEntry> h_;
};

/**
 * @brief Binary min-heap of OpenEntry with decrease-key: at most one entry per state, whose
 * position is kept in an array indexed by state (SearchSpace::heapPositions()).
 *
 * Used by astar() when the priority is f = g + h: an improved g then always lowers the entry's
 * key, so decrease() only sifts up, and the pop order is exactly that of the lazy-deletion
 * OpenList, without its stale entries (on the Moving AI maps about half of all lazy pops were
 * stale: a cell is often reached diagonally first and then more cheaply straight).
 * pop() moves the hole down to a leaf along the lesser children, then sifts the last entry up
 * (one compare per level on the way down).
 */
class IndexedOpenList
{
public:
    explicit IndexedOpenList(std::uint32_t *positions) : pos_(positions) {}
    bool empty() const { return h_.empty(); }
    void push(const OpenEntry &e)
    {
        h_.emplace_back();
        siftUp(h_.size() - 1, e);
    }
    /// Lowers the key of @p e's state, which must be in the list with a key not below e's.
    void decrease(const OpenEntry &e) { siftUp(pos_[e.s()], e); }
    OpenEntry pop()
    {
        const OpenEntry top = h_.front();
        const OpenEntry last = h_.back();
        h_.pop_back();
        const std::size_t n = h_.size();
        if (n == 0) return top;
        std::size_t i = 0;
        for (std::size_t c = 1; c < n; c = 2 * i + 1)
        {
            if (c + 1 < n && openBefore(h_[c + 1], h_[c])) ++c;
            place(i, h_[c]);
            i = c;
        }
        siftUp(i, last);
        return top;
    }

private:
    void place(std::size_t i, const OpenEntry &e)
    {
        h_[i] = e;
        pos_[e.s()] = std::uint32_t(i);
    }
    void siftUp(std::size_t i, const OpenEntry &e)
    {
        while (i > 0)
        {
            const std::size_t p = (i - 1) / 2;
            if (!openBefore(e, h_[p])) break;
            place(i, h_[p]);
            i = p;
        }
        place(i, e);
    }
    std::uint32_t *pos_;
    std::vector<OpenEntry> h_;
};

/// True if the search space keeps heap positions (SearchSpace; not HashSearchSpace).
template <class S, class = void>
struct HasHeapPositions : std::false_type
{
};
template <class S>
struct HasHeapPositions<S, std::void_t<decltype(std::declval<S &>().heapPositions())>> : std::true_type
{
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
 * An expander may also define `double priority(double g, double h, uint32_t s) const`: the
 * open list is then ordered by it instead of f = g + h (paper I's f = g' + h (1 + o) + s); the
 * closest state for an approximate solution is still the one of least heuristic().
 * @p reopen: with an inconsistent heuristic or priority, a closed state reached again with a
 * cheaper g (by more than kReopenTolerance relative: not rounding noise) is reopened (default)
 * or left closed (a best-first search that keeps its first parent).
 *
 * Works on a SearchSpace (dense arrays) or a HashSearchSpace.
 *
 * Open list: with f = g + h on a SearchSpace, IndexedOpenList (one entry per state,
 * decrease-key); otherwise OpenList (a binary heap with lazy deletion: stale entries are
 * skipped when popped). Both pop in the same order. Tie-breaking is deterministic: lower f first, then higher g (deeper states, fewer
 * re-expansions on plateaus), then lower state index. @p cancelled is polled every 256
 * expansions. With a consistent heuristic each state is expanded at most once; with an
 * inconsistent one (paper I's mode) a closed state is reopened when a cheaper g reaches it.
 */
/// Relative improvement of g below which astar() does not reopen a closed state.
constexpr double kReopenTolerance = 1e-9;

template <class Space, class Expander, class Cancelled>
SearchResult astar(Space &space, const std::vector<std::uint32_t> &starts, Expander &ex, Cancelled &&cancelled,
                   std::uint64_t *progress = nullptr, bool reopen = true)
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
        if (progress) *progress = res.expanded;
        double h;
        if constexpr (custom)
            h = ex.heuristic(es);
        else
            h = e.f() - g;
        if (h < bestH)
        {
            bestH = h;
            res.closest = es;
        }
        if (ex.isGoal(es))
        {
            res.outcome = SearchOutcome::Found;
            res.goal = es;
            return res;
        }
        if ((res.expanded & 255u) == 0 && cancelled())
        {
            res.outcome = SearchOutcome::Cancelled;
            return res;
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

inline SearchSpace::SearchSpace(std::size_t n) : n_(n)
{
    if (n == 0 || n >= std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("search space size must be in 1..2^32-2 states");
    rec_ = static_cast<Record *>(std::calloc(n, sizeof(Record)));
    if (!rec_) throw std::bad_alloc();
}

inline SearchSpace::~SearchSpace()
{
    std::free(rec_);
    std::free(pos_);
}

inline void SearchSpace::reset()
{
    ++epoch_;
    if (epoch_ >= (1u << 31))  // stamps would wrap: clear them once
    {
        for (std::size_t i = 0; i < n_; ++i) rec_[i].stamp = 0;
        epoch_ = 1;
    }
}

}  // namespace gridcar
