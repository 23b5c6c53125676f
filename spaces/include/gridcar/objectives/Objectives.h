#pragma once
/// @file Objectives.h
/// @brief OMPL optimization objectives of gridcar: obstacle distance (paper I's o(n) integrated
/// along the path) and driving time (paper C's future work), plus the exact driving time of a
/// path from a forward-backward velocity profile.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/objectives/StateCostIntegralObjective.h>

#include <memory>
#include <string>
#include <vector>

namespace gridcar
{
/**
 * @brief Integral of delta / d_O along the path (paper I, eq. 8, as a cost instead of a
 * heuristic weight), d_O the bilinear obstacle distance of the DistanceField (clamped below at
 * half a cell); optionally delta x Dolgov's Voronoi field. Motion costs use the trapezoid rule
 * over the motion's interpolated states (StateCostIntegralObjective with interpolation), so it
 * is the same cost improved-astar's `integral` mode minimises on its lattice (there per step).
 * Combine with path length through ompl::base::MultiOptimizationObjective
 * (makeObjective("length+obstacle")).
 */
class ObstacleDistanceObjective : public ompl::base::StateCostIntegralObjective
{
public:
    ObstacleDistanceObjective(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const DistanceField> field,
                              double delta = 1.0, bool voronoi = false);
    ompl::base::Cost stateCost(const ompl::base::State *s) const override;
    double delta() const { return delta_; }

private:
    std::shared_ptr<const DistanceField> field_;
    double delta_;
    bool voronoi_;
};

/**
 * @brief Driving time as an OMPL objective (additive, as RRT* / PRM* / BIT* need): the cost of
 * a motion s1 -> s2 is its length / v_max plus the time lost for the heading change between
 * s1's yaw and the motion's direction, (v_max - v_c)^2 / 2 x (1/a + 1/d) / v_max with v_c the
 * corner speed of that change (the `physics` corner-weight model of corner-astar, in seconds).
 * This is an approximation: it charges a turn where it happens in the tree, not where the
 * vehicle brakes. The exact time of a finished path is drivingTime(); the benchmark reports
 * that. Cost-to-go heuristic: Euclidean distance / v_max (admissible).
 */
class DrivingTimeObjective : public ompl::base::OptimizationObjective
{
public:
    DrivingTimeObjective(const ompl::base::SpaceInformationPtr &si, const VehicleParams &vehicle);
    ompl::base::Cost stateCost(const ompl::base::State *s) const override;
    ompl::base::Cost motionCost(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    ompl::base::Cost motionCostHeuristic(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    /// Seconds lost for a heading change of @p thetaRad (0 for no change).
    double turnPenalty(double thetaRad) const;

private:
    VehicleParams vehicle_;
};

/// Objectives by name: "length", "obstacle", "length+obstacle" (weights 1, 1),
/// "driving-time". @p checker supplies the distance field and the vehicle. Throws
/// std::invalid_argument listing the names.
ompl::base::OptimizationObjectivePtr makeObjective(const std::string &name, const ompl::base::SpaceInformationPtr &si,
                                                   const FootprintChecker &checker, double delta = 1.0);
std::vector<std::string> objectiveNames();

}  // namespace gridcar
