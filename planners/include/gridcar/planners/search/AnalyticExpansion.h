#pragma once
/// @file AnalyticExpansion.h
/// @brief The car lattice's analytic expansion: from a state of the search, a free curve of the
/// primitive set's family to the exact goal, which ends the search (Hybrid A*'s shot).

#include "gridcar/curves/ClothoidTurns.h"
#include "gridcar/planners/search/CarCollision.h"
#include "gridcar/planners/search/CarLattice.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace gridcar
{
struct CarLatticeQuery;
class LatticeCostModel;

/// A curve the analytic expansion found: its poses after the state it leaves (the last one
/// the goal pose) and its cost by the search's cost model and the query's penalties.
struct AnalyticShot
{
    std::vector<Pose2> poses;
    double cost{0.0};
};

/**
 * @brief The analytic expansion of CarLatticeSearch, in three parts:
 * - when to try (due()): from a state within 2 R + 2 cells of the goal at every expansion; within
 *   30 R + 10 cells at every 8th, and only where the obstacle-aware distance to the goal is not
 *   well above the straight line (something in the way: a nearly straight curve would hit it);
 * - the curve family (shoot()): gridcar's Dubins curves, Reeds-Shepp when the primitive set
 *   reverses and the query lets the state reverse (CarLatticeQuery::reverseWithin: a
 *   Reeds-Shepp curve then reverses no farther than that) (the few shortest words per end yaw near the goal: in a tight spot the shortest one
 *   is often blocked where a slightly longer one is free), to the goal's yaw (within its
 *   tolerance: the yaw and both ends of the tolerance), or with a free goal heading to the
 *   bearing and every lattice heading; with clothoid turns the clothoid turn-straight-turn
 *   counterpart of a free Dubins curve (whose arcs would break the curvature rate);
 * - the free check (free()): the body grown by the lattice's margin at poses no farther apart
 *   than lets a body point move the lattice's spacing (the swept motion certified as the
 *   primitives' own), in blocks of 64 poses with the termination condition polled between them.
 * A curve across ground costlier than the query's start and goal (a cost layer) is refused: the
 * search then goes round a costly band, not through it.
 */
class AnalyticExpansion
{
public:
    /// How far a state is from the goal, for the expansion.
    enum class Range
    {
        Out,   ///< not tried from here
        Far,   ///< tried: the shortest curve only
        Near   ///< tried: the few shortest words per end yaw
    };

    /// For @p lattice's curve family (Reeds-Shepp when it reverses, its clothoid turns when it
    /// has a curvature rate) on @p collision; both must outlive this object.
    AnalyticExpansion(const CarCollision &collision, const CarLattice &lattice);
    ~AnalyticExpansion();

    /// The lattice's clothoid turns (null: arcs); the shots forwards use them, the Reeds-Shepp
    /// ones do not.
    const ClothoidTurn *clothoidTurns() const { return clothoid_.get(); }

    /// Whether to try from world pose @p from towards @p goal at the search's @p expansions
    /// (see the class); @p obstacleDistance gives the obstacle-aware distance to the goal from
    /// the state's node (< 0: none), asked only where it decides.
    Range due(const Pose2 &from, const Pose2 &goal, std::uint64_t expansions,
              const std::function<double()> &obstacleDistance) const;

    /// Tries the curves from world pose @p from (reached in gear @p gear: 1 forwards, -1
    /// backwards, 0 a start) to @p q's goal, in @p range; @p frameYaw the lattice frame's yaw
    /// (its headings, for a free goal heading). The first free one, costed by @p cost with the
    /// query's reverse and cusp penalties (and a gear change where it sets off in the other
    /// gear) and its cost layer, goes to @p out. @p tried counts the curves checked.
    bool shoot(const Pose2 &from, int gear, const CarLatticeQuery &q, double frameYaw, Range range,
               const LatticeCostModel &cost, const std::function<bool()> *cancelled, AnalyticShot &out, int &tried) const;

    /// True if the curve from @p from through poses 1..n given by @p poseAt is free (the body
    /// grown by the lattice's margin); false as soon as @p cancelled (may be null) fires.
    bool free(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, const std::function<bool()> *cancelled) const;

    /// With clothoid turns: a turn-straight-turn curve of the lattice's turns from @p from to
    /// @p to whose body is free (the two shortest tried), sampled as the other curves are, in
    /// @p poses with its length and turning; false when neither is free.
    bool clothoidShot(const Pose2 &from, const Pose2 &to, std::vector<Pose2> &poses, double &length, double &turn,
                      const std::function<bool()> *cancelled) const;

private:
    const CarCollision &col_;
    const CarLattice &lattice_;
    std::unique_ptr<ClothoidTurn> clothoid_;
};

}  // namespace gridcar
