#pragma once
// Helpers shared by the CLI commands: poses, vehicles, planners and their parameters.
#include "Commands.h"

#include "gridcar/spaces/Setup.h"

#include <ompl/base/Planner.h>

#include <algorithm>
#include <string>
#include <vector>

namespace gridcar::cli
{
/// "A,B[,C]" -> numbers; throws InputError naming the option.
std::vector<double> parseNumbers(const std::string &text, const std::string &option, std::size_t minN, std::size_t maxN);
/// A pose from --X (world X,Y[,YAW_DEG]) or --X-cell (COL,ROW[,DEG]); exactly one must be given.
Pose2 parsePose(const std::string &world, const std::string &cell, const std::string &which, const OccupancyGrid &g,
                bool &hasYaw);
/// "(x, y, yaw deg)".
std::string describe(const Pose2 &p);
/// A preset or vehicle file; InputError on failure.
VehicleParams loadVehicle(const std::string &v);
/// makePlanner() with InputError for unknown names.
ompl::base::PlannerPtr plannerByName(const GridSetup &setup, const std::string &name);
/// Bounding box of world points.
struct WorldBox
{
    double x0{1e300}, x1{-1e300}, y0{1e300}, y1{-1e300};
    void add(double x, double y)
    {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
};
/// The part of @p grid covering @p box plus @p margin metres on every side, clipped to the map
/// (for pictures of a query's surroundings).
OccupancyGrid cropAround(const OccupancyGrid &grid, const WorldBox &box, double margin);
/// @p v with @p prec decimals.
std::string fixed(double v, int prec);
/// A start given without a yaw: grid planners then choose their first heading freely
/// (`free_start_heading`); OMPL's planners have no such parameter and start at yaw 0.
void freeStartHeading(ompl::base::Planner &planner);
/// --param NAME=VALUE settings; InputError listing the planner's parameters on an unknown name.
void applyParams(ompl::base::Planner &planner, const std::vector<std::string> &params);
}  // namespace gridcar::cli
