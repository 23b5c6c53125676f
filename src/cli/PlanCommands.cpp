// gridcar plan / gridcar scen.
#include "Commands.h"
#include "CliUtil.h"
#include "Query.h"

#include "gridcar/io/Render.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace gridcar::cli
{
namespace
{
using Clock = std::chrono::steady_clock;
}  // namespace

int runPlan(const PlanOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    if (!(o.timeLimit > 0.0) || !std::isfinite(o.timeLimit) || o.timeLimit > 86400)
        throw InputError("--time-limit must be a positive number of seconds (at most a day)");
    auto grid = std::make_shared<OccupancyGrid>(loadMap(o.map));
    grid->setUnknownIsFree(o.unknownFree);
    const VehicleParams vehicle = loadVehicle(o.vehicle);
    bool startYaw = false, goalYaw = false;
    const Pose2 start = parsePose(o.start, o.startCell, "start", *grid, startYaw);
    const Pose2 goal = parsePose(o.goal, o.goalCell, "goal", *grid, goalYaw);
    GridSetup setup = makeGridSetup(grid, vehicle);
    const ompl::base::PlannerPtr planner = plannerByName(setup, o.planner);
    if (!startYaw) freeStartHeading(*planner);
    applyParams(*planner, o.params);

    nlohmann::json j;
    j["planner"] = o.planner;
    auto fail = [&](const std::string &status, const std::string &msg) {
        if (o.json)
        {
            j["status"] = status;
            j["error"] = msg;
            std::cout << j.dump() << "\n";
        }
        throw InputError(msg);
    };
    // the same checks for every planner (OMPL's own planners do not all check the goal)
    auto whyInvalid = [&](const Pose2 &p) {
        const Cell c = grid->worldToCell(p.x, p.y);
        return grid->inBounds(c.col, c.row) ? "in collision for vehicle " + vehicle.name : std::string("outside the map");
    };
    if (!setup.checker->isValid(start)) fail("Invalid start", "start " + describe(start) + " is " + whyInvalid(start));
    if (!setup.checker->isValid(goal)) fail("Invalid goal", "goal " + describe(goal) + " is " + whyInvalid(goal));
    const QueryResult q = runQuery(setup, planner, start, goal, o.timeLimit, o.smooth);
    const PathMetrics &m = q.metrics;
    const std::vector<Pose2> &path = q.path;
    auto *gp = dynamic_cast<GridPlanner *>(planner.get());
    j["status"] = q.status.asString();
    j["cost"] = q.cost;
    j["length"] = m.length;
    j["expanded"] = q.expanded;
    j["turns"] = m.turns;
    j["max_turn_deg"] = q.maxTurnDeg;
    j["min_clearance"] = m.minClearance;
    j["min_path_distance"] = m.minPathDistance;
    j["max_curvature"] = m.maxCurvature;
    j["time"] = q.seconds;
    j["smoothing_time"] = q.smoothingSeconds;
    j["smoothed"] = q.smoothed;
    if (q.smoothed)
    {
        j["adjust_failures"] = q.adjustFailures;
        j["bezier_fallbacks"] = q.bezierFallbacks;
    }
    j["vehicle"] = vehicle.name;
    nlohmann::json jp = nlohmann::json::array();
    for (const Pose2 &p : path) jp.push_back({p.x, p.y, p.yaw});
    j["path"] = jp;
    if (o.json)
        std::cout << j.dump() << "\n";
    else
    {
        std::printf("%s: %s in %.3f s", o.planner.c_str(), q.status.asString().c_str(), q.seconds);
        if (q.smoothed) std::printf(" (smoothing %.4f s)", q.smoothingSeconds);
        std::printf("\n  length %.2f m, cost %.2f, %d poses, %d turns, max turn %.1f deg, max curvature %.3f 1/m, "
                    "min clearance %.2f m (path line %.2f m from obstacles)",
                    m.length, q.cost, int(path.size()), m.turns, q.maxTurnDeg, m.maxCurvature, m.minClearance,
                    m.minPathDistance);
        if (gp) std::printf(", %llu nodes expanded", (unsigned long long)q.expanded);
        if (q.smoothed && q.adjustFailures + q.bezierFallbacks > 0)
            std::printf("\n  smoothing: %d corner(s) still above K_max, %d Bezier piece(s) collided and were kept sharp",
                        q.adjustFailures, q.bezierFallbacks);
        std::printf("\n");
    }
    if (!o.outCsv.empty())
    {
        std::ofstream f(o.outCsv);
        if (!f) throw InputError("cannot write " + o.outCsv);
        f << "x,y,yaw\n";
        f.precision(10);
        for (const Pose2 &p : path) f << p.x << "," << p.y << "," << p.yaw << "\n";
    }
    if (!o.png.empty())
    {
        MapCanvas canvas(*grid);
        if (gp) canvas.tintCells(gp->expandedCells(), {170, 200, 255});
        if (q.smoothed)
        {
            std::vector<std::pair<double, double>> raw;
            for (const Pose2 &p : q.rawPath) raw.push_back({p.x, p.y});
            canvas.polyline(raw, {250, 170, 60}, 1);
        }
        std::vector<std::pair<double, double>> pts;
        for (const Pose2 &p : path) pts.push_back({p.x, p.y});
        canvas.polyline(pts, {220, 30, 30}, 2);
        canvas.disc(start.x, start.y, 4, {0, 160, 0});
        canvas.disc(goal.x, goal.y, 4, {0, 0, 200});
        canvas.save(o.png);
    }
    return q.status == ompl::base::PlannerStatus::EXACT_SOLUTION ? 0 : 3;
}

int runScen(const ScenOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto grid = std::make_shared<const OccupancyGrid>(loadMovingAiMap(o.map));
    const auto scen = loadScenario(o.scen);
    const VehicleParams vehicle = loadVehicle(o.vehicle);
    GridSetup setup = makeGridSetup(grid, vehicle);
    const ompl::base::PlannerPtr planner = plannerByName(setup, o.planner);
    auto *gp = dynamic_cast<GridPlanner *>(planner.get());
    setup.ss->setPlanner(planner);
    const std::size_t n = o.limit ? std::min(o.limit, scen.size()) : scen.size();
    std::size_t matched = 0, solved = 0;
    std::uint64_t expanded = 0;
    double seconds = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const auto &e = scen[i];
        if (e.mapWidth != grid->width() || e.mapHeight != grid->height())
            throw InputError(o.scen + ": line " + std::to_string(i + 2) + " is for a " + std::to_string(e.mapWidth) +
                             " x " + std::to_string(e.mapHeight) + " map, not this one");
        setup.ss->clear();
        setup.setStartAndGoal({grid->cellCenterX(e.startX), grid->cellCenterY(e.startY), 0.0},
                              {grid->cellCenterX(e.goalX), grid->cellCenterY(e.goalY), 0.0});
        const auto t0 = Clock::now();
        const auto st = setup.ss->solve(60.0);
        seconds += std::chrono::duration<double>(Clock::now() - t0).count();
        if (st != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
        ++solved;
        const double len = gp ? gp->lastCost() : setup.ss->getSolutionPath().length();
        if (gp) expanded += gp->expandedNodes();
        if (std::abs(len - e.optimalLength) <= std::max(1e-3, 1e-5 * e.optimalLength)) ++matched;
        if ((i + 1) % 500 == 0) std::fprintf(stderr, "[scen] %zu / %zu queries\n", i + 1, n);
    }
    if (o.json)
    {
        nlohmann::json j;
        j["map"] = o.map;
        j["planner"] = o.planner;
        j["queries"] = n;
        j["solved"] = solved;
        j["matched"] = matched;
        j["seconds"] = seconds;
        j["queries_per_s"] = seconds > 0 ? n / seconds : 0.0;
        j["expanded"] = expanded;
        j["expansions_per_s"] = seconds > 0 ? expanded / seconds : 0.0;
        std::cout << j.dump() << "\n";
    }
    else
        std::printf("%s with %s: %zu / %zu paths match the published optimal length (%zu solved); %.3f ms per query, "
                    "%.2f M expansions/s\n",
                    o.map.c_str(), o.planner.c_str(), matched, n, solved, n ? 1000.0 * seconds / n : 0.0,
                    seconds > 0 ? expanded / seconds / 1e6 : 0.0);
    return matched == n ? 0 : 3;
}

}  // namespace gridcar::cli
