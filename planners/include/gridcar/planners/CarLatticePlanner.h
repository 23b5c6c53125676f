#pragma once
/// @file CarLatticePlanner.h
/// @brief The planner of the car lattice: GridPlanner over CarFamily, with the car lattice's
/// settings (CarLatticeSettings) and a cost model the subclass chooses.

#include "gridcar/planners/CarFamily.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/search/CarLatticeSettings.h"

#include <memory>
#include <string>

namespace gridcar
{
/**
 * @brief A planner of the car lattice (search/CarLattice.h: primitives of curvature within
 * K_max joining lattice nodes, or Hybrid A*'s; the footprint certified along each; the
 * obstacle-aware heuristic; the analytic expansion into the exact goal): its paths are
 * drivable as searched. What it minimises is the subclass's carCost() (default: length).
 *
 * Its settings are one plain struct, CarLatticeSettings, declared as OMPL parameters from one
 * table (CarLatticeParams.h: `headings`, `heuristic_weight`, `reverse`, `reverse_penalty`,
 * `cusp_penalty`, `curve_heuristic`, `primitives`, `continuous_curvature`, `curvature_rate`,
 * `cost_layer_weight`, `turns`, `shortcut`), each parsed in its setter (std::invalid_argument
 * naming the value and what is accepted) and copied whole into the search's query.
 * `reverse=on` is refused by setup() on a Dubins space, which is forward-only.
 */
class CarLatticePlanner : public GridPlanner
{
public:
    CarLatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);

    bool usesCarLattice() const final { return true; }

    /// The car lattice's settings as set (see CarLatticeSettings and docs/planners.md). The
    /// `curve_heuristic` bound: `table` reads it from the lattice's CurveTable (node offsets
    /// within 10 R_min per axis, kept across queries; none in the hybrid fallback), `exact`
    /// computes it at every state within 30 R_min (CurveBound).
    const CarLatticeSettings &carSettings() const { return settings_; }
    /// All settings at once (set-up is redone before the next solve()).
    void setCarSettings(const CarLatticeSettings &s);
    /// True if the lattice drives backwards as configured (`reverse` on, or auto off a Dubins
    /// space).
    bool reversing() const;
    /// True on OMPL's Dubins space (forward only: `reverse=on` refused, `auto` off).
    bool onDubinsSpace() const;
    /// Cost of a gear change (m of length-equivalent cost): `cusp_penalty` as set, else from
    /// the vehicle: the distance its stop and start at a manoeuvring speed cost (see
    /// gearChangeDistance()).
    double cuspPenalty() const;
    /// How far from the start and the goal the first search reverses (CarLatticeQuery::
    /// reverseWithin): reverse=auto's zone where the planner reverses, else -1 (everywhere).
    double reverseWithin() const;
    /// The range the curve heuristic covers (m; 0: off, or no car lattice set up).
    double curveWithin() const;
    /// True if a found path is shortcut as configured (`shortcut`; auto: with `reverse=on`, a
    /// lattice reversing everywhere, not with reverse=auto's routes).
    bool shortcutting() const
    {
        return settings_.shortcut == AutoSwitch::On ||
               (settings_.shortcut == AutoSwitch::Auto && reversing() && settings_.reverse == AutoSwitch::On);
    }
    /// The curvature rate the lattice's paths keep (1/m^2; 0: not smoothed).
    double curvatureRate() const;
    /// The car lattice in use after setup() (null before).
    const CarLatticeSearch *carSearch() const { return car_.search(); }
    /// The primitive set setup() gives the car lattice for this map and vehicle (with
    /// `primitives=auto`, the lattice's; carLatticeConfig(true) is its hybrid fallback).
    CarLatticeConfig carLatticeConfig() const;
    CarLatticeConfig carLatticeConfig(bool hybrid) const;

protected:
    /// The cost the search minimises (default: length).
    virtual std::unique_ptr<LatticeCostModel> carCost() const { return std::make_unique<LengthCost>(); }
    void setupFamily(const std::shared_ptr<CarCollision> &collision) override;
    FamilyRun searchFamily(const ompl::base::State *start, const GoalTarget &goal, const std::function<bool()> &cancelled,
                           std::atomic<std::uint64_t> *progress) override;
    void familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const override;

private:
    CarLatticeSettings settings_;
    CarFamily car_;
};

}  // namespace gridcar
