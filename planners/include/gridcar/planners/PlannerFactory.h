#pragma once
/// @file PlannerFactory.h
/// @brief Planners by name: gridcar's grid planners and OMPL's sampling planners.

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace gridcar
{
/// dijkstra, astar-manhattan, astar-euclidean, astar-octile, corner-astar, improved-astar.
std::vector<std::string> gridPlannerNames();
/// rrt, rrtconnect, rrtstar, prm, prmstar, lazyprmstar, bitstar, informedrrtstar.
std::vector<std::string> omplPlannerNames();
/// Both lists.
std::vector<std::string> plannerNames();

/// True if makePlanner() knows @p name (with or without "+smooth" / "+simplify").
bool isPlannerName(const std::string &name);

/// A new planner by name; "NAME+smooth" wraps planner NAME in a SmoothedPlanner (paper I's
/// post-processing), "NAME+simplify" in one that runs OMPL's PathSimplifier. Throws
/// std::invalid_argument listing the known names.
ompl::base::PlannerPtr makePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);

}  // namespace gridcar
