/// @file GridPlannerParams.cpp
/// @brief GridPlanner's common parameter setters (each validates, then redoes set-up).
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
bool GridPlanner::matchGoalHeading() const
{
    return params_.matchGoalHeading.value_or(usesCarLattice());
}

void GridPlanner::setFreeStartHeading(bool v)
{
    params_.freeStartHeading = v;
    parameterSet("free_start_heading");
}

void GridPlanner::setMatchGoalHeading(bool v)
{
    params_.matchGoalHeading = v;
    parameterSet("match_goal_heading");
}

void GridPlanner::setMaxMemoryMb(double mb)
{
    if (!std::isfinite(mb) || mb < 0.0 || mb > 1e7)
        throw std::invalid_argument(getName() + ": max_memory_mb must be 0 (no bound) or a size in MB up to 1e7");
    params_.maxMemoryMb = mb;
    parameterSet("max_memory_mb");
}

void GridPlanner::setTurningRadius(double r)
{
    if (!std::isfinite(r) || r < 0.0 || r > 1e4)
        throw std::invalid_argument(getName() + ": turning_radius must be 0 (automatic) or a length in (0, 10000] m");
    params_.turningRadius = r;
    parameterSet("turning_radius");
}

void GridPlanner::setLatticeCell(double m)
{
    if (!std::isfinite(m) || m < 0.0 || m > 1000.0)
        throw std::invalid_argument(getName() + ": lattice_cell must be 0 (automatic) or a length in (0, 1000] m");
    params_.latticeCell = m;
    parameterSet("lattice_cell");
}

}  // namespace gridcar
