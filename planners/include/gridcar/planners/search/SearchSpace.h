#pragma once
/// @file SearchSpace.h
/// @brief Per-search state storage of the search core: dense arrays over every state (SearchSpace)
/// or chunked arrays over the states a search discovers (GrowingSearchSpace).

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
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
 * @brief The same interface as SearchSpace over states numbered densely as a search discovers
 * them (StateInterner's ids), for lattices too large for arrays over every state (improved
 * A*'s cell x heading x straight-run states, the car lattice): records in chunks of 2^16
 * allocated when a state of the chunk is first opened, so memory grows with the states a search
 * touches, growth never copies (no pause the termination condition cannot interrupt), and
 * reset() is O(1) (stamps, as SearchSpace).
 */
class GrowingSearchSpace
{
public:
    GrowingSearchSpace() = default;
    GrowingSearchSpace(const GrowingSearchSpace &) = delete;
    GrowingSearchSpace &operator=(const GrowingSearchSpace &) = delete;

    /// Starts a new search: every state becomes unseen.
    void reset()
    {
        ++epoch_;
        end_ = 0;
        if (epoch_ >= (1u << 31))  // stamps would wrap: clear them once
        {
            for (auto &c : chunks_)
                if (c)
                    for (std::size_t i = 0; i < kChunk; ++i) c[i].stamp = 0;
            epoch_ = 1;
        }
    }
    bool seen(std::uint32_t s) const
    {
        const Record *r = find(s);
        return r && (r->stamp >> 1) == epoch_;
    }
    bool closed(std::uint32_t s) const
    {
        const Record *r = find(s);
        return r && r->stamp == ((epoch_ << 1) | 1u);
    }
    double g(std::uint32_t s) const { return seen(s) ? find(s)->g : std::numeric_limits<double>::infinity(); }
    std::uint32_t parent(std::uint32_t s) const { return seen(s) ? find(s)->parent : SearchSpace::kNoParent; }
    void open(std::uint32_t s, double g, std::uint32_t parent)
    {
        Record &r = slot(s);
        r.stamp = epoch_ << 1;
        r.parent = parent;
        r.g = g;
    }
    void close(std::uint32_t s) { slot(s).stamp = (epoch_ << 1) | 1u; }
    /// Calls fn(state, closed) for every state the current search has seen (in state order).
    template <class Fn>
    void forEach(Fn &&fn) const
    {
        for (std::uint32_t s = 0; s < end_; ++s)
            if (seen(s)) fn(s, closed(s));
    }

private:
    static constexpr std::size_t kChunkBits = 16, kChunk = std::size_t(1) << kChunkBits;
    struct Record
    {
        std::uint32_t stamp;
        std::uint32_t parent;
        double g;
    };
    struct Free
    {
        void operator()(Record *p) const { std::free(p); }
    };
    const Record *find(std::uint32_t s) const
    {
        const std::size_t c = s >> kChunkBits;
        return c < chunks_.size() && chunks_[c] ? &chunks_[c][s & (kChunk - 1)] : nullptr;
    }
    Record &slot(std::uint32_t s)
    {
        const std::size_t c = s >> kChunkBits;
        if (c >= chunks_.size()) chunks_.resize(c + 1);
        if (!chunks_[c])
        {
            chunks_[c].reset(static_cast<Record *>(std::calloc(kChunk, sizeof(Record))));
            if (!chunks_[c]) throw std::bad_alloc();
        }
        if (s >= end_) end_ = s + 1;
        return chunks_[c][s & (kChunk - 1)];
    }
    std::vector<std::unique_ptr<Record[], Free>> chunks_;
    std::uint32_t epoch_{1};
    std::uint32_t end_{0};  ///< one past the highest state opened in this search
};

/// True if the search space keeps heap positions (SearchSpace; not GrowingSearchSpace).
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
