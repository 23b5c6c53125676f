#pragma once
/// @file GridPlanner.h
/// @brief The OMPL planner class of gridcar's searches: parameters, the world (space,
/// collision model), one solve() over a search family (GridFamily or CarFamily), the shared
/// solver support.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/planners/CarFamily.h"
#include "gridcar/planners/GoalAdapter.h"
#include "gridcar/planners/GridFamily.h"
#include "gridcar/planners/PlannerReport.h"
#include "gridcar/planners/search/CarLatticeSettings.h"
#include "gridcar/planners/SolverSupport.h"
#include "gridcar/spaces/GridSE2StateSpace.h"

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstdint>
#include <memory>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace gridcar
{
/// The parameters every gridcar planner declares (see GridPlanner for each).
struct GridPlannerParams
{
    bool allowCornerCutting{false};  ///< `allow_corner_cutting` (grid lattice)
    bool freeStartHeading{false};    ///< `free_start_heading`
    /// `match_goal_heading`; unset (the default): true on the car lattice (a goal pose is
    /// reached with its yaw), false on the grid lattice (the papers' searches end at the goal cell)
    std::optional<bool> matchGoalHeading;
    double turningRadius{0.0};       ///< `turning_radius`, m; 0 = automatic
    double maxMemoryMb{8192.0};      ///< `max_memory_mb`; 0 = none
    double latticeCell{0.0};         ///< `lattice_cell`, m; 0 = automatic
    /// The car lattice's settings (its planners declare them: CarLatticeParams.h); the search
    /// reads them as they are (CarLatticeQuery::settings)
    CarLatticeSettings car;
};

/**
 * @brief Base of gridcar's planners: an ompl::base::Planner that searches one of two families,
 * the grid lattice (GridFamily, over a node type the planner supplies: makeGridNodes()) or the
 * car lattice (CarFamily, with the cost model the planner supplies: carCost()), chosen by
 * usesCarLattice(). What both share is composed in: the world (the SE(2) space's lattice
 * geometry and one collision model, CarCollision: gridcar's FootprintChecker or any OMPL
 * validity checker), the goal (GoalAdapter), the solver support (SolverSupport: memory
 * bound, statistics and progress properties, the status rule).
 *
 * Start: the start state (its yaw, or a free heading with `free_start_heading` = true); an
 * invalid start is INVALID_START. Goals: a GoalState (its heading if `match_goal_heading`,
 * by default on the car lattice), gridcar's PositionGoal, or any other GoalRegion; an
 * unreachable goal pose is INVALID_GOAL. `solve()` honours its termination condition and
 * `max_memory_mb`, returns the path to the explored state nearest the goal when it stops
 * early (APPROXIMATE_SOLUTION or TIMEOUT), and sets itself up again when the application has
 * set another validity checker or motion validator since setup().
 *
 * Every parameter setter validates its value (std::invalid_argument), and redoes set-up
 * before the next solve(); a parameter set explicitly that does not act in the family the
 * planner is configured for makes setup() throw std::invalid_argument with the reason.
 */
class GridPlanner : public ompl::base::Planner, public ReportingPlanner
{
public:
    GridPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);
    ~GridPlanner() override;

    void setup() override;
    void clear() override;
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void getPlannerData(ompl::base::PlannerData &data) const override;

    /// All common parameters.
    const GridPlannerParams &commonParams() const { return params_; }
    bool allowCornerCutting() const { return params_.allowCornerCutting; }
    /// Grid lattice: a diagonal move may cut past a blocked side cell (default false: the
    /// Moving AI rule).
    void setAllowCornerCutting(bool v);
    /// A GoalState's heading must be matched: as set, else true on the car lattice (a goal pose
    /// given with a yaw is reached with that yaw; for a free heading give a PositionGoal) and
    /// false on the grid lattice (the papers' searches: any arrival heading).
    bool matchGoalHeading() const;
    void setMatchGoalHeading(bool v);
    /// When true the start state's yaw is ignored (any first move costs no corner).
    bool freeStartHeading() const { return params_.freeStartHeading; }
    void setFreeStartHeading(bool v);

    /// The last solve()'s report: expansions, search cost, stop reason, which family searched.
    PlannerReport lastReport() const override;
    /// Statistics of the last solve().
    std::uint64_t expandedNodes() const { return support_.expanded(); }
    /// The planner's own search cost of the last solution (metres, incl. any penalties).
    double lastCost() const { return support_.cost(); }
    /// Seconds spent in the search loop itself by the last solve() (no path building).
    double lastSearchSeconds() const { return support_.searchSeconds(); }
    /// Memory bound (`max_memory_mb`, MB; 0 = none; default 8192, a third of a 24 GB
    /// machine): solve() stops when the process's resident memory exceeds it (checked every
    /// 10 ms through the termination condition), and returns APPROXIMATE_SOLUTION with the
    /// path to the explored state nearest the goal, or ABORT when there is none;
    /// lastStopReason() says why. setup() refuses grid-lattice arrays larger than it.
    double maxMemoryMb() const { return params_.maxMemoryMb; }
    void setMaxMemoryMb(double mb);
    /// Why the last solve() returned no exact solution though not out of time: stopped at the
    /// memory bound, or (a planner that smooths) its smoothed path failed checkDrivable() and is
    /// returned as an approximate solution. Empty otherwise.
    const std::string &lastStopReason() const { return support_.stopReason(); }

    /// Turning radius of the car lattice's arcs (`turning_radius`, m); 0 = automatic: the
    /// vehicle's R_min with gridcar's checker, the space's radius on OMPL's Dubins or
    /// Reeds-Shepp space, else the default car's (VehicleParams{}: 3.86 m).
    double turningRadiusParam() const { return params_.turningRadius; }
    void setTurningRadius(double r);
    /// The turning radius in use (see turningRadiusParam()).
    double turningRadius() const;
    /// The vehicle whose limits the planner uses: gridcar's checker's, or on any other
    /// validity checker the default car with its steering set to turningRadius().
    const VehicleParams &vehicle() const { return checker_ ? checker_->vehicle() : genericVehicle_; }

    /// Lattice cell size in metres; 0 = automatic (lattice_cell). Car lattice: the multiple of
    /// the map resolution nearest to min(width, R_min) / 4, at least one map cell (R_min / 4
    /// without gridcar's checker). Grid lattice: the map's cells on gridcar's space; on any
    /// other SE(2) space cells of this size over the space's bounds (automatic: R_min / 4).
    double latticeCell() const { return params_.latticeCell; }
    void setLatticeCell(double m);
    /// The car lattice's settings as set (`headings`, `heuristic_weight`, `reverse`,
    /// `reverse_penalty`, `cusp_penalty`, `curve_heuristic`, `primitives`,
    /// `continuous_curvature`, `curvature_rate`, `cost_layer_weight`, `turns`, `shortcut`: see
    /// CarLatticeSettings and docs/planners.md). Each is an OMPL parameter of the planners that
    /// search the car lattice, parsed in its setter (std::invalid_argument naming the value and
    /// what is accepted); `reverse=on` is refused by setup() on a Dubins space, which is
    /// forward-only. The `curve_heuristic` bound: `table` reads it from the lattice's
    /// CurveTable (node offsets within 10 R_min per axis, kept across queries; none in the
    /// hybrid fallback), `exact` computes it at every state within 30 R_min (CurveBound).
    const CarLatticeSettings &carSettings() const { return params_.car; }
    /// All car-lattice settings at once (each field that differs counts as set explicitly).
    void setCarSettings(const CarLatticeSettings &s);
    /// True if the car lattice drives backwards as configured (`reverse` on, or auto off a
    /// Dubins space).
    bool reversing() const;
    /// True on OMPL's Dubins space (forward only: `reverse=on` refused, `auto` off).
    bool onDubinsSpace() const;
    /// Cost of a gear change (m of length-equivalent cost): `cusp_penalty` as set, else from
    /// the vehicle: the distance its stop and start at a manoeuvring speed cost (see
    /// gearChangeDistance()).
    double cuspPenalty() const;
    /// The range the curve heuristic covers (m; 0: off, or no car lattice set up).
    double curveWithin() const;
    /// True if a found path is shortcut as configured (`shortcut`, `reverse`).
    bool shortcutting() const
    {
        return params_.car.shortcut == AutoSwitch::On || (params_.car.shortcut == AutoSwitch::Auto && reversing());
    }
    /// The curvature rate the car lattice's paths keep (1/m^2; 0: not smoothed).
    double curvatureRate() const;

    /// True if the planner, as configured, searches the car lattice.
    virtual bool usesCarLattice() const { return false; }
    /// The car lattice in use after setup() (null on the grid lattice).
    const CarLatticeSearch *carSearch() const { return usesCarLattice() ? car_.search() : nullptr; }
    /// The primitive set setup() gives the car lattice for this map and vehicle (with
    /// `primitives=auto`, the lattice's; carLatticeConfig(true) is its hybrid fallback).
    CarLatticeConfig carLatticeConfig() const;
    CarLatticeConfig carLatticeConfig(bool hybrid) const;

protected:
    /// The grid lattice's node type for this planner as configured (called by setup() when
    /// usesCarLattice() is false; default: none, a planner of the car lattice only).
    virtual std::unique_ptr<GridNodes> makeGridNodes() { return nullptr; }
    /// The cost the car lattice search minimises (default: length).
    virtual std::unique_ptr<LatticeCostModel> carCost() const { return std::make_unique<LengthCost>(); }
    /// Hook for a planner that post-processes its path (default: none), polling @p ptc.
    /// Returns true when it replaced @p path.
    virtual bool postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
    {
        (void)path;
        (void)ptc;
        return false;
    }
    /// Every parameter setter ends here: set-up is redone before the next solve() (whenever the
    /// parameter is set, before or after setup()), and the name is remembered for setup()'s
    /// check that it acts in the planner as configured.
    void parameterSet(const std::string &name)
    {
        setParams_.insert(name);
        setup_ = false;
    }
    /// Parameters that act only on the grid lattice (the papers' searches on the map's cells):
    /// setup() refuses them, set explicitly, on a planner configured for the car lattice.
    virtual std::vector<std::string> gridLatticeOnlyParams() const { return {"allow_corner_cutting"}; }
    /// Parameters that act only on the car lattice: setup() refuses them on the grid lattice
    /// (the car-lattice settings' names).
    virtual std::vector<std::string> carLatticeOnlyParams() const;
    /// For postProcess(): the solution found is not to be reported exact (e.g. its smoothing
    /// was stopped by the termination condition), for the reason given (lastStopReason()).
    void markNotExact(const std::string &why) { notExactBecause_ = why; }
    /// "" when a smoothed path's last pose @p end still meets @p goal (a GoalState's heading
    /// only where it is to be matched), else why not (paper I's smoothing ends on the last
    /// leg's heading).
    static std::string endsOffGoal(const GoalTarget &goal, const Pose2 &end);
    /// Declares the car lattice's settings (CarLatticeParams.h), for the planners that search it.
    void declareCarLatticeParams();
    /// Size of the lattice cells of the grid family (after setup()).
    double cellSize() const { return space_->cellSize(); }

    std::shared_ptr<GridSE2StateSpace> space_;  ///< lattice geometry (after setup())
    const FootprintChecker *checker_{nullptr};  ///< null when the validity checker is not ours

private:
    /// On an SE(2) space that is not gridcar's: the lattice geometry from the bounds and
    /// lattice_cell (GridPlannerSpace.cpp).
    std::shared_ptr<GridSE2StateSpace> ownGridSpace();
    VehicleParams genericVehicle() const;
    /// The first valid start of the problem, every solve() (OMPL's input states hand each
    /// start out once; a second solve() without clear() must still see it).
    const ompl::base::State *currentStart();
    /// std::invalid_argument naming a parameter set explicitly that does not act as configured.
    void checkParametersAct() const;

    GridPlannerParams params_;
    SolverSupport support_;
    GoalAdapter goals_;
    GoalTarget goal_;
    /// The collision model of the world setup() was built on (both families use it).
    std::shared_ptr<CarCollision> collision_;
    GridFamily grid_;
    CarFamily car_;
    std::string tooBig_;  ///< set by setup() when the grid lattice's arrays exceed the bound
    std::string notExactBecause_;  ///< set through markNotExact() during one solve()
    std::set<std::string> setParams_;  ///< every parameter set explicitly (parameterSet())
    std::shared_ptr<GridSE2StateSpace> ownSpace_;
    VehicleParams genericVehicle_;
    mutable PlannerDataStates dataStates_;  ///< for getPlannerData()
};

}  // namespace gridcar
