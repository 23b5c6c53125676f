#pragma once
/// @file TurnHeuristic.h
/// @brief The car lattice's 2D heuristic with the turning counted: distance plus the least
/// turning cost to the goal over (node, axis) states, for cost models that charge turning
/// (corner A*'s corner weights).

#include "gridcar/planners/search/ObstacleHeuristic.h"
#include "gridcar/planners/search/detail/PollSchedule.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace gridcar
{
/**
 * @brief Least cost from a node at a heading's axis to the goal over the lattice's 2D graph,
 * counting the turning: states (node, axis), an axis being a lattice heading and its reverse
 * (H / 2 of them); a state moves along its axis either way (the step's length, as
 * ObstacleHeuristic's edges, with its node and axis tests), or turns to a neighbouring axis
 * at a cost per radian of the angle between them.
 *
 * Why it bounds a lattice path (corner A*'s cost: length + a corner weight w(|turn|) per
 * primitive, w(x) >= c x, c = minTurnCostPerRad()): a primitive from heading h1 to h2 turns
 * monotonically, so its displacement lies between h1 and h2, and the 2D graph's shortest walk
 * for it takes the two step directions that bracket the displacement (adjacent lattice
 * directions, unimodular: every displacement between them is a whole combination of the two),
 * both within [h1, h2]. That walk turns its axis from h1 to h2 once, monotonically: it costs
 * at most ratio x the primitive's length in steps and c |h2 - h1| in turning. Backwards
 * primitives move along the same axis. So the walk of a whole lattice path costs at most
 * ratio x its length + c x its turning, and the search's value, with rotation costed at
 * ratio x c per radian, divided by ratio (as the 2D distance is) is a lower bound of the
 * path's cost, for every goal heading (the seeds take every axis at their cost). Its node
 * tests are those of ObstacleHeuristic (shared: asked once per node and query). Two things the
 * argument does not cover: the walk's corner node (where its two steps meet, off the curve)
 * must pass those tests; and a path that ends with the analytic shot ends between nodes at a
 * heading between the lattice's, so the walk to a seed may turn up to two gaps between
 * neighbouring headings (and the seed's offset) more than the shot. docs/planners.md ("Turn
 * bound") says what was measured and why no allowance is taken off.
 *
 * Resumable as ObstacleHeuristic (Reverse Resumable A*, directed at the query's start node by
 * the 2D distance from it, or the Euclidean one: rotations cost >= 0, moves their length), its
 * node storage kept from query to query and invalidated by a stamp. It closes every state whose
 * cost to the goal plus its guide is below the cost asked about; the 2D distance from the start
 * sees walls the straight line does not (a fifth fewer states on issue 41's Willow Garage
 * query), but neither sees the corners between the start and the state, so the search still
 * covers the routes within that corner cost.
 */
class TurnHeuristic
{
public:
    /// @p steps: the lattice's H direction vectors in cells (heading k = step k, step k + H / 2
    /// its reverse), H = 8 or 16; @p cell the node spacing, m.
    TurnHeuristic(std::vector<std::array<int, 2>> steps, double cell);

    /// Starts a search over the box of @p nodes (reset for the same query: its node tests are
    /// used) from the seeds (node, initial cost, every axis) towards the target node, turning
    /// costing @p rotationPerRad (graph units, >= 0) per radian. False (and inactive) when the
    /// box is above kMaxNodes.
    /// @p guide: the 2D distance from the target node (the query's start) over the same graph
    /// (an ObstacleHeuristic seeded there), which directs the search far better than the
    /// straight line where walls stand between; null, or where it answers < 0 or +inf: the
    /// straight-line distance. Either is consistent for this graph (its moves are the 2D
    /// graph's edges, its turns stay on a node).
    bool reset(ObstacleHeuristic &nodes, int i0, int j0, int ni, int nj,
               const std::vector<std::pair<std::array<int, 2>, double>> &seeds, int ti, int tj, double rotationPerRad,
               std::function<double(int, int)> guide = nullptr);
    /// Least cost from node (i, j) at lattice heading @p heading to the goal; +inf when
    /// unreachable or off the box; -1 when the search was cancelled before it knew.
    double distance(int i, int j, int heading);
    /// Polled as ObstacleHeuristic's.
    void setCancel(std::function<bool()> cancelled) { cancelled_ = std::move(cancelled); }
    /// States closed so far (for benchmarks).
    std::size_t closedCount() const { return closedCount_; }
    /// The largest box reset() accepts (44 bytes a node, allocated lazily by the pages touched).
    static constexpr double kMaxNodes = 1.0e8;

private:
    static constexpr int kMaxAxes = 8;
    struct Node
    {
        std::uint32_t stamp;
        std::uint8_t closed;  ///< bit a: axis a closed
        float guide;          ///< guideAt() (< 0: not asked yet)
        float g[kMaxAxes];
    };
    struct Entry
    {
        double f, g;
        std::uint32_t n;
        std::uint8_t a;
        bool operator<(const Entry &o) const { return f > o.f || (f == o.f && g < o.g); }
    };
    struct FreeNodes
    {
        void operator()(Node *p) const { std::free(p); }
    };
    bool inBox(int i, int j) const { return i >= i0_ && j >= j0_ && i < i0_ + ni_ && j < j0_ + nj_; }
    std::size_t idx(int i, int j) const { return std::size_t(j - j0_) * std::size_t(ni_) + std::size_t(i - i0_); }
    Node &at(std::size_t n);
    void relax(std::size_t n, int i, int j, int a, double g);
    bool expandUntil(std::size_t target, int axis);

    std::vector<std::array<int, 2>> steps_;
    double cell_;
    int axes_;
    std::vector<double> stepLen_;           ///< per axis
    std::vector<std::array<double, 2>> rot_;  ///< per axis: to axis a - 1, to axis a + 1 (rad)
    double rotationPerRad_{0.0};
    std::function<double(int, int)> guide_;
    double guideAt(Node &x, int i, int j);
    ObstacleHeuristic *nodes_{nullptr};
    int i0_{0}, j0_{0}, ni_{0}, nj_{0}, ti_{0}, tj_{0};
    std::unique_ptr<Node[], FreeNodes> store_;
    std::size_t storeCount_{0};
    std::uint32_t epoch_{0};
    std::vector<Entry> heap_;
    std::size_t closedCount_{0};
    std::function<bool()> cancelled_;
    PollSchedule poll_{1023};
    bool stopped_{false};
};

}  // namespace gridcar
