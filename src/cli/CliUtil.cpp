// Helpers shared by the CLI commands: poses, vehicles, planners and their parameters.
#include "CliUtil.h"

#include "gridcar/planners/PlannerFactory.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace gridcar::cli
{

/// "A,B[,C]" -> numbers; throws InputError naming the option.
std::vector<double> parseNumbers(const std::string &text, const std::string &option, std::size_t minN, std::size_t maxN)
{
    std::vector<double> v;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
    {
        std::size_t used = 0;
        double x;
        try
        {
            x = std::stod(item, &used);
        }
        catch (const std::exception &)
        {
            throw InputError(option + " '" + text + "': '" + item + "' is not a number");
        }
        if (used != item.size() && item.find_first_not_of(" \t", used) != std::string::npos)
            throw InputError(option + " '" + text + "': '" + item + "' is not a number");
        if (!std::isfinite(x)) throw InputError(option + " '" + text + "': values must be finite");
        v.push_back(x);
    }
    if (v.size() < minN || v.size() > maxN)
        throw InputError(option + " '" + text + "': expected " + std::to_string(minN) +
                         (maxN > minN ? " or " + std::to_string(maxN) : std::string()) + " comma-separated numbers");
    return v;
}

/// A pose from --start/--goal (world X,Y[,YAW_DEG]) or --start-cell/--goal-cell (COL,ROW[,DEG]).
Pose2 parsePose(const std::string &world, const std::string &cell, const std::string &which, const OccupancyGrid &g,
                bool &hasYaw)
{
    if (world.empty() == cell.empty())
        throw InputError("give exactly one of --" + which + " X,Y[,YAW_DEG] and --" + which + "-cell COL,ROW[,HEADING_DEG]");
    Pose2 p;
    if (!world.empty())
    {
        const auto v = parseNumbers(world, "--" + which, 2, 3);
        p = {v[0], v[1], v.size() == 3 ? v[2] * M_PI / 180.0 : 0.0};
        hasYaw = v.size() == 3;
    }
    else
    {
        const auto v = parseNumbers(cell, "--" + which + "-cell", 2, 3);
        if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
            throw InputError("--" + which + "-cell: column and row must be integers");
        if (!g.inBounds(int(v[0]), int(v[1])) || std::abs(v[0]) > 1e9 || std::abs(v[1]) > 1e9)
            throw InputError("--" + which + "-cell " + cell + " is outside the " + std::to_string(g.width()) + " x " +
                             std::to_string(g.height()) + " map");
        p = {g.cellCenterX(int(v[0])), g.cellCenterY(int(v[1])), v.size() == 3 ? v[2] * M_PI / 180.0 : 0.0};
        hasYaw = v.size() == 3;
    }
    p.yaw = GridSE2StateSpace::wrapYaw(p.yaw);
    return p;
}

std::string describe(const Pose2 &p)
{
    char buf[128];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.1f deg)", p.x, p.y, p.yaw * 180.0 / M_PI);
    return buf;
}

VehicleParams loadVehicle(const std::string &v)
{
    try
    {
        return VehicleParams::fromNameOrFile(v);
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(e.what());
    }
}

ompl::base::PlannerPtr plannerByName(const GridSetup &setup, const std::string &name)
{
    try
    {
        return makePlanner(setup.ss->getSpaceInformation(), name);
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(e.what());
    }
}

void applyParams(ompl::base::Planner &planner, const std::vector<std::string> &params)
{
    for (const auto &kv : params)
    {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0) throw InputError("--param '" + kv + "': expected NAME=VALUE");
        const std::string name = kv.substr(0, eq), value = kv.substr(eq + 1);
        if (!planner.params().hasParam(name))
        {
            std::vector<std::string> names;
            planner.params().getParamNames(names);
            std::string list;
            for (const auto &n : names) list += (list.empty() ? "" : ", ") + n;
            throw InputError("planner " + planner.getName() + " has no parameter '" + name + "' (its parameters: " +
                             list + ")");
        }
        bool ok = false;
        try
        {
            ok = planner.params().setParam(name, value);
        }
        catch (const std::exception &e)
        {
            throw InputError("--param " + kv + ": " + e.what());
        }
        if (!ok) throw InputError("--param " + kv + ": value not accepted");
    }
}
void freeStartHeading(ompl::base::Planner &planner)
{
    if (planner.params().hasParam("free_start_heading")) planner.params().setParam("free_start_heading", "1");
}

OccupancyGrid cropAround(const OccupancyGrid &grid, const WorldBox &box, double margin)
{
    const Cell tl = grid.worldToCell(box.x0 - margin, box.y1 + margin), br = grid.worldToCell(box.x1 + margin, box.y0 - margin);
    const int c0 = std::clamp(tl.col, 0, grid.width() - 1), r0 = std::clamp(tl.row, 0, grid.height() - 1);
    const int c1 = std::clamp(br.col, 0, grid.width() - 1), r1 = std::clamp(br.row, 0, grid.height() - 1);
    return grid.cropped(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
}

std::string fixed(double v, int prec)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}

}  // namespace gridcar::cli
