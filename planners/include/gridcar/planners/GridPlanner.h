#pragma once
/// @file GridPlanner.h
/// @brief Common OMPL plumbing of the grid A* planners (one search core, search/AStar.h).

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Memory.h"
#include "gridcar/planners/search/AStar.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/spaces/GridSE2StateSpace.h"
#include "gridcar/spaces/Lattice.h"

#include <ompl/base/Planner.h>
#include <ompl/base/goals/GoalRegion.h>

#include <ompl/geometric/PathGeometric.h>

#include <array>
#include <atomic>
#include <functional>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace gridcar
{
/// Row-major index of a map cell and back: the cell part of every grid planner's search state
/// (32 bits: the dense lattices of the grid planners).
struct CellIndex
{
    std::uint32_t width;
    std::uint32_t of(int col, int row) const { return std::uint32_t(row) * width + std::uint32_t(col); }
    void split(std::uint32_t index, int &col, int &row) const
    {
        col = int(index % width);
        row = int(index / width);
    }
};

/**
 * @brief Base of the grid planners: an ompl::base::Planner over a GridSE2StateSpace.
 *
 * Handles what every grid planner shares: start / goal to lattice conversion, INVALID_START /
 * INVALID_GOAL (off the map or in collision), the termination condition (polled every 256
 * expansions), exact and approximate solutions (the expanded state closest to the goal by the
 * heuristic), PlannerData of the explored graph, the progress property "expanded nodes
 * INTEGER", and cached move validity: a move from a cell in one of 8 directions is valid when
 * the target is on the map, for a diagonal both side cells are free unless corner cutting is
 * allowed (parameter `allow_corner_cutting`, default false: the Moving AI rule), and the
 * vehicle footprint at the move's heading is free along the swept motion
 * (FootprintChecker::isMotionValid, both end poses included). With a validity checker that is
 * not gridcar's, SpaceInformation::isValid / checkMotion are used instead.
 *
 * Start: the start state's cell and yaw (nearest of 8 directions), or a free heading with
 * `free_start_heading` = true. Goals: a GoalState (its cell; its heading only if
 * `match_goal_heading` is true), or any
 * other GoalRegion, tested with isSatisfied() on the cell centre when a state is expanded.
 */
class GridPlanner : public ompl::base::Planner
{
public:
    GridPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);
    ~GridPlanner() override;

    void setup() override;
    void clear() override;
    ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
    void getPlannerData(ompl::base::PlannerData &data) const override;

    bool allowCornerCutting() const { return allowCornerCutting_; }
    void setAllowCornerCutting(bool v);
    bool matchGoalHeading() const { return matchGoalHeading_; }
    /// When true the start state's yaw is ignored (any first move costs no corner).
    bool freeStartHeading() const { return freeStartHeading_; }
    void setFreeStartHeading(bool v)
    {
        freeStartHeading_ = v;
        parameterSet("free_start_heading");
    }
    void setMatchGoalHeading(bool v)
    {
        matchGoalHeading_ = v;
        parameterSet("match_goal_heading");
    }

    /// Statistics of the last solve().
    std::uint64_t expandedNodes() const { return lastExpanded_; }
    /// The planner's own search cost of the last solution (metres, incl. any penalties).
    double lastCost() const { return lastCost_; }
    /// Seconds spent in the search loop itself by the last solve() (no path building).
    double lastSearchSeconds() const { return lastSearchSeconds_; }
    /// Memory bound (`max_memory_mb`, MB; 0 = none; default 8192, a third of a 24 GB
    /// machine): solve() stops when the process's resident memory exceeds it (checked every
    /// 10 ms through the termination condition), and returns APPROXIMATE_SOLUTION with the
    /// path to the explored state nearest the goal, or ABORT when there is none;
    /// lastStopReason() says why.
    double maxMemoryMb() const { return maxMemoryMb_; }
    void setMaxMemoryMb(double mb);  // takes effect at the next setup() for the per-map arrays
    /// Why the last solve() returned no exact solution though not out of time: stopped at the
    /// memory bound, or (a planner that smooths) its smoothed path failed checkDrivable() and is
    /// returned as an approximate solution. Empty otherwise.
    const std::string &lastStopReason() const { return lastStopReason_; }

    /// Turning radius of the car lattice's arcs (`turning_radius`, m); 0 = automatic: the
    /// vehicle's R_min with gridcar's checker, the space's radius on OMPL's Dubins or
    /// Reeds-Shepp space, else the default car's (VehicleParams{}: 3.86 m).
    double turningRadiusParam() const { return turningRadius_; }
    void setTurningRadius(double r);
    /// The turning radius in use (see turningRadiusParam()).
    double turningRadius() const;
    /// The vehicle whose limits the planner uses: gridcar's checker's, or on any other
    /// validity checker the default car with its steering set to turningRadius().
    const VehicleParams &vehicle() const { return checker_ ? checker_->vehicle() : genericVehicle_; }

    // The car lattice (search/CarLattice.h), for the planners that search it.
    /// Lattice cell size in metres; 0 = automatic (lattice_cell). Car lattice: the multiple of
    /// the map resolution nearest to min(width, R_min) / 4, at least one map cell (R_min / 4
    /// without gridcar's checker). Grid lattice: the map's cells on gridcar's space; on any
    /// other SE(2) space cells of this size over the space's bounds (automatic: R_min / 4).
    double latticeCell() const { return latticeCell_; }
    void setLatticeCell(double m);
    /// Heading count of the car lattice: 8 or 16 (`headings`).
    int latticeHeadings() const { return latticeHeadings_; }
    void setLatticeHeadings(int h);
    /// Heuristic weight on the car lattice (`heuristic_weight`, >= 1; see CarLatticeQuery).
    double heuristicWeight() const { return heuristicWeight_; }
    void setHeuristicWeight(double w);
    /// True if the planner, as configured, searches the car lattice.
    virtual bool usesCarLattice() const { return false; }
    /// The car lattice in use after setup() (null on the grid lattice).
    const CarLatticeSearch *carSearch() const { return car_.get(); }
    /// The configuration setup() gives the car lattice for this map and vehicle.
    CarLatticeConfig carLatticeConfig() const;

    /// The query in lattice terms.
    struct Query
    {
        int startCol{0}, startRow{0};
        int startDir{-1};  ///< -1: free start heading
        bool goalIsState{false};
        int goalCol{0}, goalRow{0};
        int goalDir{-1};  ///< -1: any heading
    };


    // Queries the expanders of the search core use (valid after setup()).
    /// True if the cell (with arrival direction @p dir, -1 = none) satisfies the goal.
    bool isGoal(int col, int row, int dir) const;
    /// Cached validity of the move from (col, row) in direction d (see the class comment).
    bool moveValid(int col, int row, int d) const
    {
        const std::uint8_t c = moveCache_[(std::size_t(row) * std::size_t(width_) + std::size_t(col)) * 8 + std::size_t(d)];
        if (c != 0) return c == 1;
        return fillMoveCache(col, row, d);
    }
    /// Step length of direction d in metres (resolution or resolution * sqrt 2).
    double stepLength(int d) const { return (d & 1) ? diagStep_ : straightStep_; }
    /// The cell indexing of this map (after setup()).
    CellIndex cellIndex() const { return {std::uint32_t(width_)}; }
    /// Octile distance in metres between two cells (admissible for 8-connected moves).
    double octile(int c0, int r0, int c1, int r1) const;

protected:
    /// Number of search states (cells x headings the planner distinguishes).
    virtual std::size_t stateCount() const = 0;
    /// The search states a query starts from.
    virtual std::vector<std::uint32_t> startStates(const Query &q) const = 0;
    /// Runs the search (through gridcar::astar) for the query.
    virtual SearchResult runSearch(const Query &q, const std::vector<std::uint32_t> &starts,
                                   const ompl::base::PlannerTerminationCondition &ptc) = 0;
    /// Cell (and arrival direction, -1 if the state has none) of a search state.
    virtual void decode(std::uint32_t s, int &col, int &row, int &dir) const = 0;
    /// True if the planner searches the dense SearchSpace `search_` (allocated by setup());
    /// a planner with its own search space returns false and overrides the three below.
    virtual bool usesDenseSearch() const { return true; }
    /// Parent and g of a state of the last search.
    virtual std::uint32_t parentOf(std::uint32_t s) const { return search_->parent(s); }
    virtual double gOf(std::uint32_t s) const { return search_->g(s); }
    /// Calls fn(s) for every state the last search expanded.
    virtual void forEachClosed(const std::function<void(std::uint32_t)> &fn) const;
    /// Hook for a planner that post-processes its lattice path (default: none), polling @p ptc.
    /// Returns true when it replaced @p path.
    virtual bool postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
    {
        (void)path;
        (void)ptc;
        return false;
    }
    /// The cost the car lattice search minimises (a planner that uses it overrides this).
    virtual std::unique_ptr<LatticeCostModel> carCost() const { return std::make_unique<LengthCost>(); }
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
    /// Parameters that act only on the car lattice: setup() refuses them on the grid lattice.
    virtual std::vector<std::string> carLatticeOnlyParams() const { return {"headings", "heuristic_weight"}; }
    /// For postProcess(): the solution found is not to be reported exact (e.g. its smoothing
    /// was stopped by the termination condition), for the reason given (lastStopReason()).
    void markNotExact(const std::string &why) { notExactBecause_ = why; }
    /// Declares `lattice_cell` and `headings` (for the planners that search the car lattice).
    void declareCarLatticeParams();


    std::shared_ptr<GridSE2StateSpace> space_;
    const FootprintChecker *checker_{nullptr};  ///< null when the validity checker is not ours
    int width_{0}, height_{0};
    double straightStep_{1.0}, diagStep_{1.4142135623730951};
    Query query_;
    std::unique_ptr<SearchSpace> search_;
    /// Read by OMPL's Benchmark progress thread while solve() writes it.
    std::atomic<std::uint64_t> progressExpanded_{0};

private:
    ompl::base::PlannerStatus solveCarLattice(const ompl::base::PlannerTerminationCondition &ptc);
    bool carGoal(CarLatticeQuery &q, ompl::base::PlannerStatus &bad);
    void getCarPlannerData(ompl::base::PlannerData &data) const;
    double latticeCell_{0.0};
    int latticeHeadings_{16};
    double heuristicWeight_{1.1};
    std::unique_ptr<CarLatticeSearch> car_;
    mutable std::vector<ompl::base::State *> carDataStates_;
    bool checkMoveUncached(int col, int row, int d) const;
    bool fillMoveCache(int col, int row, int d) const;
    bool poseValid(double x, double y, double yaw) const;
    /// On an SE(2) space that is not gridcar's: the lattice geometry from the bounds and
    /// lattice_cell (GridPlannerSpace.cpp).
    std::shared_ptr<GridSE2StateSpace> ownGridSpace();
    VehicleParams genericVehicle() const;
    std::shared_ptr<GridSE2StateSpace> ownSpace_;
    VehicleParams genericVehicle_;
    /// The validity checker and motion validator setup() built on, held so that what was
    /// built on them (checker_, the move cache, the car lattice) never outlives them; solve()
    /// sets up again when the application has set others on the SpaceInformation.
    ompl::base::StateValidityCheckerPtr builtOnChecker_;
    ompl::base::MotionValidatorPtr builtOnMotion_;
    bool builtOnCurrentWorld() const;
    /// The first valid start of the problem, every solve() (OMPL's input states hand each
    /// start out once; a second solve() without clear() must still see it).
    const ompl::base::State *currentStart();
    double turningRadius_{0.0};

    /// @p ptc or'ed with the memory bound (and the stop state reset).
    ompl::base::PlannerTerminationCondition withMemoryBound(const ompl::base::PlannerTerminationCondition &ptc);
    /// The status a solve() that stopped at the memory bound returns, with a warning.
    ompl::base::PlannerStatus memoryStatus(bool pathAdded) const;
    double maxMemoryMb_{8192.0};
    std::string tooBig_;  ///< set by setup() when the grid lattice's arrays exceed the bound
    bool memoryStopped_{false};
    std::string lastStopReason_;
    std::string notExactBecause_;  ///< set through markNotExact() during one solve()
    std::set<std::string> setParams_;  ///< every parameter set explicitly (parameterSet())
    /// std::invalid_argument naming a parameter set explicitly that does not act as configured.
    void checkParametersAct() const;
    bool allowCornerCutting_{false};
    bool matchGoalHeading_{false};
    bool freeStartHeading_{false};
    const ompl::base::GoalRegion *goalRegion_{nullptr};
    mutable ZeroedBytes moveCache_;  ///< per (cell, d): 0 unknown, 1 valid, 2 invalid
    std::atomic<std::uint64_t> lastExpanded_{0};
    // read by the progress properties, which OMPL's Benchmark polls from another thread
    std::atomic<double> lastCost_{0.0};
    std::atomic<double> lastSearchSeconds_{0.0};
    std::vector<std::uint32_t> lastPath_;
    ompl::base::State *scratchA_{nullptr}, *scratchB_{nullptr};
    void freeDataStates();
    mutable std::unordered_map<std::uint32_t, ompl::base::State *> dataStates_;  ///< for getPlannerData()
};

}  // namespace gridcar
