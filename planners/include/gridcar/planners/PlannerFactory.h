#pragma once
/// @file PlannerFactory.h
/// @brief Planners by name: gridcar's grid planners and OMPL's sampling planners.

#include <ompl/base/Planner.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
/// One named planner configuration of the registry.
struct PlannerEntry
{
    std::string name;
    std::string description;  ///< one line
    bool ours{false};         ///< gridcar's (a GridPlanner) or OMPL's
    std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr &)> make;
};

/// Every planner by name, in one table: gridcar's (the grid searches, corner-astar and
/// improved-astar on the car lattice, the papers' searches on the map's cells as
/// corner-astar-grid and improved-astar-grid) and OMPL's. A new planner is one entry here.
const std::vector<PlannerEntry> &plannerRegistry();

/// The registry's entry of @p name (no suffix), or null. Case-insensitive: OMPL's class names
/// (RRTConnect, RRTstar, PRMstar, LazyPRMstar, BITstar, InformedRRTstar) find OMPL's planners.
const PlannerEntry *findPlanner(const std::string &name);

/// The registry name nearest to @p name by edit distance when it is close enough to be a
/// typo (for "did you mean"), else "".
std::string suggestPlanner(const std::string &name);

/// dijkstra, astar-manhattan, astar-euclidean, astar-octile, corner-astar, improved-astar,
/// corner-astar-grid, improved-astar-grid.
std::vector<std::string> gridPlannerNames();
/// rrt, rrtconnect, rrtstar, prm, prmstar, lazyprmstar, bitstar, informedrrtstar.
std::vector<std::string> omplPlannerNames();
/// Both lists.
std::vector<std::string> plannerNames();

/// True if makePlanner() knows @p name (with or without "+smooth" / "+simplify").
bool isPlannerName(const std::string &name);

/// The old command lines as aliases of the registry's names: `corner-astar` with `lattice=grid`
/// or `mode=paper` is `corner-astar-grid`, `improved-astar` with `lattice=grid` is
/// `improved-astar-grid`; `lattice=car` and corner-astar's `mode=drivable` name the car
/// lattice, which `corner-astar` and `improved-astar` search. Returns the name to make (a
/// "+smooth" / "+simplify" suffix kept) and removes those switches from @p params; any other
/// name and parameters are returned as they are. std::invalid_argument for `lattice=car` on a
/// `-grid` name.
std::string resolvePlannerAlias(const std::string &name, std::vector<std::pair<std::string, std::string>> &params);
/// A new planner by name; "NAME+smooth" wraps planner NAME in a SmoothedPlanner (paper I's
/// post-processing), "NAME+simplify" in one that runs OMPL's PathSimplifier. Throws
/// std::invalid_argument listing the known names.
ompl::base::PlannerPtr makePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);

}  // namespace gridcar
