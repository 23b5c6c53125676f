#pragma once
/// @file CornerAStar.h
/// @brief Paper C's corner-weighted A*.

#include "gridcar/planners/CornerWeights.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/GridLatticePlanner.h"
#include "gridcar/vehicle/Dynamics.h"

#include <string>

namespace gridcar
{
/**
 * @brief corner A*'s weights as a part of a planner of either family: the weight settings
 * (CornerWeightSettings, declared from their table) and the weights in use, resolved by
 * setup() for the planner's vehicle.
 */
template <class Family>
class CornerWeighted : public Family
{
public:
    CornerWeighted(const ompl::base::SpaceInformationPtr &si, const std::string &name) : Family(si, name)
    {
        declareSettings<CornerWeightSettings>(this->params(), name, cornerWeightFields(), cw_,
                                              [this](const std::string &n) { this->parameterSet(n); });
    }
    void setup() override
    {
        Family::setup();
        weights_ = cw_.resolve(this->vehicle());  // no checker: the default car's dynamics
    }
    /// The weights in use after setup() (paper C's before).
    const CornerWeights &weights() const { return weights_; }
    /// The weight settings as set.
    const CornerWeightSettings &cornerSettings() const { return cw_; }

private:
    CornerWeightSettings cw_;
    CornerWeights weights_;
};

/**
 * @brief Corner-weighted A* (paper C).
 *
 * On the car lattice (search/CarLattice.h, the successors improved A* uses; `lattice_cell`,
 * `headings` 8 or 16, default 16; CarLatticePlanner): step cost = primitive length +
 * the corner weight of its heading change, interpolated linearly in the turn angle between
 * 0 (0 degrees) and the 45 / 90 / 135-degree weights below (a 22.5-degree turn costs half the
 * 45-degree weight; two 45-degree turns cost 2 x w45, a little less than w90). Its paths have
 * curvature <= K_max and a free footprint as searched.
 *
 * Paper C's own search on the map's cells is CornerAStarGrid (`corner-astar-grid`).
 *
 * Parameters (declareParam): `corner_weight_45` (2.7 m), `corner_weight_90` (7.0 m),
 * `corner_weight_135` (11.3 m: the paper gives none; we continue its two values linearly in the
 * turn angle, 7.0 + (7.0 - 2.7), which keeps a 135-degree corner dearer than a 90-degree one as
 * the physics model says while staying admissible for any weight >= 0), `weights` (paper | physics). Weights are distances in metres and
 * are NOT rescaled with the cell size: on paper C's 1 m grid a 90-degree corner costs as much
 * as 7 cells, on a 0.298 m grid as much as 23.5 cells, the same 7 m of lost driving.
 *
 * `weights = physics` derives the weights not set explicitly from the VehicleParams of the footprint checker as
 * v_max x (time lost braking for and leaving the corner) = (v_max - v_c)^2 / 2 x (1/a + 1/d),
 * with a / d the acceleration / deceleration and v_c the corner speed (the vehicle's
 * corner_speed_* when set, else sqrt(min(mu g, a_lat) r) with r the minimum turning radius
 * scaled by 1 / tan(theta / 2)). A `corner_weight_*` set explicitly is used as given with either
 * `weights`, whenever it is set (before or after setup()); the others come from `weights`.
 *
 * `cost = time` (default `corners`): paper C's future work, the driving time
 * itself as the search cost, in seconds: each primitive costs its length at the speed limit of
 * its curvature at every sample, min(v_max, sqrt(min(mu g, a_lat) / kappa)), plus the time lost
 * braking from v_max to the speed of its sharpest curvature and accelerating after it
 * (cornerDistanceLost() / v_max; at least cornerTimeLost() of its heading change, the physics
 * weights' model in seconds: a small heading change at full lock is driven as slowly as a
 * large one); the heuristic is the lattice's distance bound / v_max (every metre takes at
 * least 1 / v_max seconds: admissible, and weaker than the length bound, so the search expands
 * more); a gear change costs `cusp_penalty` metres at the manoeuvring speed. The corner weights
 * do not act then. Braking is charged per primitive, not from the speed the path arrives with
 * (that would need the speed in the state), so a turn made of several primitives is charged
 * more than a car loses on it.
 *
 * @par External documentation
 * Paper C: "Shortest driving-time path planning considering UGV driving characteristics and
 * driving time, and its driving algorithm", JKROS 2014.
 */
class CornerAStar : public CornerWeighted<CarLatticePlanner>
{
public:
    explicit CornerAStar(const ompl::base::SpaceInformationPtr &si);

    /// `cost`: corners (length + corner weights, paper C) or time (driving time, seconds).
    std::string cost() const { return timeCost_ ? "time" : "corners"; }
    void setCost(const std::string &c);
    /// `turn_heuristic` (default 1): with `cost = corners`, the 2D heuristic also counts the
    /// corner weights of the turning its route needs (TurnHeuristic; docs/planners.md).
    bool turnHeuristic() const { return turnHeuristic_; }
    void setTurnHeuristic(bool on);
    /// Corner weight (m) of a heading change of @p rad radians (linear between the table's).
    double turnWeight(double rad) const { return gridcar::turnWeight(weights(), rad); }

protected:
    std::unique_ptr<LatticeCostModel> carCost() const override;

private:
    bool timeCost_{false};  ///< `cost` = time: driving time (s) instead of length + corner weights
    bool turnHeuristic_{true};  ///< `turn_heuristic`
};

/**
 * @brief Paper C's corner-weighted A* as published, on the map's cells (`corner-astar-grid`;
 * the older command lines `corner-astar lattice=grid` and `corner-astar mode=paper`): paper
 * C's 8-connected search: state = (cell, arrival direction); step cost = step length + corner
 * weight of the heading change (0 / 45 / 90 / 135 degrees, the weights of CornerAStar). A
 * 180-degree reversal is never a successor. Heuristic: octile distance (admissible: weights
 * are >= 0). Its paths are cell polylines, not drivable curves.
 *
 * @par External documentation
 * Paper C: "Shortest driving-time path planning considering UGV driving characteristics and
 * driving time, and its driving algorithm", JKROS 2014.
 */
class CornerAStarGrid : public CornerWeighted<GridLatticePlanner>
{
public:
    explicit CornerAStarGrid(const ompl::base::SpaceInformationPtr &si);

protected:
    std::unique_ptr<GridNodes> makeGridNodes() override;
};

}  // namespace gridcar
