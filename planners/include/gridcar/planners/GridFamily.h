#pragma once
/// @file GridFamily.h
/// @brief The grid-lattice search family: the map's cells (or cells over an SE(2) space's
/// bounds), 8-connected moves cached over the collision model, and node types (GridNodes) that
/// say what a search state is: a cell (plain A*), a cell and its arrival direction (paper C), a
/// cell, heading and straight run (paper I).

#include "gridcar/core/Memory.h"
#include "gridcar/planners/GoalAdapter.h"
#include "gridcar/planners/SolverSupport.h"
#include "gridcar/planners/search/AStar.h"
#include "gridcar/planners/search/CarCollision.h"
#include "gridcar/spaces/GridSE2StateSpace.h"
#include "gridcar/spaces/Lattice.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gridcar
{
/// Row-major index of a map cell and back: the cell part of every grid search state (32 bits:
/// the dense lattices of the grid planners).
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

/// The query in grid-lattice terms.
struct GridQuery
{
    int startCol{0}, startRow{0};
    int startDir{-1};  ///< -1: free start heading
    /// A cell to aim at (every goal kind but a plain region): the cell of the GoalState, of the
    /// PositionGoal's position or of the region's sample. The heuristics measure to it, and
    /// reaching it at an accepted arrival direction ends the search.
    bool goalKnown{false};
    int goalCol{0}, goalRow{0};
    std::uint8_t goalDirs{0xFF};  ///< arrival directions accepted in the goal cell (bit d); a
                                  ///< node type without directions is always accepted there
    /// The goal's own test also runs at every expanded cell's centre: regions, and a
    /// PositionGoal whose tolerance reaches another cell's centre.
    bool regionTest{false};
    /// Metres taken off the heuristics (never below 0) so that they stay lower bounds to a
    /// cell satisfying the goal that is not the target cell (a position tolerance).
    double goalSlack{0.0};
};

class GridFamily;

/**
 * @brief A node type of the grid lattice: what a search state is, where a query starts, its
 * successors and costs (an expander run by astar()), and the records of the last search.
 * Records default to the family's dense SearchSpace (denseStates() of them); a node type with
 * a growing state set keeps its own and overrides parent(), g() and forEachClosed().
 */
class GridNodes
{
public:
    virtual ~GridNodes() = default;
    /// Dense search states the family allocates for this node type, or 0 for none.
    virtual std::size_t denseStates(const GridFamily &f) const = 0;
    /// The search states the query of @p f starts from.
    virtual std::vector<std::uint32_t> starts(const GridFamily &f) = 0;
    /// Runs astar() over this node type, polling @p cancelled and writing @p progress.
    virtual SearchResult search(GridFamily &f, const std::vector<std::uint32_t> &starts,
                                const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress) = 0;
    /// Cell and arrival direction (-1: none) of a search state.
    virtual void decode(const GridFamily &f, std::uint32_t s, int &col, int &row, int &dir) const = 0;
    virtual std::uint32_t parent(const GridFamily &f, std::uint32_t s) const;
    virtual double g(const GridFamily &f, std::uint32_t s) const;
    /// Calls @p fn for every state the last search expanded.
    virtual void forEachClosed(const GridFamily &f, const std::function<void(std::uint32_t)> &fn) const;
    /// Frees the records of the last search (GridPlanner::clear()).
    virtual void clear() {}
};

/// What a search family returns from one query.
struct FamilyRun
{
    SearchEnd end;
    std::uint64_t expanded{0};
    double cost{0.0};          ///< the search's own cost of the path
    double searchSeconds{0.0};  ///< the search loop alone
};

/**
 * @brief The grid lattice: cells of a GridSE2StateSpace, moves in 8 directions, and a cache
 * of move validity that decorates the collision model (CarCollision). A move from a cell in
 * direction d is valid when the target is on the lattice, for a diagonal both side cells are
 * free unless corner cutting is allowed (the Moving AI rule), and the footprint at the move's
 * heading is free along the move (CarCollision::segmentFree(); a point vehicle on gridcar's
 * checker: the target cell).
 *
 * A query starts at the start state's cell and yaw (nearest of 8 directions), or any heading
 * when the start heading is free. Its goal is the cell of the pose the goal gives to aim at (a
 * GoalState's, with its heading when it must match; a PositionGoal's position, with an arrival
 * direction within its yaw tolerance or nearest its yaw; a sampleable region's sample), and
 * for regions, and a PositionGoal whose tolerance reaches beyond its cell, also any cell whose
 * centre satisfies the goal's own test. The path is the cell centres, each at the heading of
 * the move into it, then, where it ends in the target cell, the goal's pose: the GoalState
 * itself, the PositionGoal's exact position (at the arrival heading, or the goal's yaw where
 * the arrival is outside its tolerance; the nearest free heading where the vehicle does not
 * fit at it), the region's sample. A search that does not reach the goal returns the path to
 * the explored cell nearest it (closeness()).
 */
class GridFamily
{
public:
    /// Prepares the lattice of @p space over @p collision for @p nodes. Returns "" or, when
    /// the move cache and dense records alone would exceed @p maxMemoryMb (> 0), the reason
    /// (nothing is allocated then).
    std::string setup(std::shared_ptr<const GridSE2StateSpace> space, std::shared_ptr<CarCollision> collision,
                      std::unique_ptr<GridNodes> nodes, double maxMemoryMb);
    /// Forgets the cached move validity (a new map, or corner cutting switched).
    void forgetMoves() { moveCache_.zero(); }
    void setAllowCornerCutting(bool v)
    {
        if (v != allowCornerCutting_) forgetMoves();
        allowCornerCutting_ = v;
    }
    bool allowCornerCutting() const { return allowCornerCutting_; }

    /// One query: start state and goal, the search, the path (see the class comment).
    FamilyRun solve(const ompl::base::SpaceInformationPtr &si, const ompl::base::State *start, bool freeStartHeading,
                    const GoalTarget &goal, const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress);
    /// The explored graph of the last search.
    void plannerData(ompl::base::PlannerData &data, PlannerDataStates &states) const;
    /// Frees the last search's records (the move cache, which depends only on the map, stays).
    void clear()
    {
        if (nodes_) nodes_->clear();
    }

    // what the node types ask (valid after setup())
    const GridSE2StateSpace &space() const { return *space_; }
    const CarCollision &collision() const { return *collision_; }
    const GridQuery &query() const { return query_; }
    int width() const { return width_; }
    int height() const { return height_; }
    CellIndex cellIndex() const { return {std::uint32_t(width_)}; }
    /// Step length of direction d in metres (the cell size, or it times sqrt 2).
    double stepLength(int d) const { return (d & 1) ? diagStep_ : straightStep_; }
    /// Octile distance in metres between two cells (admissible for 8-connected moves).
    double octile(int c0, int r0, int c1, int r1) const;
    /// True if the cell (with arrival direction @p dir, -1 = none) satisfies the goal.
    bool isGoal(int col, int row, int dir) const;
    /// A heuristic's distance to the target cell as a lower bound to the goal (less goalSlack).
    double towardGoal(double h) const { return std::max(0.0, h - query_.goalSlack); }
    /// How near the centre of a cell is to the goal, the order of the approximate answer (the
    /// explored state nearest the goal): the squared distance to the position aimed at, or for
    /// a plain region the goal's own distance (ompl::base::Goal::isSatisfied()'s).
    double closeness(int col, int row, int dir) const;
    /// Cached validity of the move from (col, row) in direction d (see the class comment).
    bool moveValid(int col, int row, int d) const
    {
        const std::uint8_t c = moveCache_[(std::size_t(row) * std::size_t(width_) + std::size_t(col)) * 8 + std::size_t(d)];
        if (c != 0) return c == 1;
        return fillMoveCache(col, row, d);
    }
    /// The dense records (node types with denseStates() > 0).
    SearchSpace &dense() { return *dense_; }
    const SearchSpace &dense() const { return *dense_; }

private:
    bool checkMoveUncached(int col, int row, int d) const;
    void readGoal(const GoalTarget &goal);
    /// The last pose of a path that reached the target cell at @p arrivalYaw: the goal's own
    /// pose there (see the class comment).
    Pose2 goalPose(const GoalTarget &goal, double arrivalYaw) const;
    /// The straight leg from the last cell's centre to the goal's pose is free (the body along
    /// it at the leg's heading, and at the goal pose): else the path ends at the centre.
    bool lastLegFree(const Pose2 &from, const Pose2 &to) const;
    bool fillMoveCache(int col, int row, int d) const;

    std::shared_ptr<const GridSE2StateSpace> space_;
    std::shared_ptr<CarCollision> collision_;
    std::unique_ptr<GridNodes> nodes_;
    int width_{0}, height_{0};
    double straightStep_{1.0}, diagStep_{1.4142135623730951};
    bool allowCornerCutting_{false};
    GridQuery query_;
    const GoalTarget *goal_{nullptr};
    std::unique_ptr<SearchSpace> dense_;
    mutable ZeroedBytes moveCache_;  ///< per (cell, d): 0 unknown, 1 valid, 2 invalid
};

}  // namespace gridcar
