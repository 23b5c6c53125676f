#pragma once
/// @file GridAStar.h
/// @brief The baseline grid searches: Dijkstra and A* with Manhattan, Euclidean and octile
/// heuristics.

#include "gridcar/planners/GridLatticePlanner.h"

namespace gridcar
{
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
class GridAStar : public GridLatticePlanner
{
public:
    GridAStar(const ompl::base::SpaceInformationPtr &si, GridHeuristic h, const std::string &name);
    GridHeuristic heuristicKind() const { return heuristic_; }

protected:
    std::unique_ptr<GridNodes> makeGridNodes() override;

private:
    GridHeuristic heuristic_;
};

}  // namespace gridcar
