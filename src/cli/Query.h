#pragma once
// One planning query and everything the CLI reports about it (shared by plan and paper-i).
#include "gridcar/path/PathMetrics.h"
#include "gridcar/path/PostProcess.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <vector>

namespace gridcar::cli
{
struct QueryResult
{
    ompl::base::PlannerStatus status;
    double seconds{0.0};           ///< wall time of solve() plus any --smooth post-processing
    double smoothingSeconds{0.0};  ///< of that, post-processing (improved-astar's own or --smooth)
    std::vector<Pose2> path;       ///< the reported path (smoothed where smoothing ran)
    std::vector<Pose2> rawPath;    ///< before smoothing (the lattice path for grid planners)
    PathMetrics metrics;           ///< of `path`
    /// Largest heading change at a turning point: of `path`, or where smoothing ran, of the
    /// turning points the Bezier pieces were built on (paper I's measure for its smoothed paths)
    double maxTurnDeg{0.0};
    std::uint64_t expanded{0};
    double cost{0.0};              ///< the grid planner's search cost, else the path length
    bool smoothed{false};
    int adjustFailures{0}, bezierFallbacks{0};
};

/// Solves start -> goal with @p planner on @p setup (start / goal must be valid: the caller
/// checks), then, with @p smooth, post-processes the path with smoothPath() unless the planner
/// smoothed it itself (improved-astar with smooth = 1).
QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit, bool smooth);
}  // namespace gridcar::cli
