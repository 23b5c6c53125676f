#pragma once
/// @file PollSchedule.h
/// @brief When a search polls its termination condition: by count, adapted to time.
/// Internal to the search core (detail/): installed because the search loop's header includes
/// it, not part of gridcar's API.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

namespace gridcar
{
/**
 * @brief Polls every (mask + 1) expansions, the mask adapted to how long expansions take: it
 * starts at every expansion and doubles, up to @p maxMask (a power of two minus one), while
 * polls come less than 0.5 ms apart, and halves while they come more than 2 ms apart. A search
 * whose expansions are slow (an application's slow validity checker, a heavy primitive) so
 * still notices a stop within a few milliseconds, and a fast one pays one clock read per
 * maxMask + 1 expansions.
 */
class PollSchedule
{
public:
    explicit PollSchedule(std::uint64_t maxMask) : max_(maxMask) {}
    /// True when expansion number @p count should poll.
    bool due(std::uint64_t count) const { return (count & mask_) == 0; }
    /// Records a poll (call it when due() said so, before or after polling).
    void polled()
    {
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        if (dt > 2e-3) mask_ >>= 1;
        else if (dt < 5e-4 && mask_ < max_) mask_ = (mask_ << 1) | 1u;
    }

private:
    using Clock = std::chrono::steady_clock;
    std::uint64_t max_;
    std::uint64_t mask_{0};
    Clock::time_point last_{Clock::now()};
};

/**
 * @brief One step of a resumable search's loop (the 2D heuristics'): @p cancelled polled when
 * @p schedule says expansion number @p count is due, then the top of @p heap (a std heap)
 * popped into @p out. False, with @p stopped set, when the condition fired.
 */
template <class Entry>
bool popUnlessCancelled(std::vector<Entry> &heap, PollSchedule &schedule, std::uint64_t count,
                        const std::function<bool()> &cancelled, bool &stopped, Entry &out)
{
    if (cancelled && schedule.due(count) && (schedule.polled(), cancelled()))
    {
        stopped = true;
        return false;
    }
    std::pop_heap(heap.begin(), heap.end());
    out = heap.back();
    heap.pop_back();
    return true;
}

}  // namespace gridcar
