// Option groups and parsing helpers shared by the gridcar commands.
#include "Cli.h"

#include <iostream>

#include "gridcar/bench/Format.h"
#include "gridcar/bench/ParamsFile.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/PlannerReport.h"
#include "gridcar/planners/PlannerFactory.h"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace gridcar::cli
{
void addMapOption(CLI::App *cmd, std::string &map)
{
    cmd->add_option("--map", map, "Map file (.yaml, .map, .ppm, .pgm, .png), or 'embedded' for the embedded campus")->required();
}

OccupancyGrid loadMapArgument(const std::string &map)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (map == "embedded" && !fs::exists(map, ec)) return generateCampus();
    const fs::path path(map);
    std::string ext = path.extension().string();
    for (char &c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".pgm" || ext == ".png" || ext == ".ppm" || ext == ".pnm")
        for (const char *y : {".yaml", ".yml"})
        {
            fs::path yaml = path;
            yaml.replace_extension(y);
            if (fs::exists(yaml, ec))
                std::fprintf(stderr,
                             "gridcar: warning: %s is read as a plain image (1 m/cell, origin 0, dark = occupied); its ROS "
                             "map file %s sits beside it: pass --map %s for its resolution, origin and thresholds\n",
                             map.c_str(), yaml.string().c_str(), yaml.string().c_str());
        }
    return loadMap(map);
}

void addVehicleOption(CLI::App *cmd, std::string &vehicle)
{
    cmd->add_option("--vehicle", vehicle, "Vehicle preset (paper-i, paper-c-car, paper-c-robot, point) or YAML file")
        ->capture_default_str();
}

void addTimeLimitOption(CLI::App *cmd, double &seconds, const std::string &what)
{
    cmd->add_option("--time-limit", seconds, what)->capture_default_str();
}

void addQueryOptions(CLI::App *cmd, QueryArgs &q, bool plannerRequired)
{
    addMapOption(cmd, q.map);
    std::string plannerList;
    for (const auto &n : plannerNames()) plannerList += (plannerList.empty() ? "" : ", ") + n;
    cmd->add_option("--planner", q.planner,
                    plannerList + " (or NAME+smooth; OMPL's own names too, any case; the older corner-astar --param lattice=grid or mode=paper, and improved-astar --param lattice=grid, are aliases of the -grid names)" +
                        (plannerRequired ? std::string(". Required, here or in --params-file") : std::string()));
    q.cmd = cmd;
    cmd->add_option("--start", q.start,
                    "Start X,Y[,YAW] in the world frame (m; yaw 0 = +x, CCW, in degrees, or with its unit: 90deg, 1.5708rad); no yaw: free start heading for the grid "
                    "planners (OMPL planners start at the first yaw, in 5-degree steps from 0, at which the vehicle fits)");
    cmd->add_option("--start-cell", q.startCell, "Start COL,ROW[,HEADING] (row 0 = top image row; see --row-order; heading as --start's yaw)");
    cmd->add_option("--goal", q.goal, "Goal X,Y[,YAW] (yaw as --start's): with a yaw the car-lattice planners (and OMPL's) arrive at that heading (--param match_goal_heading=0 relaxes it); without one, at any heading where the vehicle fits");
    cmd->add_option("--goal-cell", q.goalCell, "Goal COL,ROW[,HEADING]");
    cmd->add_option("--goal-tolerance", q.goalTolerance,
                    "XY[,YAW]: the path may end within XY m of the goal and, with a goal yaw, within YAW of its heading "
                    "(degrees, or with its unit: 0.25rad), as Nav2's goal checker (xy_goal_tolerance 0.25, "
                    "yaw_goal_tolerance 0.25 rad); drive's follower stops within XY of the path's end, navigate within "
                    "the tolerance of the goal (the plan and the follower each take a part). Default: exact");
    cmd->add_option("--row-order", q.rowOrder,
                    "Which row --start-cell / --goal-cell count from: top (row 0 = the image's first row) or bottom "
                    "(row 0 = the map origin's row, as ROS's OccupancyGrid data and map_server count)")
        ->check(CLI::IsMember({"top", "bottom"}))
        ->capture_default_str();
    addVehicleOption(cmd, q.vehicle);
    cmd->add_option("--param", q.params, "NAME=VALUE: set a declared planner parameter (repeatable)");
    addTimeLimitOption(cmd, q.timeLimit, "Planning time limit, s");
    cmd->add_flag("--smooth", q.smooth,
                  "Post-process any planner's path as paper I does (line of sight, turning-point adjustment under K_max, "
                  "Bezier); improved-astar does this itself unless --param smooth=0");
    cmd->add_flag("--unknown-free", q.unknownFree, "Treat unknown cells as free");
    cmd->add_option("--space", q.space,
                    "State space: se2 (gridcar's: straight motions, the car may slide sideways), dubins or reeds-shepp "
                    "(OMPL's, at the vehicle's minimum turning radius; motions checked along the curves: OMPL's planners "
                    "then return drivable paths; reeds-shepp paths may reverse, their cusps counted)")
        ->check(CLI::IsMember({"se2", "dubins", "reeds-shepp"}))
        ->capture_default_str();
    cmd->add_option("--params-file", q.paramsFile,
                    "YAML file with any of planner, params {NAME: VALUE}, vehicle (preset or file, relative to it), space, "
                    "time_limit; options given on the command line win (a --param over the file's value of that name)");
}

void applyParamsFile(QueryArgs &q, bool plannerRequired)
{
    if (!q.paramsFile.empty())
    {
        const bench::ParamsFile pf = bench::readParamsFile(q.paramsFile);
        const auto given = [&q](const char *opt) { return q.cmd && q.cmd->count(opt) > 0; };
        if (!pf.planner.empty() && !given("--planner")) q.planner = pf.planner;
        if (!pf.vehicle.empty() && !given("--vehicle")) q.vehicle = pf.vehicle;
        if (!pf.space.empty() && !given("--space")) q.space = pf.space;
        if (pf.timeLimit > 0 && !given("--time-limit")) q.timeLimit = pf.timeLimit;
        std::vector<std::string> params;  // the file's, except those the command line sets too
        for (const auto &[name, value] : pf.params)
        {
            bool overridden = false;
            for (const std::string &cli : q.params) overridden = overridden || cli.rfind(name + "=", 0) == 0;
            if (!overridden) params.push_back(name + "=" + value);
        }
        params.insert(params.end(), q.params.begin(), q.params.end());
        q.params = params;
    }
    if (plannerRequired && q.planner.empty()) throw InputError("give --planner NAME (or planner: in --params-file)");
}

Query loadQuery(const QueryArgs &q, bool withPoses)
{
    bench::checkTimeLimit(q.timeLimit);
    Query query;
    query.grid = std::make_shared<OccupancyGrid>(loadMapArgument(q.map));
    query.grid->setUnknownIsFree(q.unknownFree);
    query.vehicle = VehicleParams::fromNameOrFile(q.vehicle);
    if (withPoses)  // before the set-up: a malformed pose fails at once
    {
        const bool bottom = q.rowOrder == "bottom";
        query.start = parsePose(q.start, q.startCell, "start", *query.grid, query.startYaw, bottom);
        query.goal = parsePose(q.goal, q.goalCell, "goal", *query.grid, query.goalYaw, bottom);
        if (!q.goalTolerance.empty()) query.goalTolerance = parseGoalTolerance(q.goalTolerance);
    }
    SetupOptions so;
    so.space = parseSpaceKind(q.space);
    // the set-up of a large map (distance field, footprint checker) takes seconds: say so
    const bool large = double(query.grid->width()) * query.grid->height() > 1.5e7;
    const auto t0 = std::chrono::steady_clock::now();
    if (large)
        std::fprintf(stderr, "[gridcar] %d x %d cells: distance field and footprint checker ...\n", query.grid->width(),
                     query.grid->height());
    try
    {
        query.setup = makeGridSetup(query.grid, query.vehicle, so);
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(std::string("--space ") + q.space + ": " + e.what());
    }
    if (large)
        std::fprintf(stderr, "[gridcar] set-up done in %.1f s\n",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (withPoses)
    {
        double yaw = 0;
        if (!query.startYaw && query.setup.checker->fitsAtSomeHeading(query.start.x, query.start.y, 72, &yaw)) query.start.yaw = yaw;
        if (!query.goalYaw && query.setup.checker->fitsAtSomeHeading(query.goal.x, query.goal.y, 72, &yaw)) query.goal.yaw = yaw;
    }
    return query;
}

std::string whyInvalid(const Query &query, const Pose2 &p, bool anyHeading)
{
    return whyPoseInvalid(*query.setup.checker, *query.grid, p, anyHeading);
}

ompl::base::PlannerPtr queryPlanner(const QueryArgs &q, const Query &query)
{
    ompl::base::PlannerPtr p = configurePlanner(query.setup.ss->getSpaceInformation(),
                                                {q.planner, parsePlannerParams(q.params), !query.startYaw, q.smooth});
    // a search over the map's cells moves in straight cell steps whatever the space: on a car
    // space its path is no Dubins / Reeds-Shepp path, and the user should hear it before the result
    if (reportOf(*p).searchesMapCells && q.space != "se2")
        std::fprintf(stderr,
                     "gridcar: warning: %s searches the map's cells in straight steps: on --space %s it ignores the "
                     "curves, and its path is not a %s path (the car-lattice planners corner-astar and improved-astar "
                     "and OMPL's planners use them)\n",
                     q.planner.c_str(), q.space.c_str(), q.space == "dubins" ? "Dubins" : "Reeds-Shepp");
    return p;
}

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

GoalTolerance parseGoalTolerance(const std::string &text)
{
    std::string t = text;
    double yawUnit = M_PI / 180.0;
    for (const auto &[suffix, unit] : {std::make_pair(std::string("rad"), 1.0), std::make_pair(std::string("deg"), M_PI / 180.0)})
        if (t.size() > suffix.size() && t.compare(t.size() - suffix.size(), suffix.size(), suffix) == 0)
        {
            t.resize(t.size() - suffix.size());
            yawUnit = unit;
            break;
        }
    const auto v = parseNumbers(t, "--goal-tolerance", 1, 2);
    GoalTolerance tol{v[0], v.size() == 2 ? v[1] * yawUnit : 0.0};
    if (!(tol.position >= 0) || tol.position > 1e3 || !(tol.yaw >= 0) || tol.yaw > M_PI + 1e-9)
        throw InputError("--goal-tolerance '" + text + "': XY in [0, 1000] m, YAW in [0, 180] deg");
    return tol;
}

Pose2 parsePose(const std::string &world, const std::string &cell, const std::string &which, const OccupancyGrid &g,
                bool &hasYaw, bool rowsFromBottom)
{
    if (world.empty() == cell.empty())
        throw InputError("give exactly one of --" + which + " X,Y[,YAW] and --" + which + "-cell COL,ROW[,HEADING]");
    Pose2 p;
    // the yaw is in degrees unless it names its unit: 90deg, 1.5708rad
    const std::string option = world.empty() ? "--" + which + "-cell" : "--" + which;
    std::string text = world.empty() ? cell : world;
    double yawUnit = M_PI / 180.0;
    bool unitGiven = false;
    for (const auto &[suffix, unit] : {std::make_pair(std::string("rad"), 1.0), std::make_pair(std::string("deg"), M_PI / 180.0)})
    {
        const std::size_t end = text.find_last_not_of(" \t") + 1;
        if (end >= suffix.size() && text.compare(end - suffix.size(), suffix.size(), suffix) == 0)
        {
            text = text.substr(0, end - suffix.size());
            yawUnit = unit;
            unitGiven = true;
            break;
        }
    }
    const auto v = parseNumbers(text, option, 2, 3);
    if (unitGiven && v.size() != 3)
        throw InputError(option + " '" + (world.empty() ? cell : world) + "': a unit (deg, rad) needs a yaw: X,Y,YAW");
    // a yaw without a unit that looks like radians (a fraction within 2 pi): say how it is read
    if (!unitGiven && v.size() == 3 && v[2] != std::round(v[2]) && std::abs(v[2]) <= 2 * M_PI + 1e-3)
        std::fprintf(stderr, "gridcar: note: %s yaw %g is read as degrees; write %grad for radians\n", option.c_str(), v[2], v[2]);
    if (!world.empty())
    {
        p = {v[0], v[1], v.size() == 3 ? v[2] * yawUnit : 0.0};
        hasYaw = v.size() == 3;
    }
    else
    {
        if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]))
            throw InputError("--" + which + "-cell: column and row must be integers");
        if (std::abs(v[0]) > 1e9 || std::abs(v[1]) > 1e9 || !g.inBounds(int(v[0]), int(v[1])))
            throw InputError("--" + which + "-cell " + cell + " is outside the " + std::to_string(g.width()) + " x " +
                             std::to_string(g.height()) + " map");
        const int row = rowsFromBottom ? g.height() - 1 - int(v[1]) : int(v[1]);
        p = {g.cellCenterX(int(v[0])), g.cellCenterY(row), v.size() == 3 ? v[2] * yawUnit : 0.0};
        hasYaw = v.size() == 3;
    }
    p.yaw = wrapYaw(p.yaw);
    return p;
}

std::string describe(const Pose2 &p)
{
    char buf[128];
    std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.1f deg)", p.x, p.y, p.yaw * 180.0 / M_PI);
    return buf;
}

void ensureDir(const std::string &dir)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError("cannot create output folder '" + dir + "': " + ec.message());
}

namespace
{
bool gJsonPrinted = false;
}

void printJson(const std::string &text)
{
    std::cout << text << "\n" << std::flush;
    gJsonPrinted = true;
}

bool jsonPrinted() { return gJsonPrinted; }

}  // namespace gridcar::cli
