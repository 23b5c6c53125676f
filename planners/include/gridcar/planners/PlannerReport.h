#pragma once
/// @file PlannerReport.h
/// @brief What a planner's last solve() found beyond OMPL's status and path, as one typed
/// report: the query pipeline reads it for any planner without downcasts or progress-property
/// names.

#include "gridcar/core/Pose2.h"
#include "gridcar/path/PostProcess.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gridcar
{
/// A planner's report of its last solve() (and what kind of planner it is).
struct PlannerReport
{
    /// The solution path is the planner's own poses (the car lattice's dense curves, the papers'
    /// grid polylines, paper I's smoothing): taken as they are on any space, never interpolated
    /// along the space's curves.
    bool ownPoses{false};
    /// The planner searches the map's cells in straight steps (the papers' grid searches): on a
    /// Dubins or Reeds-Shepp space its path is no curve of the space.
    bool searchesMapCells{false};
    /// The planner searches the car lattice: its paths are drivable curves as searched (paper
    /// I's smoothing would only move them off the curves whose footprint was checked).
    bool searchesCarLattice{false};
    /// The planner smooths its own path (paper I's post-processing): wrapping it in another
    /// SmoothedPlanner would add nothing.
    bool smoothsItself{false};
    std::optional<std::uint64_t> expanded;  ///< states expanded (unset: the planner does not count them)
    std::optional<double> searchCost;       ///< the planner's own search cost (unset: it has none)
    std::optional<double> searchSeconds;    ///< seconds in the search loop itself (unset: not measured)
    /// Why the last solve() returned no exact solution though not out of time (the memory bound;
    /// a smoothed path that failed the drivability check), else empty.
    std::string stopReason;
    /// The smoothing of the last solve(), when the planner smooths (null otherwise; its path is
    /// empty when nothing was smoothed), and the path before it.
    const SmoothingResult *smoothing{nullptr};
    std::vector<Pose2> rawPath;
};

/// A planner that reports its last solve() (gridcar's planners and SmoothedPlanner).
class ReportingPlanner
{
public:
    virtual ~ReportingPlanner() = default;
    /// The report of the last solve() (valid until the next solve() or clear()).
    virtual PlannerReport lastReport() const = 0;
};

/// The report of any planner: gridcar's planners report themselves; any other OMPL planner
/// reports nothing but what it is (its path interpolated along the space's curves).
PlannerReport reportOf(const ompl::base::Planner &planner);

}  // namespace gridcar
