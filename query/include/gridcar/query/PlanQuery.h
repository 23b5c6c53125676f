#pragma once
/// @file PlanQuery.h
/// @brief The query pipeline for any planner, ours or OMPL's: configure it by name (parameters,
/// free start heading, paper I's smoothing), plan start -> goal, and measure the result. The
/// `gridcar` program's plan / drive commands and the benchmark harness all go through it.

#include "gridcar/path/Drivability.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/path/PostProcess.h"
#include "gridcar/spaces/Setup.h"
#include "gridcar/planners/PlannerReport.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
/// Planner parameters as NAME, VALUE pairs (OMPL's ParamSet takes strings).
using PlannerParams = std::vector<std::pair<std::string, std::string>>;

/// "NAME=VALUE" strings (as `--param` gives them) to pairs; InputError on a malformed one.
PlannerParams parsePlannerParams(const std::vector<std::string> &settings);

/// A planner name with parameter settings.
using NamedConfiguration = std::pair<std::string, PlannerParams>;
/// Every registry name, plus the configurations worth measuring apart: improved-astar-grid in
/// integral mode, improved-astar in paper mode, astar-octile+smooth, rrtconnect+smooth,
/// rrtconnect+simplify (the termination test and benchmark run them all).
std::vector<NamedConfiguration> everyConfiguration();
/// "NAME P=V P=V" for messages and tables.
std::string configurationLabel(const NamedConfiguration &c);

/// How to build a planner for a query.
struct PlannerConfig
{
    std::string name;           ///< a makePlanner() name, optionally with "+smooth"
    PlannerParams params;       ///< declared parameters to set
    bool freeStartHeading{false};  ///< grid planners choose their first heading (no start yaw given)
    bool smooth{false};         ///< add paper I's post-processing unless the planner smooths itself
};

/**
 * @brief makePlanner() by name, then: `free_start_heading` where the planner has it (OMPL's
 * planners have no such parameter and start at the start state's yaw), the parameters (an
 * unknown name lists the planner's parameters; a rejected value says why: both InputError), and
 * with `smooth` a SmoothedPlanner around it unless it smooths its own paths already
 * (improved-astar with smooth = 1, or a name ending in "+smooth").
 */
ompl::base::PlannerPtr configurePlanner(const ompl::base::SpaceInformationPtr &si, const PlannerConfig &config);

/// One planning query and everything reported about it.
struct QueryResult
{
    ompl::base::PlannerStatus status;
    double seconds{0.0};           ///< wall time of solve(), smoothing included
    double smoothingSeconds{0.0};  ///< of that, post-processing
    std::vector<Pose2> path;       ///< the reported path (smoothed where smoothing ran)
    std::vector<Pose2> rawPath;    ///< before smoothing (the lattice path for grid planners)
    PathMetrics metrics;           ///< of `path`
    /// Largest heading change at a turning point: of `path`, or where smoothing ran, of the
    /// turning points the Bezier pieces were built on (paper I's measure for its smoothed paths)
    double maxTurnDeg{0.0};
    std::uint64_t expanded{0};     ///< the planner's "expanded nodes" (0 for OMPL's planners)
    double cost{0.0};              ///< the grid planner's search cost, else the path length
    bool smoothed{false};
    int adjustFailures{0}, bezierFallbacks{0};
    /// checkDrivable() of `path` for the setup's vehicle: an exact solution is not
    /// necessarily a path the vehicle can drive (a grid path's corners, a smoothed curve that
    /// clips a curb); this says which, independently of the planner
    Drivability drivability;
    /// Why the planner returned no exact solution though it was not out of time: a grid
    /// planner stopped at its memory bound, or a smoothed path failed the drivable check
    /// (PlannerReport::stopReason, SmoothingResult::notDrivable); empty otherwise
    std::string notExactBecause;
};

/// Solves start -> goal with @p planner on @p setup within @p timeLimit seconds (start / goal
/// must be valid: the caller checks) and measures the path (computePathMetrics(), and
/// checkDrivable() when there is one).
/// With @p freeGoalHeading the goal is a position at any heading (a query given without a goal
/// yaw), else the goal pose with its yaw (GridSetup::setStartAndGoal()); a @p tolerance that is
/// not exact lets the path end within it.
QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit, bool freeGoalHeading = false, const GoalTolerance &tolerance = GoalTolerance());

/// The poses of the set-up's solution path: on a Dubins / Reeds-Shepp space an OMPL planner's
/// states with the poses along the curves between them (at most the validity resolution
/// apart); a gridcar planner's path as it is.
std::vector<Pose2> solutionPoses(const GridSetup &setup, const ompl::base::Planner &planner);
/// Cells of the states @p planner explored in its last solve() (its PlannerData vertices).
std::vector<Cell> exploredCells(const ompl::base::Planner &planner, const OccupancyGrid &grid);

/// "" if the vehicle of @p checker fits at @p p (at any heading in 5-degree steps with
/// @p anyHeading), else why not: "outside the map, which spans ...", "in collision for vehicle X
/// [at every heading]", with a word on unknown cells where only unknown cells are near it.
std::string whyPoseInvalid(const FootprintChecker &checker, const OccupancyGrid &grid, const Pose2 &p, bool anyHeading = false);

}  // namespace gridcar
