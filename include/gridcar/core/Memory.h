#pragma once
/// @file Memory.h
/// @brief The process's resident memory, for the planners' memory bound (max_memory_mb), and
/// zero-initialised byte arrays that cost nothing until they are written.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace gridcar
{
/// Resident set size of this process in MB (Linux: /proc/self/statm), or -1 where it cannot be
/// read (the memory bound then does not apply).
double residentMegabytes();

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
