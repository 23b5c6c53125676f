// gridcar plan: one query with any planner; the path as text, JSON, CSV and a picture.
#include "Cli.h"

#include "gridcar/bench/Figure.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/path/PathIO.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace gridcar::cli
{
namespace
{
struct PlanOptions
{
    QueryArgs query;
    bool json{false};
    std::string outCsv;
    std::string angleUnit{"deg"};
    std::string png;
    bool allowUndrivable{false};
};

/// How far the path's end is from the goal (m), and its heading from the goal's (deg, < 0:
/// no goal heading given).
std::pair<double, double> goalError(const QueryResult &q, const Query &query)
{
    if (q.path.empty()) return {NAN, -1.0};
    const Pose2 &e = q.path.back();
    const double d = std::hypot(e.x - query.goal.x, e.y - query.goal.y);
    const double h = query.goalYaw ? std::abs(std::remainder(e.yaw - query.goal.yaw, 2 * M_PI)) * 180.0 / M_PI : -1.0;
    return {d, h};
}

nlohmann::json resultJson(const QueryResult &q, const Query &query)
{
    const VehicleParams &vehicle = query.vehicle;
    const PathMetrics &m = q.metrics;
    nlohmann::json j;
    j["status"] = q.status.asString();
    if (!q.path.empty() && q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        // an approximate answer: how far from the goal it ends
        const auto [d, h] = goalError(q, query);
        j["goal_distance"] = d;
        if (h >= 0) j["goal_heading_error_deg"] = h;
    }
    j["cost"] = q.cost;
    j["length"] = m.length;
    j["expanded"] = q.expanded;
    j["turns"] = m.turns;
    j["max_turn_deg"] = q.maxTurnDeg;
    j["max_turn_angle_deg"] = m.maxTurnAngleDeg;
    j["min_clearance"] = m.minClearance;
    j["min_path_distance"] = m.minPathDistance;
    j["max_curvature"] = m.maxCurvature;
    j["max_curvature_rate"] = q.drivability.maxCurvatureRate;
    j["curvature_rate_limit"] = vehicle.curvatureRateLimit();
    j["within_curvature_rate"] = q.drivability.maxCurvatureRate <= 1.02 * vehicle.curvatureRateLimit();
    j["cusps"] = m.cusps;
    j["time"] = q.seconds;
    j["smoothing_time"] = q.smoothingSeconds;
    j["smoothed"] = q.smoothed;
    if (q.smoothed)
    {
        j["adjust_failures"] = q.adjustFailures;
        j["bezier_fallbacks"] = q.bezierFallbacks;
    }
    j["vehicle"] = vehicle.name;
    j["drivable"] = q.drivability.drivable;
    if (!q.notExactBecause.empty()) j["not_exact_because"] = q.notExactBecause;
    if (!q.drivability.drivable) j["not_drivable_because"] = q.drivability.reason;
    nlohmann::json jp = nlohmann::json::array();
    for (const Pose2 &p : q.path) jp.push_back({p.x, p.y, p.yaw});
    j["path"] = jp;
    return j;
}

void printResult(const std::string &planner, const QueryResult &q, const Query &query)
{
    const PathMetrics &m = q.metrics;
    std::printf("%s: %s in %.3f s", planner.c_str(), q.status.asString().c_str(), q.seconds);
    if (!q.path.empty() && q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        const auto [d, h] = goalError(q, query);
        std::printf(" (ends %.2f m from the goal", d);
        if (h >= 0) std::printf(", heading %.1f deg off", h);
        std::printf(")");
    }
    if (q.smoothed) std::printf(" (smoothing %.4f s)", q.smoothingSeconds);
    if (!q.notExactBecause.empty()) std::printf(" (%s)", q.notExactBecause.c_str());
    std::printf("\n  length %.2f m, cost %.2f, %d poses, %d turns (the largest %.0f deg; at one vertex up to %.1f deg), "
                "max curvature %.3f 1/m, min clearance %.2f m (path line %.2f m from obstacles)",
                m.length, q.cost, int(q.path.size()), m.turns, m.maxTurnAngleDeg, q.maxTurnDeg, m.maxCurvature,
                m.minClearance, m.minPathDistance);
    if (m.cusps) std::printf(", %d cusp(s)", m.cusps);
    if (q.expanded) std::printf(", %llu nodes expanded", (unsigned long long)q.expanded);
    if (!q.path.empty())
        std::printf("\n  %s; curvature rate up to %.3g 1/m^2", q.drivability.drivable ? "drivable: body free at 2 cm steps, curvature within K_max"
                                                      : ("NOT drivable: " + q.drivability.reason).c_str(), q.drivability.maxCurvatureRate);
    if (q.smoothed && q.adjustFailures + q.bezierFallbacks > 0)
        std::printf("\n  smoothing: %d corner(s) still above K_max, %d Bezier piece(s) collided and were kept sharp",
                    q.adjustFailures, q.bezierFallbacks);
    std::printf("\n");
}

std::string formatLength(double metres)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f m", metres);
    return buf;
}

void drawPlan(const std::string &png, const Query &query, const ompl::base::Planner &planner, const QueryResult &q,
              const std::string &name)
{
    bench::Figure fig;
    fig.title = name + ": " + q.status.asString() + (q.path.empty() ? std::string() : " (" + formatLength(q.metrics.length) + ")");
    fig.vehicle = query.vehicle;
    fig.start = query.start;
    fig.goal = query.goal;
    fig.goalYaw = query.goalYaw;
    if (!query.startYaw && !q.path.empty()) fig.start.yaw = q.path.front().yaw;  // the heading the planner chose
    fig.tinted = exploredCells(planner, *query.grid);
    if (q.smoothed) fig.paths.push_back({"before smoothing", "tab:orange", q.rawPath, false, 1.0});
    fig.paths.push_back({name, "tab:blue", q.path, true, 1.8});
    bench::drawFigure(*query.grid, fig, png, "plan");
}

int planAndReport(const PlanOptions &o, bool &printed);

int runPlan(const PlanOptions &o)
{
    if (!o.outCsv.empty() && pathFormatOf(o.outCsv).empty())
        throw InputError("--out " + o.outCsv + ": the path file must end in .csv, .yaml, .yml or .json");
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // with --json, one JSON object on stdout whatever happens (a bad input too)
    bool printed = false;
    try
    {
        return planAndReport(o, printed);
    }
    catch (const std::exception &e)
    {
        // (the exception goes on to main(): its message on stderr, its exit status)
        const bool bad = dynamic_cast<const InputError *>(&e) || dynamic_cast<const MapLoadError *>(&e) ||
                         dynamic_cast<const std::invalid_argument *>(&e) || dynamic_cast<const ompl::Exception *>(&e);
        if (o.json && !printed)
            printJson(nlohmann::json{{"planner", o.query.planner}, {"status", bad ? "Invalid input" : "Internal error"}, {"error", e.what()}}
                          .dump());
        throw;
    }
}

int planAndReport(const PlanOptions &o, bool &printed)
{
    Query query = loadQuery(o.query, true);
    const ompl::base::PlannerPtr planner = queryPlanner(o.query, query);
    // the same checks for every planner (OMPL's own planners do not all check the goal)
    for (const auto &[what, pose] : {std::make_pair(std::string("start"), query.start), std::make_pair(std::string("goal"), query.goal)})
    {
        const std::string why = whyInvalid(query, pose, what == "start" ? !query.startYaw : !query.goalYaw);
        if (why.empty()) continue;
        const std::string msg = what + " " + describe(pose) + " is " + why;
        if (o.json)
            printJson(nlohmann::json{{"planner", o.query.planner}, {"status", "Invalid " + what}, {"error", msg}}.dump());
        printed = o.json;
        throw InputError(msg);
    }
    const QueryResult q = runQuery(query.setup, planner, query.start, query.goal, o.query.timeLimit, !query.goalYaw,
                                   query.goalTolerance);
    if (o.json)
    {
        nlohmann::json j = resultJson(q, query);
        j["planner"] = o.query.planner;
        printJson(j.dump());
        printed = true;
    }
    else
        printResult(o.query.planner, q, query);
    if (!o.outCsv.empty()) writePath(o.outCsv, q.path, o.angleUnit == "rad" ? AngleUnit::Radians : AngleUnit::Degrees);
    if (!o.png.empty()) drawPlan(o.png, query, *planner, q, o.query.planner);
    if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION) return 3;
    // an exact solution the independent check finds undrivable is not a plan to drive
    if (!q.drivability.drivable && !o.allowUndrivable)
    {
        std::fprintf(stderr,
                     "gridcar: the path is NOT drivable (%s): exit 4 (--allow-undrivable exits 0 for an exact solution "
                     "whatever the check says; the car-lattice planners corner-astar and improved-astar plan drivable paths)\n",
                     q.drivability.reason.c_str());
        return 4;
    }
    return 0;
}
}  // namespace

Command addPlanCommand(CLI::App &app)
{
    auto o = std::make_shared<PlanOptions>();
    auto *c = app.add_subcommand("plan", "Plan one path on a map with a grid planner or an OMPL planner");
    addQueryOptions(c, o->query, true);
    c->add_flag("--json", o->json,
                "Print one JSON object: status, planner, cost, length, expanded, turns, max_turn_deg (at one vertex: depends on the sampling), max_turn_angle_deg (of one turn: does not), max_curvature, "
                "max_curvature_rate (1/m^2, fastest change of curvature), curvature_rate_limit (the vehicle's), "
                "within_curvature_rate, cusps, "
                "min_path_distance, smoothing_time, min_clearance, time, drivable (and not_drivable_because), not_exact_because "
                "(a grid planner stopped at its memory bound, a goal proven unreachable), goal_distance and "
                "goal_heading_error_deg (an approximate path's end), "
                "path [[x, y, yaw_rad], ...]; on bad input {planner, status, error}");
    c->add_option("--out", o->outCsv,
                  "Write the path, the format from the extension: .csv (header x,y,yaw_deg), .yaml / .yml or .json "
                  "({frame_id: map, angle_unit: deg, poses: [{x, y, yaw}]}); x, y in metres in the map frame");
    c->add_option("--angle-unit", o->angleUnit, "Unit of the yaw in the --out file (named in the file)")
        ->check(CLI::IsMember({"deg", "rad"}))
        ->capture_default_str();
    c->add_option("--png", o->png, "Write a picture (matplotlib): the map around the path with axes in metres, a scale "
                                   "bar and a legend; the path with the vehicle's outline along it (reverse segments in "
                                   "purple), before smoothing in orange, the cells the planner explored in light blue; "
                                   "start black, goal magenta as in gridcar bench");
    c->add_flag("--allow-undrivable", o->allowUndrivable,
                "Exit 0 for an exact solution even when the independent check finds the path not drivable (default: "
                "exit 4)");
    c->footer("Exit status: 0 exact solution (and drivable: full body free at 2 cm steps, curvature within K_max), 4 "
              "exact solution that the check finds NOT drivable (a grid search's or a sampling planner's path on the se2 "
              "space; --allow-undrivable exits 0), 3 no exact solution (timeout / approximate / goal proven "
              "unreachable; the path's end is given as its distance and heading from the goal), 2 bad input "
              "(including a start or goal off the map or in collision; with --json one JSON object with status and "
              "error), 1 internal error.");
    return {c, [o] {
                applyParamsFile(o->query, true);
                return runPlan(*o);
            }};
}

}  // namespace gridcar::cli
