#pragma once
/// @file PathShortcut.h
/// @brief A post-processor of the car lattice: a found path shortened by free curves of the
/// lattice's own family (the analytic expansion's), never longer, costlier or with more cusps.

#include "gridcar/planners/search/CarLatticeSearch.h"

#include <functional>
#include <vector>

namespace gridcar
{
/// What PathShortcut::apply() did to a path.
struct ShortcutReport
{
    int curves{0};            ///< curves tried (each sampled and checked)
    int replaced{0};          ///< stretches replaced by a curve
    double lengthBefore{0.0}; ///< m
    double lengthAfter{0.0};  ///< m
    double costBefore{0.0};   ///< by the cost model, as apply() measures it
    double costAfter{0.0};
};

/**
 * @brief Shortens a path found on a car lattice by the curves of its analytic expansion, for
 * the same collision model and primitive set (the search's own: PathShortcut(search)).
 */
class PathShortcut
{
public:
    /// On @p collision with @p lattice's turning radius, spacing, margin and gears; with
    /// @p clothoid (the lattice's clothoid turns, borrowed) its turn-straight-turn curves.
    PathShortcut(const CarCollision &collision, const CarLattice &lattice, const ClothoidTurn *clothoid);
    /// For the paths @p search finds (its collision model, lattice and clothoid turns).
    explicit PathShortcut(const CarLatticeSearch &search);

    /**
     * @brief Shortens @p path (dense world poses, start first, ending where it must end)
     * by the curves of the analytic expansion: between poses about 0.3 m apart along it (and
     * its cusps; farther apart on a long path, at most about 80 of them on a reversing
     * lattice, 40 on a forward one, whose shortcuts span at most 12 R), from each one the
     * farthest later one that a curve of the lattice's family (Reeds-Shepp when it reverses,
     * its clothoid turn-straight-turn curves with clothoid turns, also with turns of 2 and 4
     * R at the same rate, else Dubins; the two shortest words of each) joins is reached by
     * that curve, if the curve
     * - is free with the body grown 5 cm beyond the search's margin (CarCollision::curveFree():
     *   every pose, swept motion certified as the search's own), so that it leaves a follower
     *   room instead of grazing what the lattice kept clear of,
     * - has no flick of the wheels (an arc between arcs of the other side shorter than a
     *   quarter circle or 2 m),
     * - is shorter than the stretch it replaces, costs less by @p cost with @p q's reverse and
     *   cusp penalties and cost layer (each run of one gear and turning side costed as a
     *   motion of the search), and adds no gear change,
     * - with clothoid turns: joins the path where it runs straight (its curves start and end
     *   at curvature 0), the rate where it joins measured by curvatureRateProfile().
     * So the path keeps its ends and its guarantees (curvature within the lattice's turning
     * radius; within its curvature rate with clothoid turns), never gets longer or costlier,
     * and never gains a cusp: what a lattice's few headings and coarse cells leave over (a
     * parking manoeuvre some metres longer than a continuous planner's) is taken off. Up to
     * @p maxCurves curves are checked; @p cancelled is polled between them (the path is then
     * kept as far as it got: still valid); after 4 free curves from one anchor that are no
     * better, the next anchor. Two passes at most.
     */
    ShortcutReport apply(std::vector<Pose2> &path, const CarLatticeQuery &q, const LatticeCostModel &cost,
                         const std::function<bool()> &cancelled, int maxCurves) const;

private:
    const CarCollision &col_;
    const CarLattice &lattice_;
    const ClothoidTurn *clothoid_;
};

}  // namespace gridcar
