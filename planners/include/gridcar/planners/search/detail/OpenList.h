#pragma once
/// @file OpenList.h
/// @brief Open lists of the search core: integer keys, a lazy-deletion heap and a decrease-key heap.
/// Internal to the search core (detail/): installed because the search loop's header includes
/// it, not part of gridcar's API.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace gridcar
{
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

}  // namespace gridcar
