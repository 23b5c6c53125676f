#pragma once
/// @file CurveTable.h
/// @brief The obstacle-free non-holonomic distance between the nodes of a car lattice, kept in
/// a table (the Hybrid-A* planners' heuristic lookup table), and the lower bound it gives to a
/// goal pose that is not itself a node.

#include "gridcar/core/Pose2.h"

#include <array>
#include <cstddef>
#include <vector>

namespace gridcar
{
class CarLattice;

/**
 * @brief The length of the shortest Reeds-Shepp curve (a lattice that reverses) or Dubins curve
 * (forwards only) at the lattice's turning radius from node (di, dj) at heading hs to node
 * (0, 0) at heading hg, for |di|, |dj| <= span(): Dolgov et al.'s "non-holonomic without
 * obstacles" heuristic, which Nav2's Smac Hybrid-A* planner reads from a precomputed table.
 *
 * Unlike a table over binned continuous poses, this one is exact where it is read: a lattice's
 * states are its nodes, and the distance between two nodes depends only on their offset in
 * cells and their two headings (the lattice is the same everywhere; a quarter turn maps it to
 * itself, so only goal headings 0 .. headings/4 - 1 are stored). Each entry is computed on
 * first use and kept (fill() computes them all), so a planner's later queries read what its
 * earlier ones computed; entries are floats rounded down, so a value read never exceeds the
 * distance. Not thread-safe: one search at a time, as CarLatticeSearch.
 *
 * @par External documentation
 * D. Dolgov, S. Thrun, M. Montemerlo, J. Diebel, "Path planning for autonomous vehicles in
 * unknown semi-structured environments", IJRR 2010 (the two heuristics of Hybrid A*).
 * J. A. Reeds, L. A. Shepp, "Optimal paths for a car that goes both forwards and backwards",
 * Pacific J. Math. 1990.
 */
class CurveTable
{
public:
    /// For the nodes of @p lattice within @p range metres (per axis) of each other. Throws
    /// std::invalid_argument for a hybrid lattice (its states are not nodes) or a range that is
    /// not finite and positive, or one that would need more than 64 million entries.
    CurveTable(const CarLattice &lattice, double range);

    int span() const { return span_; }
    double cell() const { return cell_; }
    int headings() const { return headings_; }
    double radius() const { return radius_; }
    bool reverse() const { return reverse_; }
    /// Entries stored and entries computed so far.
    std::size_t size() const { return d_.size(); }
    std::size_t computed() const { return computed_; }

    /// The curve length (m) from node (di, dj) at heading @p hs to node (0, 0) at heading
    /// @p hg, rounded down to a float; < 0 when the offset is beyond span().
    double distance(int di, int dj, int hs, int hg) const;
    /// Computes every entry not computed yet.
    void fill() const;

    /// The lattice's node (i, j) at heading h, in its frame.
    Pose2 node(int i, int j, int h) const;

private:
    std::size_t index(int di, int dj, int hs, int hg) const;
    double compute(int di, int dj, int hs, int hg) const;

    double cell_;
    int headings_;
    int quarter_;  ///< headings per quarter turn where a quarter turn maps the lattice to itself, else headings
    double radius_;
    bool reverse_;
    int span_;
    std::vector<double> yaw_;
    mutable std::vector<float> d_;  ///< NaN: not computed yet
    mutable std::size_t computed_{0};
};

/**
 * @brief A lower bound on the curve length from a lattice node to a goal pose anywhere, read
 * from a CurveTable: for a reference node g0 near the goal g, every curve from s to g followed
 * by the shortest one from g to g0 is a curve from s to g0, so
 * d(s, g) >= d(s, g0) - d(g, g0) (the triangle inequality; d(g, g0) computed exactly, once per
 * query). Of the nodes round the goal (within R / 2, at the two headings nearest its yaw), the
 * two with the least d(g, g0) are kept and the larger of their bounds is taken. 0 where no
 * reference is within the table.
 */
class CurveTableBound
{
public:
    CurveTableBound() = default;
    /// @p goal in the lattice's frame.
    CurveTableBound(const CurveTable &table, const Pose2 &goal);
    bool active() const { return table_ != nullptr && count_ > 0; }
    /// The bound (m) at node (i, j) at heading h (>= 0).
    double operator()(int i, int j, int h) const;
    /// d(g, g0) of the reference nodes kept, least first.
    double slack(int k) const { return refs_[std::size_t(k)].slack; }
    int references() const { return count_; }

private:
    struct Ref
    {
        int i{0}, j{0}, h{0};
        double slack{0.0};
    };
    const CurveTable *table_{nullptr};
    std::array<Ref, 2> refs_{};
    int count_{0};
};

}  // namespace gridcar
