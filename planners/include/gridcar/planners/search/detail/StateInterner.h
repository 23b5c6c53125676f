#pragma once
/// @file StateInterner.h
/// @brief Dense ids for the sparse 64-bit keys of a lattice's states, in the order a search
/// discovers them: the one hash of a state (key -> id); its search record then sits in a
/// GrowingSearchSpace by id.
/// Internal to the search core (detail/): installed because the search loop's header includes
/// it, not part of gridcar's API.

#include <cstdint>
#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gridcar
{
/**
 * @brief Key -> dense id map (open addressing, linear probing) whose growth is incremental: a
 * doubling moves the old table's entries a few at a time on the following insertions, so that
 * no single insertion takes longer than a few probes (a search polls its termination condition
 * between expansions; a table of 10 M states rehashed at once held it back half a second).
 * Keys are kept in chunks by id (growth never copies them).
 */
class StateInterner
{
public:
    StateInterner() { clear(); }

    /// Forgets every key (ids restart at 0): the tables are dropped, the key chunks kept.
    void clear()
    {
        size_ = 0;
        old_ = Table();
        table_ = Table(kInitial);
        migrated_ = 0;
    }

    /// The id of @p key, a new one (the next integer) the first time it is seen.
    std::uint32_t intern(std::uint64_t key)
    {
        migrateSome();
        if (const std::uint32_t *slot = findIn(table_, key)) return *slot - 1;
        if (old_.n)
            if (const std::uint32_t *slot = findIn(old_, key)) return *slot - 1;
        if (size_ >= std::size_t(kLimit)) throw std::length_error("more than 2^32 - 3 lattice states");
        if (2 * (size_ + 1) > table_.n) grow();
        const auto id = std::uint32_t(size_);
        storeKey(id, key);
        ++size_;
        place(table_, id);
        return id;
    }

    /// The id of @p key if it was seen, else kNone (nothing is added).
    std::uint32_t find(std::uint64_t key) const
    {
        if (const std::uint32_t *slot = findIn(table_, key)) return *slot - 1;
        if (old_.n)
            if (const std::uint32_t *slot = findIn(old_, key)) return *slot - 1;
        return kNone;
    }
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    std::uint64_t key(std::uint32_t id) const { return keys_[id >> kChunkBits][id & (kChunk - 1)]; }
    std::size_t size() const { return size_; }

private:
    // a slot holds id + 1; 0 is empty (so that a new table is calloc's zero pages, committed
    // only as they are written: no pause to fill it), kMoved an old slot already moved over
    static constexpr std::uint32_t kMoved = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::uint32_t kLimit = kMoved - 2;
    static constexpr std::size_t kInitial = 1u << 12, kChunkBits = 16, kChunk = std::size_t(1) << kChunkBits;
    static constexpr std::size_t kMovesPerInsert = 16;

    struct Table
    {
        Table() = default;
        explicit Table(std::size_t size) : p(static_cast<std::uint32_t *>(std::calloc(size, sizeof(std::uint32_t)))), n(size)
        {
            if (!p) throw std::bad_alloc();
        }
        Table(Table &&o) noexcept : p(o.p), n(o.n) { o.p = nullptr, o.n = 0; }
        Table &operator=(Table &&o) noexcept
        {
            std::swap(p, o.p);
            std::swap(n, o.n);
            return *this;
        }
        ~Table() { std::free(p); }
        std::uint32_t *p{nullptr};
        std::size_t n{0};
    };

    static std::size_t home(std::uint64_t key, std::size_t n) { return std::size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & (n - 1); }

    const std::uint32_t *findIn(const Table &t, std::uint64_t k) const
    {
        for (std::size_t i = home(k, t.n);; i = (i + 1) & (t.n - 1))
        {
            const std::uint32_t v = t.p[i];
            if (v == 0) return nullptr;
            if (v != kMoved && key(v - 1) == k) return &t.p[i];
        }
    }
    void place(Table &t, std::uint32_t id)
    {
        for (std::size_t i = home(key(id), t.n);; i = (i + 1) & (t.n - 1))
            if (t.p[i] == 0)
            {
                t.p[i] = id + 1;
                return;
            }
    }
    void storeKey(std::uint32_t id, std::uint64_t k)
    {
        const std::size_t c = id >> kChunkBits;
        if (c >= keys_.size()) keys_.emplace_back(new std::uint64_t[kChunk]);
        keys_[c][id & (kChunk - 1)] = k;
    }
    /// Doubles the table; the old one's entries move over on the next insertions.
    void grow()
    {
        while (old_.n) migrateSome();  // a doubling still under way (not reached: 16 moves an insertion finish it first)
        Table bigger(table_.n * 2);
        old_ = std::move(table_);
        table_ = std::move(bigger);
        migrated_ = 0;
    }
    void migrateSome()
    {
        if (!old_.n) return;
        const std::size_t end = std::min(old_.n, migrated_ + kMovesPerInsert);
        for (; migrated_ < end; ++migrated_)
        {
            std::uint32_t &v = old_.p[migrated_];
            if (v == 0 || v == kMoved) continue;
            place(table_, v - 1);
            v = kMoved;
        }
        if (migrated_ == old_.n) old_ = Table();
    }

    Table table_, old_;
    std::size_t migrated_{0}, size_{0};
    std::vector<std::unique_ptr<std::uint64_t[]>> keys_;
};

}  // namespace gridcar
