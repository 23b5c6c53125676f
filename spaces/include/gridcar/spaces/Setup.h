#pragma once
/// @file Setup.h
/// @brief One call from a map and a vehicle to a ready ompl::geometric::SimpleSetup.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/spaces/GridSE2StateSpace.h"

#include <ompl/geometric/SimpleSetup.h>

#include <memory>

namespace gridcar
{
/// Options of makeGridSetup().
struct SetupOptions
{
    int headingBins{8};          ///< lattice heading bins: 8, 16, 32 or 72
    double sweepFraction{0.5};   ///< swept-motion check spacing, fraction of the cell size
};

/// Everything a planning problem on a grid map needs, shared by every planner.
struct GridSetup
{
    std::shared_ptr<const OccupancyGrid> grid;
    std::shared_ptr<const DistanceField> field;
    std::shared_ptr<FootprintChecker> checker;
    std::shared_ptr<GridSE2StateSpace> space;
    ompl::geometric::SimpleSetupPtr ss;

    /// Sets start and goal poses (world frame, yaw in radians) on the SimpleSetup.
    void setStartAndGoal(const Pose2 &start, const Pose2 &goal) const;
};

/**
 * @brief Builds the distance field, the footprint checker, the grid SE(2) space and a
 * SimpleSetup with FootprintValidityChecker, FootprintMotionValidator and a state validity
 * checking resolution of half a cell. Any OMPL planner (or ours) can then be set on `ss`.
 * @param field optional precomputed distance field of @p grid (computed when null).
 */
GridSetup makeGridSetup(std::shared_ptr<const OccupancyGrid> grid, const VehicleParams &vehicle,
                        const SetupOptions &options = SetupOptions(),
                        std::shared_ptr<const DistanceField> field = nullptr);

}  // namespace gridcar
