#pragma once
/// @file SolverSupport.h
/// @brief The OMPL plumbing every planner of this library shares, held by composition: the
/// memory bound, the statistics behind the progress properties, the world a set-up was built
/// on, and the one rule that turns a search's end into a solution path and a PlannerStatus.

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>

#include "gridcar/core/Pose2.h"

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace gridcar
{
/// How one solve() ended, as the search family saw it (SolverSupport::finish() reports it).
struct SearchEnd
{
    /// The path to report (start first), or null when there is none.
    std::shared_ptr<ompl::geometric::PathGeometric> path;
    bool reached{false};    ///< the path ends in the goal
    bool cancelled{false};  ///< the termination condition stopped the search
    /// Non-empty: the path reaches the goal but is not to be reported exact, for this reason
    /// (a smoothed path failed the drivable check, the smoothing was stopped, ...).
    std::string notExactBecause;
    /// The status when there is no path and neither the memory bound nor the termination
    /// condition stopped the search (e.g. INVALID_START: the vehicle fits at no start heading).
    ompl::base::PlannerStatus::StatusType noPath{ompl::base::PlannerStatus::TIMEOUT};
    /// Logged as an error when noPath is returned (empty: nothing logged).
    std::string noPathWhy;
    /// Non-empty: why the path (not reaching the goal) is all there is (the goal proven
    /// unreachable): logged, and the stop reason.
    std::string approximateWhy;
};

/**
 * @brief Solver support shared by every gridcar planner (composition, not a base class).
 *
 * - **Memory bound** (`max_memory_mb`): withMemoryBound() or's the termination condition with
 *   a resident-memory check every 10 ms; a solve() stopped by it returns APPROXIMATE_SOLUTION
 *   with the path found so far, or ABORT without one (stopReason() says why).
 * - **Statistics**: the last search's expansions, cost and loop time, atomics because OMPL's
 *   Benchmark reads them from its progress thread while solve() writes them; the progress
 *   properties "expanded nodes INTEGER", "search cost REAL" and "search time REAL".
 * - **World**: the validity checker and motion validator a set-up was built on, held (shared
 *   ownership) so that nothing built on them outlives them.
 * - **Reporting** (finish()): one rule for every search family. A path that reaches the goal is
 *   EXACT_SOLUTION unless something says it is not drivable (then APPROXIMATE_SOLUTION, added
 *   as approximate with difference 0); a path that does not reach it is APPROXIMATE_SOLUTION
 *   (TIMEOUT when the termination condition stopped the search); no path: ABORT at the memory
 *   bound, TIMEOUT when stopped, else SearchEnd::noPath.
 */
class SolverSupport
{
public:
    /// @p owner must outlive this object.
    explicit SolverSupport(ompl::base::Planner &owner);
    /// The progress properties (name, reader) the owner declares
    /// (Planner::addPlannerProgressProperty() is the owner's to call).
    std::vector<std::pair<std::string, ompl::base::Planner::PlannerProgressProperty>> progressProperties();

    /// @p ptc or'ed with the memory bound @p maxMemoryMb (MB; 0: none); resets the stop state
    /// and reason.
    ompl::base::PlannerTerminationCondition withMemoryBound(const ompl::base::PlannerTerminationCondition &ptc,
                                                            double maxMemoryMb);
    bool memoryStopped() const { return memoryStopped_; }
    /// The status of a solve() stopped at the memory bound (logs the reason).
    ompl::base::PlannerStatus memoryStatus(bool pathAdded) const;

    /// Why the last solve() returned no exact solution though it was not out of time.
    const std::string &stopReason() const { return stopReason_; }
    void setStopReason(const std::string &why) { stopReason_ = why; }

    /// Statistics: reset() at the start of a solve(), record() after its search.
    void resetStatistics();
    void record(std::uint64_t expanded, double cost, double searchSeconds);
    /// Written by the search loop as it expands (the "expanded nodes" progress property).
    std::atomic<std::uint64_t> *progress() { return &progress_; }
    std::uint64_t expanded() const { return expanded_; }
    double cost() const { return cost_; }
    double searchSeconds() const { return searchSeconds_; }

    /// True if the space information still has the checker and validator of rememberWorld().
    bool builtOnCurrentWorld(const ompl::base::SpaceInformation &si) const;
    void rememberWorld(const ompl::base::SpaceInformation &si);

    /// Adds the path of @p end to the problem definition and returns the status (see the
    /// class comment).
    ompl::base::PlannerStatus finish(SearchEnd end);

private:
    ompl::base::Planner &owner_;
    bool memoryStopped_{false};
    std::string stopReason_;
    std::atomic<std::uint64_t> progress_{0};
    std::atomic<std::uint64_t> expanded_{0};
    std::atomic<double> cost_{0.0};
    std::atomic<double> searchSeconds_{0.0};
    ompl::base::StateValidityCheckerPtr builtOnChecker_;
    ompl::base::MotionValidatorPtr builtOnMotion_;
};

/// The states of PlannerData vertices (PlannerData identifies vertices by state pointer): one
/// per key, owned here until clear() (PlannerData::decoupleFromPlanner() copies them).
class PlannerDataStates
{
public:
    explicit PlannerDataStates(ompl::base::SpaceInformationPtr si) : si_(std::move(si)) {}
    ~PlannerDataStates() { clear(); }
    PlannerDataStates(const PlannerDataStates &) = delete;
    PlannerDataStates &operator=(const PlannerDataStates &) = delete;
    /// The state of a search state @p id at @p pose (the same id and pose: the same state).
    ompl::base::State *at(std::uint64_t id, const Pose2 &pose);
    void clear();

private:
    ompl::base::SpaceInformationPtr si_;
    std::map<std::tuple<std::uint64_t, double, double, double>, ompl::base::State *> states_;
};

}  // namespace gridcar
