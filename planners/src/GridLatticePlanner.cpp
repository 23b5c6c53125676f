/// @file GridLatticePlanner.cpp
/// @brief The grid lattice's planner: its set-up, one search, the explored graph.
#include "gridcar/planners/GridLatticePlanner.h"

namespace gridcar
{
GridLatticePlanner::GridLatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
  : GridPlanner(si, name)
{
    declareParam<bool>("allow_corner_cutting", this, &GridLatticePlanner::setAllowCornerCutting,
                       &GridLatticePlanner::allowCornerCutting, "0,1");
}

void GridLatticePlanner::setAllowCornerCutting(bool v)
{
    allowCornerCutting_ = v;
    parameterSet("allow_corner_cutting");
}

void GridLatticePlanner::setupFamily(const std::shared_ptr<CarCollision> &collision)
{
    std::unique_ptr<GridNodes> nodes = makeGridNodes();
    if (!nodes) throw ompl::Exception(getName(), "has no grid-lattice node type");
    grid_.setAllowCornerCutting(allowCornerCutting_);
    // the lattice's per-map arrays are refused (solve() then returns ABORT with the reason)
    // when they alone would exceed max_memory_mb
    tooBig_ = grid_.setup(space_, collision, std::move(nodes), maxMemoryMb());
}

FamilyRun GridLatticePlanner::searchFamily(const ompl::base::State *start, const GoalTarget &goal,
                                           const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    return grid_.solve(si_, start, freeStartHeading(), goal, cancelled, progress);
}

void GridLatticePlanner::familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const
{
    grid_.plannerData(data, states);
}

}  // namespace gridcar
