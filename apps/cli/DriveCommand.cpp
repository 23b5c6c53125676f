// gridcar drive: plan a path (or read one), then drive it with paper C's potential-field
// follower in the kinematic simulation, with optional moving obstacles.
#include "Cli.h"

#include "gridcar/bench/Figure.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/path/PathIO.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace gridcar::cli
{
Scenario loadScenarioOnMap(const std::string &file, const OccupancyGrid &g)
{
    Scenario sc;
    if (file.empty()) return sc;
    sc = Scenario::load(file);
    // a waypoint off the map is a mistake in the file (a wrong frame, a typo), not a scenario
    for (std::size_t i = 0; i < sc.obstacles.size(); ++i)
        for (const auto &[x, y] : sc.obstacles[i].waypoints)
            if (!(x >= g.originX() && x <= g.originX() + g.sizeX() && y >= g.originY() && y <= g.originY() + g.sizeY()))
                throw MapLoadError(file, "obstacle " + std::to_string(i + 1) + " (" + sc.obstacles[i].name +
                                             "): waypoint " + describe({x, y, 0.0}) + " is outside the map (x " +
                                             std::to_string(g.originX()) + " .. " + std::to_string(g.originX() + g.sizeX()) +
                                             ", y " + std::to_string(g.originY()) + " .. " +
                                             std::to_string(g.originY() + g.sizeY()) + ")");
    return sc;
}

void writeTrajectoryCsv(const std::string &file, const std::vector<TrajectorySample> &trajectory)
{
    std::ofstream f(file);
    if (!f) throw InputError("cannot write " + file);
    f << "t,x,y,yaw_rad,v,steer_rad\n";
    f.precision(10);
    for (const TrajectorySample &q : trajectory) f << q.t << "," << q.x << "," << q.y << "," << q.yaw << "," << q.v << "," << q.steer << "\n";
}

namespace
{
struct DriveOptions
{
    QueryArgs query;           ///< map, planner, start / goal, vehicle, params, time limit, smooth
    std::string pathCsv;       ///< drive this path (CSV, YAML or JSON poses) instead of planning
    std::string scenario;      ///< moving obstacles (YAML)
    double dt{0.05};
    double xi{1.0}, eta{0.6}, rho0{1.5};  ///< potential-field gains (FollowerParams)
    bool json{false};
    std::string png;
    std::string trajectoryCsv;
};

/// A picture of the path, the trajectory and the moving obstacles (their routes and where
/// they were every 10 s), around what was driven.
void drawDrive(const Query &query, const std::vector<Pose2> &path, const DriveResult &r, const Scenario &sc,
               const std::string &png)
{
    bench::Figure fig;
    fig.title = std::string("drive: ") + DriveResult::outcomeName(r.outcome);
    fig.vehicle = query.vehicle;
    fig.start = path.front();
    fig.goal = path.back();
    fig.margin = 6.0;
    fig.paths.push_back({"planned path", "tab:blue", path, false, 1.4});
    std::vector<Pose2> driven;
    for (const TrajectorySample &q : r.trajectory) driven.push_back({q.x, q.y, q.yaw});
    if (driven.size() >= 2) fig.paths.push_back({"driven (simulation)", "tab:red", driven, true, 1.0});
    if (!driven.empty()) fig.markers.push_back({"end of the drive", "tab:red", "X", "none", {{driven.back().x, driven.back().y}}});
    for (const MovingObstacle &o : sc.obstacles)
    {
        fig.markers.push_back({o.name + " route", "tab:orange", "", "--", o.waypoints});
        bench::FigureMarkers at{o.name + " every 10 s", "tab:orange", "o", "none", {}};
        for (double t = 0; !r.trajectory.empty() && t <= r.trajectory.back().t; t += 10.0)
        {
            double ox, oy;
            o.positionAt(t, ox, oy);
            at.points.push_back({ox, oy});
        }
        fig.markers.push_back(at);
    }
    bench::drawFigure(*query.grid, fig, png, "drive");
}

nlohmann::json driveJson(const DriveResult &r)
{
    return {{"outcome", DriveResult::outcomeName(r.outcome)},
            {"reason", r.reason},
            {"driving_time", r.drivingTime},
            {"path_length", r.pathLength},
            {"distance_driven", r.distanceDriven},
            {"cross_track_mean", r.crossTrackMean},
            {"cross_track_max", r.crossTrackMax},
            {"min_clearance", r.minClearance},
            {"recoveries", r.recoveries}};
}
/// The path to drive: planned (false when the planner found no exact solution) or read.
bool pathToDrive(const DriveOptions &o, Query &query, std::vector<Pose2> &path, nlohmann::json &j)
{
    if (!o.pathCsv.empty())
    {
        path = readPath(o.pathCsv);
        if (!query.setup.checker->isValid(path.front()))
            throw InputError(o.pathCsv + ": the path starts " + describe(path.front()) + " off the map or in collision");
        j["plan"] = {{"path_file", o.pathCsv}};
        return true;
    }
    const QueryArgs &p = o.query;
    for (const auto &[what, pose] : {std::make_pair(std::string("start"), query.start), std::make_pair(std::string("goal"), query.goal)})
        if (const std::string why = whyInvalid(query, pose, what == "start" ? !query.startYaw : !query.goalYaw); !why.empty())
            throw InputError(what + " " + describe(pose) + " is " + why);
    const QueryResult q = runQuery(query.setup, queryPlanner(p, query), query.start, query.goal, p.timeLimit, !query.goalYaw,
                                   query.goalTolerance);
    DrivingTimeParams profile;
    profile.reversing = query.setup.reversing();  // a stop at each Reeds-Shepp cusp
    j["plan"] = {{"planner", p.planner},         {"status", q.status.asString()}, {"cost", q.cost},
                 {"length", q.metrics.length},   {"expanded", q.expanded},        {"turns", q.metrics.turns},
                 {"max_turn_deg", q.maxTurnDeg}, {"max_turn_angle_deg", q.metrics.maxTurnAngleDeg}, {"time", q.seconds},             {"min_clearance", q.metrics.minClearance},
                 {"driving_time_profile", drivingTime(q.path, query.vehicle, profile)},
                 {"cusps", q.metrics.cusps},
                 {"drivable", q.drivability.drivable}};
    if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        std::fprintf(stderr, "%s: %s, nothing to drive\n", p.planner.c_str(), q.status.asString().c_str());
        return false;
    }
    path = q.path;
    return true;
}

int runDrive(const DriveOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    if (!(o.dt > 0) || o.dt > 1.0) throw InputError("--dt must be in (0, 1] s");
    if (!(o.xi >= 0) || !(o.eta >= 0) || !(o.rho0 > 0) || !std::isfinite(o.xi + o.eta + o.rho0))
        throw InputError("--xi and --eta must be >= 0 and --rho0 > 0 (finite)");
    if (o.pathCsv.empty() && o.query.planner.empty()) throw InputError("give --planner NAME (with --start / --goal) or --path FILE (.csv, .yaml or .json)");
    Query query = loadQuery(o.query, o.pathCsv.empty());
    const Scenario sc = loadScenarioOnMap(o.scenario, *query.grid);
    nlohmann::json j;
    std::vector<Pose2> path;
    if (!pathToDrive(o, query, path, j))
    {
        j["outcome"] = "no plan";
        if (o.json) printJson(j.dump());
        return 3;
    }
    FollowerParams fp;
    fp.dt = o.dt;
    fp.xi = o.xi;
    fp.eta = o.eta;
    fp.rho0 = o.rho0;
    if (query.goalTolerance.position > 0) fp.goalTolerance = query.goalTolerance.position;
    if (query.goalTolerance.yaw > 0 && query.goalYaw) fp.goalYawTolerance = query.goalTolerance.yaw;
    const DriveResult r = drivePath(path, *query.setup.checker, sc, fp);
    const nlohmann::json dj = driveJson(r);  // (items() of a temporary would dangle)
    for (const auto &kv : dj.items()) j[kv.key()] = kv.value();
    if (o.json)
        printJson(j.dump());
    else
        std::printf("%s: %s in %.2f s of driving (%.1f m path, %.1f m driven), cross-track mean %.2f m / max %.2f m, "
                    "min clearance %.2f m, %d recoveries\n",
                    DriveResult::outcomeName(r.outcome).c_str(), r.reason.c_str(), r.drivingTime, r.pathLength,
                    r.distanceDriven, r.crossTrackMean, r.crossTrackMax, r.minClearance, r.recoveries);
    if (!o.trajectoryCsv.empty()) writeTrajectoryCsv(o.trajectoryCsv, r.trajectory);
    if (!o.png.empty()) drawDrive(query, path, r, sc, o.png);
    return r.outcome == DriveResult::Outcome::Reached ? 0 : 3;
}
}  // namespace

Command addDriveCommand(CLI::App &app)
{
    auto o = std::make_shared<DriveOptions>();
    auto *c = app.add_subcommand("drive", "Plan a path (or read one) and drive it with paper C's potential-field follower "
                                          "in the kinematic bicycle simulation, with optional moving obstacles");
    addQueryOptions(c, o->query, false);
    c->add_option("--path", o->pathCsv,
                  "Drive this path instead of planning: as plan --out writes it (.csv with a header x,y,yaw_deg or "
                  "x,y,yaw_rad (yaw: radians); .yaml / .json {frame_id, angle_unit: deg | rad, poses: [{x, y, yaw}]})");
    c->add_option("--scenario", o->scenario,
                  "Moving obstacles (YAML: obstacles: [{shape, radius | size, waypoints, speed, start_time, loop}])");
    c->add_option("--dt", o->dt, "Simulation step, s")->capture_default_str();
    c->add_option("--xi", o->xi, "Attractive gain of the potential field")->capture_default_str();
    c->add_option("--eta", o->eta, "Repulsive gain of the potential field")->capture_default_str();
    c->add_option("--rho0", o->rho0, "Influence distance of obstacles, m (beyond the body's half width)")->capture_default_str();
    c->add_flag("--json", o->json,
                "Print one JSON object: outcome (reached | collided | stuck | timeout), reason, driving_time, path_length, "
                "distance_driven, cross_track_mean, cross_track_max, min_clearance, recoveries, plan {...} (with "
                "driving_time_profile: the path at the vehicle's limits; the follower drives slower where an "
                "obstacle is within --rho0 of the body, so driving_time is longer indoors)");
    c->add_option("--png", o->png, "Picture (matplotlib, axes in metres, scale bar, legend): the path (blue), the trajectory (red, the "
                                   "vehicle's outline along it, reverse in purple), the moving obstacles (orange)");
    c->add_option("--out", o->trajectoryCsv, "Trajectory CSV: t (s), x, y (m), yaw_rad, v (m/s, negative in reverse), steer_rad");
    c->footer("Exit status: 0 reached, 3 collided / stuck / timeout (or no plan), 2 bad input, 1 internal error.");
    return {c, [o] {
                applyParamsFile(o->query, false);
                return runDrive(*o);
            }};
}

}  // namespace gridcar::cli
