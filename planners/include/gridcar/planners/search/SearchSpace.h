#pragma once
/// @file SearchSpace.h
/// @brief Per-search state storage of the search core: dense arrays (SearchSpace) or a hash table (HashSearchSpace).

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>
#include <stdexcept>
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

/// True if the search space keeps heap positions (SearchSpace; not HashSearchSpace).
template <class S, class = void>
struct HasHeapPositions : std::false_type
{
};
template <class S>
struct HasHeapPositions<S, std::void_t<decltype(std::declval<S &>().heapPositions())>> : std::true_type
{
};

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
