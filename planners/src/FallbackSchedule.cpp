/// @file FallbackSchedule.cpp
/// @brief The car lattice's fallback schedule: its stages and its rounds.
#include "gridcar/planners/FallbackSchedule.h"

#include <algorithm>
#include <limits>

namespace gridcar
{
FallbackSchedule::FallbackSchedule(const FallbackOptions &o)
{
    const bool lattice = o.latticeReverses && !o.startShut;
    if (o.reverseNearEnds && lattice) stages_.push_back({FallbackSearch::Lattice, false});
    if (o.fixedEnds && lattice) stages_.push_back({FallbackSearch::Lattice, true});
    if (!o.hybrid) return;
    stages_.push_back({FallbackSearch::Hybrid, false});
    if (o.fixedEnds && o.hybridReverses) stages_.push_back({FallbackSearch::Hybrid, true});
    if (!o.fine) return;
    // the half-cell set is the hybrid one with a finer cell: it reverses as the hybrid does
    stages_.push_back({FallbackSearch::FineHybrid, false});
    if (o.fixedEnds && o.hybridReverses) stages_.push_back({FallbackSearch::FineHybrid, true});
}

std::uint64_t FallbackSchedule::firstBudget() const
{
    return stages_.size() > 1 ? 2000 : std::numeric_limits<std::uint64_t>::max();
}

std::uint64_t FallbackSchedule::nextBudget(std::uint64_t b)
{
    return b > std::numeric_limits<std::uint64_t>::max() / 4 ? b : 4 * b;
}

int FallbackSchedule::run(const std::function<bool(const FallbackStage &, std::uint64_t)> &runStage,
                          const std::function<bool()> &answered) const
{
    std::vector<char> ended(stages_.size(), 0);
    const bool turns = stages_.size() > 1;
    auto pending = [&ended] { return std::any_of(ended.begin(), ended.end(), [](char e) { return !e; }); };
    int runs = 0;
    for (std::uint64_t budget = firstBudget(); !answered() && pending(); budget = nextBudget(budget))
        for (std::size_t k = 0; k < stages_.size(); ++k)
        {
            if (ended[k] || answered()) continue;
            ++runs;
            // ended by itself: another round would repeat it; one stage alone runs once
            ended[k] = runStage(stages_[k], budget) || !turns;
        }
    return runs;
}

}  // namespace gridcar
