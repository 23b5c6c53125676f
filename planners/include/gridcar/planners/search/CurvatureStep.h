#pragma once
/// @file CurvatureStep.h
/// @brief A post-processor of the car lattice: a found path's curvature made continuous within
/// a curvature rate, and with clothoid turns its full-lock turns opened up where there is room.

#include "gridcar/planners/search/CarLatticeSearch.h"

#include <functional>
#include <vector>

namespace gridcar
{
/// What CurvatureStep::apply() did.
struct CurvatureStepReport
{
    int stretches{0};  ///< stretches whose curvature changed faster than the rate
    int replaced{0};   ///< of them, replaced (the others kept as they were: no free replacement)
    bool cancelled{false};
};

/**
 * @brief The continuous-curvature step on paths a CarLatticeSearch found: smoothCurvature()
 * replaces each curvature jump by a G2 stretch within @p curvatureRate and K_max, each
 * replacement sampled no farther apart than lets a body point move the lattice's spacing and
 * checked by the search's own swept-motion test (CarLatticeSearch::curveFree()); on a lattice
 * of clothoid turns (which keep the rate but turn at full lock) widenTurns() then opens the
 * turns up where the map leaves 5 cm more room than the search's margin (for the follower).
 * The path keeps its ends, its cusps and its guarantees; where the termination condition
 * fires during a stage, that stage's change is dropped (the path stays valid).
 */
class CurvatureStep
{
public:
    /// For paths of @p search (borrowed), curvature within @p maxCurvature (1/m) changing at
    /// most @p curvatureRate (1/m^2, > 0).
    CurvatureStep(const CarLatticeSearch &search, double maxCurvature, double curvatureRate);
    /// Applies the step to @p path (dense world poses, start first), polling @p cancelled.
    CurvatureStepReport apply(std::vector<Pose2> &path, const std::function<bool()> &cancelled) const;

private:
    const CarLatticeSearch &search_;
    double maxCurvature_, curvatureRate_;
};

}  // namespace gridcar
