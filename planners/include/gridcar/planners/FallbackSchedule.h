#pragma once
/// @file FallbackSchedule.h
/// @brief What the car-lattice family searches when its first search ends without the goal,
/// and in which order: a strategy of its own, apart from the searches it schedules.

#include <cstdint>
#include <functional>
#include <vector>

namespace gridcar
{
/// Which of the family's searches a stage runs.
enum class FallbackSearch
{
    Lattice,     ///< the search the query started on (its node lattice)
    Hybrid,      ///< Hybrid A*'s primitive set (continuous poses: finer manoeuvres)
    FineHybrid   ///< the hybrid set at half its cell (a gap the hybrid's cells are too coarse for)
};

/// One stage of the schedule: a search, from the start or from the goal back to the start
/// (CarLatticeQuery::timeReversed: leaving a slot is found where entering it is not).
struct FallbackStage
{
    FallbackSearch search;
    bool fromGoal{false};
    bool operator==(const FallbackStage &o) const { return search == o.search && fromGoal == o.fromGoal; }
};

/// What the family has, and what the query asks, that decides the stages.
struct FallbackOptions
{
    /// The goal is a pose to be met exactly from a start pose (a GoalState, no yaw tolerance,
    /// the start heading given): only then can a search run from the goal back.
    bool fixedEnds{false};
    bool latticeReverses{false};  ///< the first search's primitive set drives backwards
    /// the first search reversed only near the start and the goal (reverse=auto,
    /// CarLatticeQuery::reverseWithin): every stage reverses everywhere
    bool reverseNearEnds{false};
    /// The first search could not leave its start pose (no motion of its primitive set out of
    /// it is free, forwards or backwards): the same set reversing everywhere cannot either, and
    /// from the goal back it could only come in by those motions reversed. Its stages are left
    /// out; the hybrid set's finer manoeuvres may leave where the lattice's cannot.
    bool startShut{false};
    bool hybrid{false};           ///< the family has the hybrid set (then also at half its cell)
    bool hybridReverses{false};   ///< the hybrid set drives backwards
    bool fine{false};             ///< the hybrid set can be halved (its cell >= 5 cm)
};

/**
 * @brief The fallback schedule of the car lattice (CarFamily::solve()). Where the first
 * search from the start ends without the goal and was not stopped, the time left goes to, in
 * this order (every stage reversing wherever its primitive set can):
 * 0. where the first search reversed only near the start and the goal, the same search
 *    reversing everywhere (a dead end or a tight corner on the way);
 * 1. the first search again from the goal back to the start (a goal pose met exactly,
 *    reversing);
 *    (0 and 1 left out where the first search could not leave its start: startShut)
 * 2. the hybrid set (Hybrid A*'s finer manoeuvres: the lattice's nodes could not make it),
 *    then from the goal back;
 * 3. the hybrid set at half its cell (down to 2.5 cm), then from the goal back.
 * With more than one stage they run in turns, round after round, each on an expansion budget
 * that starts at 2 000 and grows fourfold a round: deterministic (the same stages get the same
 * expansions whatever the machine's speed), and at most about 4/3 of each stage's own
 * expansions repeated. A stage that ends by itself (found the goal, or ran out of its graph) is
 * not run again; the rounds end when the caller's answer is final (reached the goal, or the
 * termination condition fired) or every stage ended by itself. One stage alone runs without a
 * budget.
 */
class FallbackSchedule
{
public:
    /// The stages for @p o, in the order above (none: nothing to fall back on).
    explicit FallbackSchedule(const FallbackOptions &o);
    const std::vector<FallbackStage> &stages() const { return stages_; }
    /// The first round's expansion budget (unlimited with one stage).
    std::uint64_t firstBudget() const;
    /// Budget after @p b: four times it (saturating).
    static std::uint64_t nextBudget(std::uint64_t b);

    /// Runs the schedule: @p runStage(stage, budget) runs one stage on at most budget
    /// expansions and returns true when it ended by itself (not for want of budget);
    /// @p answered() is asked before every stage and every round. Returns the number of stage
    /// runs made.
    int run(const std::function<bool(const FallbackStage &, std::uint64_t)> &runStage,
            const std::function<bool()> &answered) const;

private:
    std::vector<FallbackStage> stages_;
};

}  // namespace gridcar
