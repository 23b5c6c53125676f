#pragma once
/// @file ObstacleHeuristic.h
/// @brief The obstacle-aware heuristic of the car lattice: shortest 2D distances to the goal
/// over the lattice nodes where the vehicle fits, computed backwards from the goal on demand.

#include "gridcar/planners/search/detail/PollSchedule.h"

#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <functional>
#include <limits>
#include <vector>

namespace gridcar
{
/**
 * @brief Distance to the goal over a grid of nodes, ignoring heading and curvature: the
 * relaxation Hybrid A* planners combine (max) with their geometric heuristics.
 *
 * The graph: nodes (i, j) in a box, an edge along each of the given steps (in cells, taken
 * both ways) of length cell x |step| between two traversable nodes. The search runs backwards
 * from the goal seeds and is resumable (Silver's Reverse Resumable A*, "Cooperative
 * pathfinding", AIIDE 2005): it is directed at one target node (the query's start) by the
 * consistent Euclidean heuristic, so it closes only the nodes it must, and distance() of a node
 * not closed yet resumes it until that node is closed or the graph is exhausted. A closed
 * node's distance is exact for this graph.
 *
 * With setAxisTest() an edge also needs the car to fit at both nodes lined up with it (at the
 * step's heading or its reverse): a long car then cannot slip sideways through a gap it could
 * only pass lengthwise. This is a relaxation of a lattice path made of straight primitives; a
 * turn primitive's nodes are lined up with its two headings, not with the 2D steps that join
 * them, so in tight turns the bound may be exceeded (the tests measure by how much).
 *
 * Why it bounds a car lattice path from below: every node of a lattice path is traversable
 * (the car stands there at a lattice heading), and a primitive from node a to node b is at
 * least |b - a| long. The graph distance between a and b may exceed |b - a|, by at most the
 * octile excess (8.2 %) for 8 steps and 2.7 % for 16 steps in open space, and more where the
 * 2D route must go round an obstacle the primitive's curve passes. So it is admissible up to
 * that factor; CarLatticeSearch divides it by the measured worst ratio of graph distance to
 * primitive length, and the tests measure what remains against exhaustive search.
 */
class ObstacleHeuristic
{
public:
    /// @p traversable is asked at most once per node and search.
    ObstacleHeuristic(std::vector<std::array<int, 2>> steps, double cell, std::function<bool(int, int)> traversable);

    /// Starts a new search over nodes i in [i0, i0 + ni), j in [j0, j0 + nj) from the seeds
    /// (node, initial cost) towards the target node. The node storage is kept from search to
    /// search and invalidated by a stamp, not cleared: a query pays for the nodes it touches,
    /// not for the size of the map. Throws std::invalid_argument for an empty box or one above
    /// 4e8 nodes.
    void reset(int i0, int j0, int ni, int nj, const std::vector<std::pair<std::array<int, 2>, double>> &seeds, int ti,
               int tj);
    /// Shortest distance (m) from node (i, j) to the goal; +inf when unreachable or off the box;
    /// -1 when the search was cancelled before it knew (the caller falls back to a bound).
    double distance(int i, int j);
    /// A lower bound of distance(i, j) that resumes nothing: a closed node's distance; +inf for
    /// a node off the box or known not traversable, or any node not closed once the search is
    /// exhausted; else what the search's progress proves (with its consistent Euclidean guide
    /// every node whose distance + guide is below the open list's least key is closed, so an
    /// open node's distance is at least that key minus its guide), at least 0; -1 after a cancel.
    double lowerBound(int i, int j) const;
    /// Edge weights: an edge costs its length x min(weight(a), weight(b)) (default 1). Weights
    /// must be >= 1: the search's own Euclidean guide assumes it.
    void setWeight(std::function<double(int, int)> weight) { weight_ = std::move(weight); }
    /// Oriented edges: a step also needs bit axis of fitsAxes(i, j) set at both its nodes, axis =
    /// stepAxis[k] for step k (the car fits there lined up with the step). Asked at most once
    /// per node, for all its axes at once (at most 16: one lookup may answer them all).
    void setAxisTest(std::vector<int> stepAxis, std::function<std::uint16_t(int, int)> fitsAxes);
    /// Polled while distance() resumes the search: every closed node at first, every 1024 once
    /// polls come fast (PollSchedule). A search the last one stopped resumes (it stopped
    /// before it popped a node).
    void setCancel(std::function<bool()> cancelled)
    {
        cancelled_ = std::move(cancelled);
        stopped_ = false;
    }
    bool inBox(int i, int j) const { return i >= i0_ && j >= j0_ && i < i0_ + ni_ && j < j0_ + nj_; }
    /// Nodes closed so far (for benchmarks).
    std::size_t closedCount() const { return closedCount_; }
    /// True if the node was asked about and is traversable.
    bool traversable(int i, int j);
    /// True if a step along @p axis may start or end at node (i, j): bit axis of fitsAxes()
    /// with an axis test (setAxisTest()), else traversable(); asked once per node and search.
    bool fitsAxis(int i, int j, int axis);

private:
    std::size_t idx(int i, int j) const { return std::size_t(j - j0_) * std::size_t(ni_) + std::size_t(i - i0_); }
    bool expandUntil(std::size_t target);
    double weightAt(std::size_t n, int i, int j);
    void push(std::size_t n, double g);
    int i0_{0}, j0_{0}, ni_{0}, nj_{0};
    std::vector<std::array<int, 2>> steps_;
    std::vector<double> stepLen_;
    double cell_;
    int ti_{0}, tj_{0};
    std::function<bool(int, int)> traversable_;
    std::function<bool()> cancelled_;
    std::function<double(int, int)> weight_;
    std::vector<int> stepAxis_;
    std::function<std::uint16_t(int, int)> fitsAxes_;
    bool axisFits(std::size_t n, int i, int j, int axis);
    bool stopped_{false};
    PollSchedule poll_{1023};  ///< when expandUntil() polls cancelled_ (reset per search)
    struct Node
    {
        double g;
        float w;  ///< cached edge weight (< 0: not computed)
        std::uint32_t stamp;
        std::uint16_t axisOk;  ///< fitsAxes() (valid once bit 3 of state is set)
        std::uint8_t state;    ///< bit 0 closed, bit 1 asked, bit 2 traversable, bit 3 axes asked
    };
    /// calloc'd (zero bytes: stamp 0, stale for every epoch >= 1): a box of 24 M nodes costs
    /// no fill before the first query, only the pages the search touches
    struct FreeNodes
    {
        void operator()(Node *p) const { std::free(p); }
    };
    std::unique_ptr<Node[], FreeNodes> nodes_;
    std::size_t nodeCount_{0};
    std::uint32_t epoch_{0};
    /// The node, reset to "not seen" if it was last touched by an earlier search.
    Node &at(std::size_t n)
    {
        Node &x = nodes_[n];
        if (x.stamp != epoch_) x = Node{std::numeric_limits<double>::infinity(), -1.0f, epoch_, 0, 0};
        return x;
    }
    struct Entry
    {
        double f, g;
        std::uint32_t n;
        bool operator<(const Entry &o) const { return f > o.f || (f == o.f && g < o.g); }
    };
    std::vector<Entry> heap_;
    std::size_t closedCount_{0};
};

}  // namespace gridcar
