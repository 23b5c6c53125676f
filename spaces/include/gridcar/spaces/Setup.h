#pragma once
/// @file Setup.h
/// @brief One call from a map and a vehicle to a ready ompl::geometric::SimpleSetup.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/spaces/CarSpaces.h"
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
    /// The space the SimpleSetup plans on: gridcar's SE(2) (default), or OMPL's Dubins /
    /// Reeds-Shepp space at the vehicle's minimum turning radius.
    SpaceKind space{SpaceKind::SE2};
};

/// How near the goal a path may end (Nav2's goal checker: xy_goal_tolerance 0.25 m,
/// yaw_goal_tolerance 0.25 rad by default there). The default here stays exact.
struct GoalTolerance
{
    double position{0.0};  ///< m from the goal position (0: the position itself)
    double yaw{0.0};       ///< rad from the goal heading, when the goal has one (0: that heading)
    bool exact() const { return position <= 0.0 && yaw <= 0.0; }
};

/// Everything a planning problem on a grid map needs, shared by every planner.
struct GridSetup
{
    std::shared_ptr<const OccupancyGrid> grid;
    std::shared_ptr<const DistanceField> field;
    std::shared_ptr<FootprintChecker> checker;
    /// The map's lattice (cells x heading bins); the SimpleSetup plans on it when kind is SE2.
    std::shared_ptr<GridSE2StateSpace> space;
    SpaceKind kind{SpaceKind::SE2};
    ompl::geometric::SimpleSetupPtr ss;  ///< its space: ss->getStateSpace()

    /// True when paths on this set-up may reverse (Reeds-Shepp): metrics and driving time
    /// then split them at their cusps.
    bool reversing() const { return kind == SpaceKind::ReedsShepp; }

    /// Sets start and goal poses (world frame, yaw in radians) on the SimpleSetup: the goal as
    /// a GoalState, or with @p freeGoalHeading as a PositionGoal at any heading (its position
    /// within 1 micrometre; OMPL's planners sample it at the first of 72 yaws where the car
    /// fits). With a @p tolerance that is not exact the goal is a PositionGoal within
    /// tolerance.position of the goal (a micrometre at 0) and, with a heading, within
    /// tolerance.yaw of it; std::invalid_argument on a negative or non-finite tolerance.
    void setStartAndGoal(const Pose2 &start, const Pose2 &goal, bool freeGoalHeading = false,
                         const GoalTolerance &tolerance = GoalTolerance()) const;
};

/**
 * @brief Builds the distance field, the footprint checker, the grid SE(2) space and a
 * SimpleSetup with FootprintValidityChecker and a state validity checking resolution of half a
 * cell. On gridcar's SE(2) space motions are FootprintMotionValidator's (straight lines, the
 * swept footprint); on Dubins / Reeds-Shepp (SetupOptions::space; bounds: the map's extent,
 * radius: the vehicle's R_min) CurveMotionValidator's (the footprint along the curve at most
 * half a cell apart), so that OMPL's planners return paths the car can drive. Any OMPL planner
 * (or ours) can then be set on `ss`. A Dubins / Reeds-Shepp space needs a vehicle with a
 * finite turning radius (std::invalid_argument otherwise).
 * @param field optional precomputed distance field of @p grid (computed when null).
 */
GridSetup makeGridSetup(std::shared_ptr<const OccupancyGrid> grid, const VehicleParams &vehicle,
                        const SetupOptions &options = SetupOptions(),
                        std::shared_ptr<const DistanceField> field = nullptr);

}  // namespace gridcar
