#pragma once
/// @file GridPlanner.h
/// @brief Common OMPL plumbing of the grid A* planners (one search core, see SearchCore.h).

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/planners/SearchCore.h"
#include "gridcar/spaces/GridSE2StateSpace.h"

#include <ompl/base/Planner.h>
#include <ompl/base/goals/GoalRegion.h>

#include <ompl/geometric/PathGeometric.h>

#include <array>
#include <functional>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace gridcar
{
/// The 8 lattice move directions, 45 degrees apart: 0 = +x (east), counter-clockwise, in the
/// world frame (y up). Row offsets are negative for moves towards +y (row 0 is the top).
struct Moves
{
    static constexpr int dcol[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    static constexpr int drow[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    static double yaw(int d) { return d * M_PI / 4.0; }
    /// Nearest of the 8 directions to a yaw.
    static int fromYaw(double yaw);
    /// Heading change between two directions in 45-degree steps (0..4).
    static int turn(int from, int to)
    {
        const int t = ((to - from) % 8 + 8) % 8;
        return t > 4 ? 8 - t : t;
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
    void setFreeStartHeading(bool v) { freeStartHeading_ = v; }
    void setMatchGoalHeading(bool v) { matchGoalHeading_ = v; }

    /// Statistics of the last solve().
    std::uint64_t expandedNodes() const { return lastExpanded_; }
    /// The planner's own search cost of the last solution (metres, incl. any penalties).
    double lastCost() const { return lastCost_; }
    /// Seconds spent in the search loop itself by the last solve() (no path building).
    double lastSearchSeconds() const { return lastSearchSeconds_; }
    /// Cells expanded by the last solve() (for pictures).
    std::vector<Cell> expandedCells() const;

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
    /// Hook for a planner that post-processes its lattice path (default: none). Returns true
    /// when it replaced @p path.
    virtual bool postProcess(ompl::geometric::PathGeometric &path) { (void)path; return false; }


    std::shared_ptr<GridSE2StateSpace> space_;
    const FootprintChecker *checker_{nullptr};  ///< null when the validity checker is not ours
    int width_{0}, height_{0};
    double straightStep_{1.0}, diagStep_{1.4142135623730951};
    Query query_;
    std::unique_ptr<SearchSpace> search_;
    std::uint64_t progressExpanded_{0};

private:
    bool checkMoveUncached(int col, int row, int d) const;
    bool fillMoveCache(int col, int row, int d) const;
    bool poseValid(double x, double y, double yaw) const;

    bool allowCornerCutting_{false};
    bool matchGoalHeading_{false};
    bool freeStartHeading_{false};
    const ompl::base::GoalRegion *goalRegion_{nullptr};
    mutable std::vector<std::uint8_t> moveCache_;  ///< per (cell, d): 0 unknown, 1 valid, 2 invalid
    std::uint64_t lastExpanded_{0};
    double lastCost_{0.0};
    double lastSearchSeconds_{0.0};
    std::vector<std::uint32_t> lastPath_;
    ompl::base::State *scratchA_{nullptr}, *scratchB_{nullptr};
    void freeDataStates();
    mutable std::unordered_map<std::uint32_t, ompl::base::State *> dataStates_;  ///< for getPlannerData()
};

/// Heuristics of the baseline planners (paper I's tables).
enum class GridHeuristic
{
    Zero,       ///< Dijkstra
    Manhattan,  ///< |dx| + |dy|: NOT admissible on an 8-connected grid (paper I's baseline)
    Euclidean,  ///< straight-line distance (paper C's plain A*)
    Octile      ///< exact 8-connected distance on an empty grid
};

/**
 * @brief Plain grid search over cells (heading only recorded for the path): `dijkstra`,
 * `astar-manhattan`, `astar-euclidean`, `astar-octile`. Step costs: resolution (straight) and
 * resolution * sqrt(2) (diagonal), in metres.
 *
 * @par External documentation
 * P. Hart, N. Nilsson, B. Raphael, A Formal Basis for the Heuristic Determination of Minimum
 * Cost Paths, 1968. Paper I (Yao et al. 2020), section 4, the baselines of its tables.
 */
class GridAStar : public GridPlanner
{
public:
    GridAStar(const ompl::base::SpaceInformationPtr &si, GridHeuristic h, const std::string &name);
    GridHeuristic heuristicKind() const { return heuristic_; }

protected:
    std::size_t stateCount() const override;
    std::vector<std::uint32_t> startStates(const Query &q) const override;
    SearchResult runSearch(const Query &q, const std::vector<std::uint32_t> &starts,
                           const ompl::base::PlannerTerminationCondition &ptc) override;
    void decode(std::uint32_t s, int &col, int &row, int &dir) const override;

private:
    GridHeuristic heuristic_;
};

/// Corner weights of corner-weighted A* (metres of lost distance per heading change).
struct CornerWeights
{
    double w45{2.7};   ///< paper C's value
    double w90{7.0};   ///< paper C's value
    double w135{11.3}; ///< our choice (see CornerAStar)
};

/// Speeds (m/s) at which a vehicle takes 45-, 90- and 135-degree grid corners.
struct CornerSpeeds
{
    double v45{0.0}, v90{0.0}, v135{0.0};
};

/**
 * @brief Corner-weighted A* (paper C): state = (cell, arrival direction); step cost = step
 * length + corner weight of the heading change (0 / 45 / 90 / 135 degrees). A 180-degree
 * reversal is never a successor. Heuristic: octile distance (admissible: weights are >= 0).
 *
 * Parameters (declareParam): `corner_weight_45` (2.7 m), `corner_weight_90` (7.0 m),
 * `corner_weight_135` (11.3 m: the paper gives none; we continue its two values linearly in the
 * turn angle, 7.0 + (7.0 - 2.7), which keeps a 135-degree corner dearer than a 90-degree one as
 * the physics model says while staying admissible for any weight >= 0), `weights` (paper | physics). Weights are distances in metres and
 * are NOT rescaled with the cell size: on paper C's 1 m grid a 90-degree corner costs as much
 * as 7 cells, on a 0.298 m grid as much as 23.5 cells, the same 7 m of lost driving.
 *
 * `weights = physics` derives each weight from the VehicleParams of the footprint checker as
 * v_max x (time lost braking for and leaving the corner) = (v_max - v_c)^2 / 2 x (1/a + 1/d),
 * with a / d the acceleration / deceleration and v_c the corner speed (the vehicle's
 * corner_speed_* when set, else sqrt(min(mu g, a_lat) r) with r the minimum turning radius
 * scaled by 1 / tan(theta / 2)).
 *
 * @par External documentation
 * Paper C: "Shortest driving-time path planning considering UGV driving characteristics and
 * driving time, and its driving algorithm", JKROS 2014.
 */
class CornerAStar : public GridPlanner
{
public:
    explicit CornerAStar(const ompl::base::SpaceInformationPtr &si);

    void setup() override;
    const CornerWeights &weights() const { return weights_; }
    /// Weights derived from a vehicle (the `physics` mode): for each corner angle
    /// (v_max - v_c)^2 / 2 (1/a + 1/d), v_max x the time lost braking to v_c and accelerating again.
    static CornerWeights physicsWeights(const VehicleParams &v);
    /// The corner speeds v_c physicsWeights() uses (m/s; 45, 90, 135 degrees): the vehicle's
    /// `corner_speed_*` if set, else sqrt(min(mu g, a_lat) r) with r = R_min / tan(theta / 2);
    /// never above v_max.
    static CornerSpeeds cornerSpeeds(const VehicleParams &v);

    double weight45() const { return userWeights_.w45; }
    double weight90() const { return userWeights_.w90; }
    double weight135() const { return userWeights_.w135; }
    void setWeight45(double w);
    void setWeight90(double w);
    void setWeight135(double w);
    void setWeightMode(const std::string &mode);
    std::string weightMode() const { return physics_ ? "physics" : "paper"; }

protected:
    std::size_t stateCount() const override;
    std::vector<std::uint32_t> startStates(const Query &q) const override;
    SearchResult runSearch(const Query &q, const std::vector<std::uint32_t> &starts,
                           const ompl::base::PlannerTerminationCondition &ptc) override;
    void decode(std::uint32_t s, int &col, int &row, int &dir) const override;

private:
    CornerWeights userWeights_;  ///< paper mode (declared parameters)
    CornerWeights weights_;      ///< in use
    bool physics_{false};
};

}  // namespace gridcar
