#pragma once
/// @file Memory.h
/// @brief The process's resident memory, for the planners' memory bound (max_memory_mb), and
/// zero-initialised byte arrays that cost nothing until they are written.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

namespace gridcar
{
/// Resident set size of this process in MB (Linux: /proc/self/statm), or -1 where it cannot be
/// read (the memory bound then does not apply).
double residentMegabytes();

/// Asks the system to back [p, p + bytes) with huge pages where it can (Linux transparent huge
/// pages in `madvise` mode, Debian's default): a grid-sized array of a 24 M-cell map is then
/// committed in 2 MB pages, not 4 KB ones, and its first write costs a few hundred page faults
/// instead of tens of thousands (on a virtual machine each fault is dear: writing 100 MB fresh
/// took 0.26-0.45 s with 4 KB pages, 0.01 s with huge ones). Only the 2 MB-aligned interior is
/// advised; small ranges, other systems and a refusal are left as they are. Call it before the
/// memory is first written.
void adviseHugePages(void *p, std::size_t bytes);

/// v.reserve(n) with the new storage advised for huge pages (adviseHugePages()) before anything
/// is written to it; v must be empty (a vector with contents would copy them into the new storage).
template <class T>
void reserveHuge(std::vector<T> &v, std::size_t n)
{
    if (n <= v.capacity()) return;
    v.reserve(n);
    adviseHugePages(v.data(), n * sizeof(T));
}

/**
 * @brief A byte array that starts as zeros, from calloc: a large one (the grid planners' move
 * cache, 192 MB on a 24 M-cell map) takes fresh zero pages from the system, committed only as
 * they are written, so allocating or zeroing it again is no pause (std::vector's zero fill of
 * 192 MB took 40-70 ms that a termination condition could not interrupt).
 */
class ZeroedBytes
{
public:
    ZeroedBytes() = default;
    ~ZeroedBytes() { std::free(p_); }
    ZeroedBytes(const ZeroedBytes &) = delete;
    ZeroedBytes &operator=(const ZeroedBytes &) = delete;

    /// @p n zero bytes (the old contents dropped).
    void assignZeros(std::size_t n)
    {
        release();
        if (n == 0) return;
        p_ = static_cast<std::uint8_t *>(std::calloc(n, 1));
        if (!p_) throw std::bad_alloc();
        n_ = n;
    }
    /// Every byte zero again, at the same size.
    void zero() { assignZeros(n_); }
    void release()
    {
        std::free(p_);
        p_ = nullptr;
        n_ = 0;
    }
    std::size_t size() const { return n_; }
    std::uint8_t &operator[](std::size_t i) const { return p_[i]; }

private:
    std::uint8_t *p_{nullptr};
    std::size_t n_{0};
};

}  // namespace gridcar
