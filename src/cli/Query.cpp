#include "Query.h"

#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>

namespace gridcar::cli
{
QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit, bool smooth)
{
    using Clock = std::chrono::steady_clock;
    QueryResult q;
    setup.ss->clear();
    setup.setStartAndGoal(start, goal);
    setup.ss->setPlanner(planner);
    const auto t0 = Clock::now();
    q.status = setup.ss->solve(timeLimit);
    q.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (setup.ss->haveSolutionPath())
        for (const auto *s : setup.ss->getSolutionPath().getStates()) q.path.push_back(toPose(s));
    q.rawPath = q.path;
    auto *gp = dynamic_cast<GridPlanner *>(planner.get());
    q.expanded = gp ? gp->expandedNodes() : 0;
    const SmoothingResult *sm = nullptr;
    SmoothingResult own;
    if (auto *ia = dynamic_cast<ImprovedAStar *>(planner.get()); ia && ia->smooth() && !ia->lastSmoothing().path.empty())
    {
        sm = &ia->lastSmoothing();
        q.rawPath = ia->lastLatticePath();
    }
    else if (auto *sp = dynamic_cast<SmoothedPlanner *>(planner.get()); sp && !sp->lastSmoothing().path.empty())
    {
        sm = &sp->lastSmoothing();
        q.rawPath.clear();
        for (const Pose2 &p : sm->turningPoints) q.rawPath.push_back(p);
    }
    else if (smooth && q.path.size() >= 3)
    {
        own = smoothPath(q.path, *setup.checker);
        q.seconds += own.seconds;
        q.path = own.path;
        sm = &own;
    }
    q.metrics = computePathMetrics(q.path, setup.checker.get());
    q.maxTurnDeg = q.metrics.maxTurnDeg;
    if (sm)
    {
        q.smoothed = true;
        q.smoothingSeconds = sm->seconds;
        q.adjustFailures = sm->adjustFailures;
        q.bezierFallbacks = sm->bezierFallbacks;
        q.maxTurnDeg = 0.0;
        for (const CornerReport &c : sm->corners) q.maxTurnDeg = std::max(q.maxTurnDeg, c.turnDeg);
    }
    q.cost = gp ? gp->lastCost() : q.metrics.length;
    return q;
}
}  // namespace gridcar::cli
