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
    /// `primitives=auto`, the lattice's; carLatticeConfig(true) is its hybrid fallback): a
    /// route's, on routeCell().
    CarLatticeConfig carLatticeConfig() const;
    /// The lattice cell of a query to a goal position, a route (m): with `lattice_cell` unset
    /// on gridcar's checker, twice poseCell() where that is at most 0.4 R_min, else poseCell().
    double routeCell() const;
    /// The lattice cell of a query to a goal pose (m): `lattice_cell`, else a quarter of the
    /// vehicle's width or R_min (the smaller) on the map's resolution; R_min / 4 on an
    /// application's own validity checker. A goal pose to meet is often a manoeuvre among
    /// obstacles, which a coarse lattice cannot make (docs/planners.md, the car lattice's "Nodes").
    double poseCell() const;
    /// With @p reach > 0, the primitives sampled for a body of that reach (the grown body of
    /// the safety margin) instead of the checker's.
    CarLatticeConfig carLatticeConfig(bool hybrid, double reach = 0.0) const;
    /// The hard safety margin in use (m): `safety_margin` as set, else (auto) 0.1 m, or a
    /// quarter of the vehicle's width if less; 0 for a point vehicle, a polygon footprint or an
    /// application's own validity checker (no distance field to grow the body in).
    double safetyMargin() const;
    /// True if the last solve()'s path came from the search for the body grown by the safety
    /// margin (the first path passed nearer an obstacle, and the grown one cost at most 5 % more).
    bool lastPathKeepsMargin() const { return lastGrown_; }

protected:
    /// The cost the search minimises (default: length).
    virtual std::unique_ptr<LatticeCostModel> carCost() const { return std::make_unique<LengthCost>(); }
    void setupFamily(const std::shared_ptr<CarCollision> &collision) override;
    FamilyRun searchFamily(const ompl::base::State *start, const GoalTarget &goal, const std::function<bool()> &cancelled,
                           std::atomic<std::uint64_t> *progress) override;
    void familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const override;

private:
    /// The family's searches on @p collision (@p reach: see carLatticeConfig()).
    void setupCar(CarFamily &family, const std::shared_ptr<CarCollision> &collision, double reach);
    /// The safety margin's pass (CarLatticeMargin.cpp): where @p run's path passes nearer an
    /// obstacle than @p margin, the same query for the grown body, on an expansion budget of
    /// twice the first search's + 2 000 and within 5 % of its cost; its path replaces @p run's
    /// if it reached the goal.
    void keepMargin(FamilyRun &run, double margin, const ompl::base::State *start, const CarLatticeQuery &terms,
                    const CarPostProcessing &post, const GoalTarget &goal, const LatticeCostModel &cost,
                    const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress);
    /// The checker of the body grown by @p margin on the map as it is now (made on first use,
    /// again after the map's cells or the margin changed) and its collision model.
    const FootprintChecker &grownChecker(double margin);

    CarLatticeSettings settings_;
    CarFamily car_;
    std::unique_ptr<FootprintChecker> grown_;  ///< the body grown by grownBy_ (null: none yet)
    std::shared_ptr<CarCollision> grownCollision_;
    CarFamily grownCar_;
    double grownBy_{0.0};
    std::uint64_t grownVersion_{0};  ///< checker_'s mapVersion() grown_ was made on
    bool lastGrown_{false};
    bool grownSearched_{false};  ///< the last query ran the grown body's search (its explored states drawn too)
};

}  // namespace gridcar
