#pragma once
/// @file StretchCost.h
/// @brief How the shortcut (PathShortcut::apply()) measures a stretch of a path: the
/// gear of a step and the stretch's cost by the planner's cost model.

#include "gridcar/core/Pose2.h"
#include "gridcar/planners/search/CarLatticeSearch.h"

#include <vector>

namespace gridcar::detail
{
/// The gear of the step from @p a to @p b: 1 forwards, -1 backwards (the displacement against
/// the mean heading of both poses), 0 for a repeated pose (samePosition()).
int stepGear(const Pose2 &a, const Pose2 &b);

/// The cost of driving poses[0..n] the way the search costs its motions: the path cut into
/// runs of one gear and one turning side, each a stepCost() with its length and turning (and
/// the cost layer), times the reverse penalty when driven backwards; plus the cusp penalty per
/// gear change, counting one against @p before (the gear the car arrives in, 0: none) and
/// @p after (the gear it leaves in). The number of gear changes goes to @p cusps.
double stretchCost(const std::vector<Pose2> &poses, int before, int after, const CarLatticeQuery &q,
                   const LatticeCostModel &cost, int &cusps);

}  // namespace gridcar::detail
