#pragma once
/// @file GridPlanner.h
/// @brief The common base of gridcar's OMPL planners: the common parameters, the world
/// (space, collision model), the goal, one solve() over the search family a subclass brings
/// (GridLatticePlanner, CarLatticePlanner), the shared solver support.

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/planners/GoalAdapter.h"
#include "gridcar/planners/GridFamily.h"
#include "gridcar/planners/PlannerReport.h"
#include "gridcar/planners/SolverSupport.h"
#include "gridcar/spaces/GridSE2StateSpace.h"

#include <ompl/base/Planner.h>
#include <ompl/geometric/PathGeometric.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gridcar
{
/// The parameters every gridcar planner declares (see GridPlanner for each).
struct GridPlannerParams
{
    bool freeStartHeading{false};    ///< `free_start_heading`
    /// `match_goal_heading`; unset (the default): true on the car lattice (a goal pose is
    /// reached with its yaw), false on the grid lattice (the papers' searches end at the goal cell)
    std::optional<bool> matchGoalHeading;
    double turningRadius{0.0};       ///< `turning_radius`, m; 0 = automatic
    double maxMemoryMb{8192.0};      ///< `max_memory_mb`; 0 = none
    double latticeCell{0.0};         ///< `lattice_cell`, m; 0 = automatic
};

/**
 * @brief Base of gridcar's planners: an ompl::base::Planner over one search family that the
 * subclass brings, the grid lattice (GridLatticePlanner: GridFamily over a node type) or the
 * car lattice (CarLatticePlanner: CarFamily over a cost model and a primitive set). What both
 * share is here, by composition: the world (the SE(2) space's lattice geometry and one
 * collision model, CarCollision: gridcar's FootprintChecker or any OMPL validity checker), the
 * goal (GoalAdapter), the solver support (SolverSupport: memory bound, statistics and progress
 * properties, the status rule), the typed report (PlannerReport).
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
 * before the next solve(). A planner declares only the parameters that act in it.
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
    /// True for the planners of the car lattice (CarLatticePlanner), false for those of the
    /// grid lattice (GridLatticePlanner).
    virtual bool usesCarLattice() const = 0;

protected:
    /// The family's part of setup(), on the world it built: the space (space_), gridcar's
    /// checker (checker_, or null) and @p collision, the collision model both families use.
    virtual void setupFamily(const std::shared_ptr<CarCollision> &collision) = 0;
    /// One search of the family from @p start to @p goal (solve() has read both, reset the
    /// statistics and bounded the memory), polling @p cancelled and counting into @p progress.
    virtual FamilyRun searchFamily(const ompl::base::State *start, const GoalTarget &goal,
                                   const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress) = 0;
    /// The explored graph of the last search, for getPlannerData().
    virtual void familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const = 0;
    /// Frees the family's records of the last search (clear()).
    virtual void clearFamily() {}
    /// The map's cells changed since the last solve() (FootprintChecker::mapVersion()): the
    /// family forgets what it learnt of them (its set-up stays).
    virtual void mapChangedFamily() {}
    /// Why the family cannot search on the world set up (solve() then returns ABORT with it as
    /// the stop reason), or "".
    virtual std::string cannotSearch() const { return ""; }
    /// Hook for a planner that post-processes its path (default: none), polling @p ptc.
    /// Returns true when it replaced @p path.
    virtual bool postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
    {
        (void)path;
        (void)ptc;
        return false;
    }
    /// Every parameter setter ends here: set-up is redone before the next solve() (whenever the
    /// parameter is set, before or after setup()).
    void parameterSet(const std::string &name)
    {
        (void)name;
        setup_ = false;
    }
    /// For postProcess(): the solution found is not to be reported exact (e.g. its smoothing
    /// was stopped by the termination condition), for the reason given (lastStopReason()).
    void markNotExact(const std::string &why) { notExactBecause_ = why; }
    /// "" when a smoothed path's last pose @p end still meets @p goal (a GoalState's heading
    /// only where it is to be matched), else why not (paper I's smoothing ends on the last
    /// leg's heading).
    static std::string endsOffGoal(const GoalTarget &goal, const Pose2 &end);
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

    GridPlannerParams params_;
    SolverSupport support_;
    GoalAdapter goals_;
    GoalTarget goal_;
    /// The collision model of the world setup() was built on (both families use it).
    std::shared_ptr<CarCollision> collision_;
    std::uint64_t mapVersion_{0};  ///< the checker's mapVersion() the collision model has seen
    std::string notExactBecause_;  ///< set through markNotExact() during one solve()
    std::shared_ptr<GridSE2StateSpace> ownSpace_;
    VehicleParams genericVehicle_;
    mutable PlannerDataStates dataStates_;  ///< for getPlannerData()
};

}  // namespace gridcar
