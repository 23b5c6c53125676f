// gridcar navigate: plan, drive with paper C's follower while a range sensor watches the true
// world, and replan from where the vehicle is (rolling on) when the path ahead is blocked (Navigator).
#include "Cli.h"

#include "gridcar/bench/Figure.h"
#include "gridcar/bench/Quantile.h"
#include "gridcar/query/Navigate.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace gridcar::cli
{
namespace
{
struct NavigateOptions
{
    QueryArgs query;
    std::string scenario, world;
    RangeSensorParams sensor;
    int maxReplans{30};
    bool stopToReplan{false};
    bool json{false};
    std::string png, trajectoryCsv;
};

/// The given map's cells the sensor marked (occupied now, not before).
std::vector<Cell> sensedCells(const OccupancyGrid &given, const OccupancyGrid &working)
{
    std::vector<Cell> out;
    for (int r = 0; r < given.height(); ++r)
        for (int c = 0; c < given.width(); ++c)
            if (working.at(c, r) == CellState::Occupied && given.at(c, r) != CellState::Occupied) out.push_back({c, r});
    return out;
}

void drawNavigation(const Query &query, const NavigationResult &r, const Scenario &sc, const std::vector<Cell> &sensed,
                    const std::string &png)
{
    bench::Figure fig;
    fig.title = "navigate: " + NavigationResult::outcomeName(r.outcome) + ", " + std::to_string(r.replans) + (r.replans == 1 ? " replan" : " replans");
    fig.vehicle = query.vehicle;
    fig.start = query.start;
    fig.goal = query.goal;
    fig.goalYaw = query.goalYaw;
    fig.margin = 6.0;
    if (!r.plans.empty()) fig.paths.push_back({"first plan (the map alone)", "tab:blue", r.plans.front(), false, 1.2});
    if (r.plans.size() > 1) fig.paths.push_back({"last plan", "tab:green", r.plans.back(), false, 1.2});
    std::vector<Pose2> driven;
    for (const TrajectorySample &q : r.trajectory) driven.push_back({q.x, q.y, q.yaw});
    if (driven.size() >= 2) fig.paths.push_back({"driven (simulation)", "tab:red", driven, true, 1.0});
    const double tEnd = r.trajectory.empty() ? 0.0 : r.trajectory.back().t;
    for (const MovingObstacle &o : sc.obstacles)
    {
        double x, y;
        o.positionAt(tEnd, x, y);
        bench::FigureMarkers m{o.name + " at the end", "tab:orange", "", "-", {}};
        if (o.shape == MovingObstacle::Shape::Box)
            m.points = {{x - o.sizeX / 2, y - o.sizeY / 2}, {x + o.sizeX / 2, y - o.sizeY / 2}, {x + o.sizeX / 2, y + o.sizeY / 2},
                        {x - o.sizeX / 2, y + o.sizeY / 2}, {x - o.sizeX / 2, y - o.sizeY / 2}};
        else
            for (int k = 0; k <= 24; ++k) m.points.push_back({x + o.radius * std::cos(k * M_PI / 12), y + o.radius * std::sin(k * M_PI / 12)});
        fig.markers.push_back(m);
        if (o.waypoints.size() > 1) fig.markers.push_back({o.name + " route", "tab:orange", "", "--", o.waypoints});
    }
    if (r.hasNearestReachable)
        fig.markers.push_back({"nearest reachable pose", "tab:purple", "*", "none", {{r.nearestReachable.x, r.nearestReachable.y}}});
    fig.tinted = sensed;
    fig.tintLabel = "seen by the sensor, not in the map";
    fig.tintColour = {255, 190, 120};
    bench::drawFigure(*query.grid, fig, png, "navigate");
}

int runNavigate(const NavigateOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    if (!(o.sensor.range > 0) || !std::isfinite(o.sensor.range)) throw InputError("--range must be > 0 m");
    if (!(o.sensor.period > 0) || o.sensor.period > 5.0) throw InputError("--scan-period must be in (0, 5] s");
    if (o.sensor.beams < 8 || o.sensor.beams > 100000) throw InputError("--beams must be in [8, 100000]");
    if (o.maxReplans < 0) throw InputError("--max-replans must be >= 0");
    QueryArgs qa = o.query;
    if (qa.planner.empty()) qa.planner = "corner-astar";
    Query query = loadQuery(qa, true);
    for (const auto &[what, pose] : {std::make_pair(std::string("start"), query.start), std::make_pair(std::string("goal"), query.goal)})
        if (const std::string why = whyInvalid(query, pose, what == "goal" && !query.goalYaw); !why.empty())
            throw InputError(what + " " + describe(pose) + " is " + why);
    const Scenario sc = loadScenarioOnMap(o.scenario, *query.grid);
    std::shared_ptr<OccupancyGrid> world;
    if (!o.world.empty())
    {
        world = std::make_shared<OccupancyGrid>(loadMapArgument(o.world));
        world->setUnknownIsFree(qa.unknownFree);
        if (!world->sameFrame(*query.grid))
            throw InputError("--world " + o.world + ": " + std::to_string(world->width()) + " x " + std::to_string(world->height()) +
                             " cells, the map " + std::to_string(query.grid->width()) + " x " + std::to_string(query.grid->height()) +
                             ": the true world must have the map's size, resolution and origin");
    }
    NavigationOptions no;
    no.planner.name = qa.planner;
    no.planner.params = parsePlannerParams(qa.params);
    no.planner.smooth = qa.smooth;
    no.setup.space = query.setup.kind;
    no.planTimeLimit = qa.timeLimit;
    no.goalTolerance = query.goalTolerance;
    no.sensor = o.sensor;
    no.maxReplans = o.maxReplans;
    no.replanRolling = !o.stopToReplan;
    Navigator nav(query.grid, query.vehicle, no, world);
    const NavigationResult r = nav.run(query.start, query.goal, !query.goalYaw, sc);
    std::vector<double> replans = r.replanSeconds;
    const double med = replans.empty() ? 0.0 : quantile(replans, 0.5), worst = replans.empty() ? 0.0 : quantile(replans, 1.0);
    if (o.json)
    {
        nlohmann::json j{{"outcome", NavigationResult::outcomeName(r.outcome)},
                         {"reason", r.reason},
                         {"driving_time", r.drivingTime},
                         {"distance_driven", r.distanceDriven},
                         {"min_clearance", r.minClearance},
                         {"replans", r.replans},
                         {"rolling_replans", r.rollingReplans},
                         {"stalls", r.stalls},
                         {"retreats", r.retreats},
                         {"replan_seconds", r.replanSeconds},
                         {"sensed_cells", r.sensedCells},
                         {"final_pose", {{"x", r.finalPose.x}, {"y", r.finalPose.y}, {"yaw_rad", r.finalPose.yaw}}}};
        if (r.hasNearestReachable)
            j["nearest_reachable"] = {{"x", r.nearestReachable.x}, {"y", r.nearestReachable.y}, {"yaw_rad", r.nearestReachable.yaw}};
        printJson(j.dump());
    }
    else
    {
        std::printf("%s: %s; %.2f s of driving, %.1f m driven, min clearance %.2f m; %d replans (%d driven on into while rolling; "
                    "update + search median %.1f ms, max %.1f ms), %d retreats, %zu cells seen that the map did not show\n",
                    NavigationResult::outcomeName(r.outcome).c_str(), r.reason.c_str(), r.drivingTime, r.distanceDriven,
                    std::isfinite(r.minClearance) ? r.minClearance : 0.0, r.replans, r.rollingReplans, 1e3 * med, 1e3 * worst,
                    r.retreats, r.sensedCells);
        if (r.hasNearestReachable) std::printf("nearest reachable pose: %s\n", describe(r.nearestReachable).c_str());
    }
    if (!o.trajectoryCsv.empty()) writeTrajectoryCsv(o.trajectoryCsv, r.trajectory);
    if (!o.png.empty()) drawNavigation(query, r, sc, sensedCells(*query.grid, nav.workingMap()), o.png);
    return r.outcome == NavigationResult::Outcome::Reached ? 0 : 3;
}
}  // namespace

Command addNavigateCommand(CLI::App &app)
{
    auto o = std::make_shared<NavigateOptions>();
    auto *c = app.add_subcommand("navigate", "Plan, drive with paper C's follower while a simulated range sensor watches the "
                                             "true world (the map plus --scenario's obstacles), and replan from where the "
                                             "vehicle is when an obstacle the map did not show blocks the path ahead (it "
                                             "rolls on along the old path while the plan is made, then drives on into the new "
                                             "path where that lets it, else stops first)");
    addQueryOptions(c, o->query, false);
    c->add_option("--scenario", o->scenario,
                  "The obstacles the map does not show (YAML: obstacles: [{shape, radius | size, waypoints, speed, start_time, "
                  "loop}]); standing ones are mapped when seen, moving ones left to the follower");
    c->add_option("--world", o->world, "The true map, when it differs from --map (the same size, resolution and origin)");
    c->add_option("--range", o->sensor.range, "Range of the sensor (360 degrees, at the vehicle's reference point), m")->capture_default_str();
    c->add_option("--beams", o->sensor.beams, "Beams of the sensor over 360 degrees")->capture_default_str();
    c->add_option("--scan-period", o->sensor.period, "Time between scans, s")->capture_default_str();
    c->add_option("--max-replans", o->maxReplans, "Replans before the run ends as stuck")->capture_default_str();
    c->add_flag("--stop-to-replan", o->stopToReplan,
                "Brake to a standstill before every replan and wait for the plan (by default the vehicle rolls on along its "
                "old path while the plan is made and then drives on into the new path when that passes where it has got to, "
                "in its gear, longer than its stopping distance, with no bend that asks it to brake hard or to turn its wheels "
                "faster than they can)");
    c->add_flag("--json", o->json,
                "Print one JSON object: outcome (reached | goal blocked | no path | collided | stuck | timeout), reason, "
                "driving_time, distance_driven, min_clearance, replans, rolling_replans (driven on into without stopping), stalls, retreats (backing up along the track where no plan "
                "started), replan_seconds (each: the map updates "
                "since the last plan + the search), sensed_cells, final_pose, nearest_reachable (a blocked goal)");
    c->add_option("--png", o->png, "Picture (axes in metres, legend): the first plan (blue), the last (green), the drive (red, "
                                   "with the vehicle's outline), the obstacles at the end (orange), the cells the sensor "
                                   "added to the map (tinted)");
    c->add_option("--out", o->trajectoryCsv, "Trajectory CSV: t (s), x, y (m), yaw_rad, v (m/s), steer_rad");
    c->footer("The planner defaults to corner-astar; --time-limit is each plan's. A start without a yaw gets the first "
              "heading at which the vehicle fits.\nExit status: 0 reached, 3 goal blocked / no path / collided / stuck / "
              "timeout, 2 bad input, 1 internal error.");
    return {c, [o] {
                applyParamsFile(o->query, false);
                return runNavigate(*o);
            }};
}

}  // namespace gridcar::cli
