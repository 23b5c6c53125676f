/// @file SolverSupport.cpp
/// @brief Memory bound, statistics, world tracking and the one solution-reporting rule.
#include "gridcar/planners/SolverSupport.h"

#include "gridcar/core/Memory.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>

#include <chrono>
#include <cstdio>

namespace gridcar
{
SolverSupport::SolverSupport(ompl::base::Planner &owner) : owner_(owner) {}

std::vector<std::pair<std::string, ompl::base::Planner::PlannerProgressProperty>> SolverSupport::progressProperties()
{
    // the planner's own cost of its last solution and the seconds its search loop took, to
    // full precision (PlanQuery and the Moving AI runner read them)
    auto exact = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return std::string(buf);
    };
    return {{"expanded nodes INTEGER", [this] { return std::to_string(progress_.load()); }},
            {"search cost REAL", [this, exact] { return exact(cost_); }},
            {"search time REAL", [this, exact] { return exact(searchSeconds_); }}};
}

ompl::base::PlannerTerminationCondition SolverSupport::withMemoryBound(const ompl::base::PlannerTerminationCondition &ptc,
                                                                       double maxMemoryMb)
{
    memoryStopped_ = false;
    stopReason_.clear();
    if (!(maxMemoryMb > 0) || residentMegabytes() < 0) return ptc;
    using Clock = std::chrono::steady_clock;
    auto next = std::make_shared<Clock::time_point>(Clock::now());
    const ompl::base::PlannerTerminationCondition memory([this, next, maxMemoryMb] {
        if (memoryStopped_) return true;
        const auto now = Clock::now();
        if (now < *next) return false;
        *next = now + std::chrono::milliseconds(10);
        const double mb = residentMegabytes();
        if (mb <= maxMemoryMb) return false;
        memoryStopped_ = true;
        char buf[160];
        std::snprintf(buf, sizeof buf, "stopped at the memory bound: resident memory %.0f MB > max_memory_mb %.0f MB", mb,
                      maxMemoryMb);
        stopReason_ = buf;
        return true;
    });
    return ompl::base::plannerOrTerminationCondition(ptc, memory);
}

ompl::base::PlannerStatus SolverSupport::memoryStatus(bool pathAdded) const
{
    OMPL_WARN("%s: %s", owner_.getName().c_str(), stopReason_.c_str());
    return pathAdded ? ompl::base::PlannerStatus::APPROXIMATE_SOLUTION : ompl::base::PlannerStatus::ABORT;
}

void SolverSupport::resetStatistics()
{
    expanded_ = 0;
    progress_ = 0;
    cost_ = 0.0;
}

void SolverSupport::record(std::uint64_t expanded, double cost, double searchSeconds)
{
    expanded_ = expanded;
    progress_ = expanded;
    cost_ = cost;
    searchSeconds_ = searchSeconds;
}

bool SolverSupport::builtOnCurrentWorld(const ompl::base::SpaceInformation &si) const
{
    return builtOnChecker_ == si.getStateValidityChecker() && builtOnMotion_ == si.getMotionValidator();
}

void SolverSupport::rememberWorld(const ompl::base::SpaceInformation &si)
{
    builtOnChecker_ = si.getStateValidityChecker();
    builtOnMotion_ = si.getMotionValidator();
}

ompl::base::PlannerStatus SolverSupport::finish(SearchEnd end)
{
    using ompl::base::PlannerStatus;
    if (!end.path || end.path->getStateCount() == 0)
    {
        if (memoryStopped_) return memoryStatus(false);
        if (end.cancelled) return PlannerStatus::TIMEOUT;
        if (!end.noPathWhy.empty())
        {
            stopReason_ = end.noPathWhy;
            OMPL_ERROR("%s: %s", owner_.getName().c_str(), end.noPathWhy.c_str());
        }
        return end.noPath;
    }
    const bool exact = end.reached && end.notExactBecause.empty();
    if (end.reached && !exact)
    {
        stopReason_ = end.notExactBecause;
        OMPL_WARN("%s: %s", owner_.getName().c_str(), stopReason_.c_str());
    }
    const ompl::base::ProblemDefinitionPtr &pdef = owner_.getProblemDefinition();
    double dist = 0.0;
    pdef->getGoal()->isSatisfied(end.path->getState(end.path->getStateCount() - 1), &dist);
    pdef->addSolutionPath(end.path, !exact, end.reached ? 0.0 : dist, owner_.getName());
    if (!end.reached && !end.approximateWhy.empty())
    {
        stopReason_ = end.approximateWhy;
        OMPL_WARN("%s: %s", owner_.getName().c_str(), stopReason_.c_str());
    }
    if (exact) return PlannerStatus::EXACT_SOLUTION;
    if (end.reached) return PlannerStatus::APPROXIMATE_SOLUTION;
    if (memoryStopped_) return memoryStatus(true);
    if (end.cancelled) return PlannerStatus::TIMEOUT;
    return PlannerStatus::APPROXIMATE_SOLUTION;
}

ompl::base::State *PlannerDataStates::at(std::uint64_t id, const Pose2 &pose)
{
    const auto key = std::make_tuple(id, pose.x, pose.y, pose.yaw);
    auto it = states_.find(key);
    if (it != states_.end()) return it->second;
    ompl::base::State *st = si_->allocState();
    setPose(st, pose);
    states_.emplace(key, st);
    return st;
}

void PlannerDataStates::clear()
{
    for (auto &kv : states_) si_->freeState(kv.second);
    states_.clear();
}

}  // namespace gridcar
