// gridcar drive (plan, then drive the path in the simulation) and gridcar paper-c (paper C's
// driving-time comparison).
#include "CliUtil.h"
#include "Commands.h"
#include "Query.h"

#include "gridcar/io/Render.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/objectives/Objectives.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/sim/Simulation.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

namespace gridcar::cli
{
namespace
{
namespace fs = std::filesystem;

/// x,y[,yaw] rows after a header line; InputError naming the file and line.
std::vector<Pose2> readPathCsv(const std::string &file)
{
    std::ifstream f(file);
    if (!f) throw InputError(file + ": cannot open the path file");
    std::vector<Pose2> path;
    std::string line;
    int n = 0;
    while (std::getline(f, line))
    {
        ++n;
        if (line.empty() || (n == 1 && line.find_first_of("0123456789") != 0 && line[0] != '-')) continue;
        std::stringstream ss(line);
        std::string item;
        std::vector<double> v;
        while (std::getline(ss, item, ','))
        {
            try
            {
                std::size_t used = 0;
                v.push_back(std::stod(item, &used));
            }
            catch (const std::exception &)
            {
                throw InputError(file + ": line " + std::to_string(n) + ": '" + item + "' is not a number");
            }
        }
        if (v.size() < 2 || v.size() > 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]))
            throw InputError(file + ": line " + std::to_string(n) + ": expected x,y[,yaw] (finite numbers)");
        path.push_back({v[0], v[1], v.size() == 3 ? v[2] : 0.0});
    }
    if (path.size() < 2) throw InputError(file + ": a path needs at least two points");
    return path;
}

/// A picture of the path, the trajectory and the moving obstacles (their routes and where
/// they were every 10 s), cropped to what was driven.
void drawDrive(const OccupancyGrid &grid, const std::vector<Pose2> &path, const DriveResult &r, const Scenario &sc,
               const std::string &png)
{
    WorldBox box;
    for (const Pose2 &p : path) box.add(p.x, p.y);
    for (const TrajectorySample &q : r.trajectory) box.add(q.x, q.y);
    const OccupancyGrid crop = cropAround(grid, box, 8.0);
    MapCanvas canvas(crop, 1200);
    for (const MovingObstacle &o : sc.obstacles)
    {
        canvas.polyline(o.waypoints, {230, 150, 40}, 1);
        for (double t = 0; !r.trajectory.empty() && t <= r.trajectory.back().t; t += 10.0)
        {
            double ox, oy;
            o.positionAt(t, ox, oy);
            canvas.disc(ox, oy, 4, {230, 150, 40});
        }
    }
    std::vector<std::pair<double, double>> pp, tp;
    for (const Pose2 &p : path) pp.push_back({p.x, p.y});
    for (const TrajectorySample &q : r.trajectory) tp.push_back({q.x, q.y});
    canvas.polyline(pp, {40, 80, 220}, 2);
    canvas.polyline(tp, {220, 30, 30}, 1);
    if (!tp.empty()) canvas.disc(tp.back().first, tp.back().second, 5, {220, 30, 30});
    canvas.disc(path.front().x, path.front().y, 5, {0, 0, 0});
    canvas.save(png);
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
}  // namespace

int runDrive(const DriveOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const PlanOptions &p = o.plan;
    if (!(o.dt > 0) || o.dt > 1.0) throw InputError("--dt must be in (0, 1] s");
    if (!(o.xi >= 0) || !(o.eta >= 0) || !(o.rho0 > 0) || !std::isfinite(o.xi + o.eta + o.rho0))
        throw InputError("--xi and --eta must be >= 0 and --rho0 > 0 (finite)");
    auto grid = std::make_shared<OccupancyGrid>(loadMap(p.map));
    grid->setUnknownIsFree(p.unknownFree);
    const VehicleParams vehicle = loadVehicle(p.vehicle);
    Scenario sc;
    if (!o.scenario.empty()) sc = Scenario::load(o.scenario);
    GridSetup setup = makeGridSetup(grid, vehicle);
    nlohmann::json j;
    std::vector<Pose2> path;
    if (!o.pathCsv.empty())
    {
        path = readPathCsv(o.pathCsv);
        if (!setup.checker->isValid(path.front()))
            throw InputError(o.pathCsv + ": the path starts " + describe(path.front()) + " off the map or in collision");
        j["plan"] = {{"path_file", o.pathCsv}};
    }
    else
    {
        if (p.planner.empty()) throw InputError("give --planner NAME (with --start / --goal) or --path path.csv");
        bool startYaw = false, goalYaw = false;
        const Pose2 start = parsePose(p.start, p.startCell, "start", *grid, startYaw);
        const Pose2 goal = parsePose(p.goal, p.goalCell, "goal", *grid, goalYaw);
        if (!setup.checker->isValid(start)) throw InputError("start " + describe(start) + " is off the map or in collision");
        if (!setup.checker->isValid(goal)) throw InputError("goal " + describe(goal) + " is off the map or in collision");
        const ompl::base::PlannerPtr planner = plannerByName(setup, p.planner);
        if (!startYaw) freeStartHeading(*planner);
        applyParams(*planner, p.params);
        const QueryResult q = runQuery(setup, planner, start, goal, p.timeLimit, p.smooth);
        j["plan"] = {{"planner", p.planner},         {"status", q.status.asString()}, {"cost", q.cost},
                     {"length", q.metrics.length},   {"expanded", q.expanded},        {"turns", q.metrics.turns},
                     {"max_turn_deg", q.maxTurnDeg}, {"time", q.seconds},             {"min_clearance", q.metrics.minClearance},
                     {"driving_time_profile", drivingTime(q.path, vehicle)}};
        if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
        {
            j["outcome"] = "no plan";
            if (o.json) std::cout << j.dump() << "\n";
            std::fprintf(stderr, "%s: %s, nothing to drive\n", p.planner.c_str(), q.status.asString().c_str());
            return 3;
        }
        path = q.path;
    }
    FollowerParams fp;
    fp.dt = o.dt;
    fp.xi = o.xi;
    fp.eta = o.eta;
    fp.rho0 = o.rho0;
    const DriveResult r = drivePath(path, *setup.checker, sc, fp);
    const nlohmann::json dj = driveJson(r);  // (items() of a temporary would dangle)
    for (const auto &kv : dj.items()) j[kv.key()] = kv.value();
    if (o.json)
        std::cout << j.dump() << "\n";
    else
        std::printf("%s: %s in %.2f s of driving (%.1f m path, %.1f m driven), cross-track mean %.2f m / max %.2f m, "
                    "min clearance %.2f m, %d recoveries\n",
                    DriveResult::outcomeName(r.outcome).c_str(), r.reason.c_str(), r.drivingTime, r.pathLength,
                    r.distanceDriven, r.crossTrackMean, r.crossTrackMax, r.minClearance, r.recoveries);
    if (!o.trajectoryCsv.empty())
    {
        std::ofstream f(o.trajectoryCsv);
        if (!f) throw InputError("cannot write " + o.trajectoryCsv);
        f << "t,x,y,yaw,v,steer\n";
        f.precision(10);
        for (const TrajectorySample &q : r.trajectory) f << q.t << "," << q.x << "," << q.y << "," << q.yaw << "," << q.v << "," << q.steer << "\n";
    }
    if (!o.png.empty()) drawDrive(*grid, path, r, sc, o.png);
    return r.outcome == DriveResult::Outcome::Reached ? 0 : 3;
}

// ------------------------------------------------------------------ paper C
namespace
{
struct PairResult
{
    std::string map, vehicle;
    int pair{0};
    double straight{0.0};  ///< m between start and goal
    std::vector<std::string> planners;
    std::vector<double> length, turnsV, profileTime, simTime;
    std::vector<std::string> outcome;
};

/// Random start / goal pairs, 80 - 300 m apart, on free cells at least max(1.5 m, 1.5 x the
/// vehicle's width + 0.3 m) from obstacles (road centres for the car), at a heading where the
/// vehicle fits.
std::vector<std::pair<Pose2, Pose2>> randomPairs(const GridSetup &s, int n, unsigned long long seed)
{
    const double minDist = std::max(1.5, 1.5 * s.checker->vehicle().width + 0.3);
    std::mt19937_64 rng(seed);
    const OccupancyGrid &g = *s.grid;
    std::uniform_int_distribution<int> col(0, g.width() - 1), row(0, g.height() - 1);
    auto pick = [&](Pose2 &p) {
        for (int k = 0; k < 200000; ++k)
        {
            const int c = col(rng), r = row(rng);
            if (g.isBlocked(c, r) || s.field->cellDistance(c, r) < minDist) continue;
            for (int a = 0; a < 8; ++a)
            {
                const double yaw = GridSE2StateSpace::wrapYaw(a * M_PI / 4);
                if (s.checker->isValid(g.cellCenterX(c), g.cellCenterY(r), yaw))
                {
                    p = {g.cellCenterX(c), g.cellCenterY(r), yaw};
                    return true;
                }
            }
        }
        return false;
    };
    std::vector<std::pair<Pose2, Pose2>> out;
    for (int tries = 0; int(out.size()) < n && tries < 50 * n; ++tries)
    {
        Pose2 a, b;
        if (!pick(a) || !pick(b)) break;
        const double d = std::hypot(a.x - b.x, a.y - b.y);
        if (d < 80.0 || d > 300.0) continue;
        out.push_back({a, b});
    }
    return out;
}

}  // namespace

int runPaperC(const PaperCOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    if (o.pairs < 1 || o.pairs > 1000) throw InputError("--pairs must be in 1..1000");
    if (!(o.timeLimit > 0.0) || !std::isfinite(o.timeLimit) || o.timeLimit > 86400)
        throw InputError("--time-limit must be a positive number of seconds (at most a day)");
    fs::create_directories(o.outDir);
    struct MapCase
    {
        std::string key;
        std::shared_ptr<const OccupancyGrid> grid;
    };
    std::vector<MapCase> maps{{"campus", std::make_shared<const OccupancyGrid>(generateCampus())}};
    const fs::path tsu = fs::path(o.sharedDir) / "maps/ros/tsudanuma_campus/tsudanuma_all.yaml";
    if (fs::exists(tsu))
        maps.push_back({"tsudanuma-0.298", std::make_shared<const OccupancyGrid>(loadMap(tsu.string()).resampled(0.298))});
    else
        std::fprintf(stderr, "[paper-c] %s not found: only the embedded campus map is run\n", tsu.string().c_str());
    const std::vector<std::pair<std::string, std::vector<std::string>>> configs = {
        {"astar-euclidean", {}}, {"corner-astar", {"weights=paper"}}, {"corner-astar", {"weights=physics"}}};
    const std::vector<std::string> labels = {"A* Euclidean", "corner A* (paper weights)", "corner A* (physics weights)"};
    std::vector<PairResult> all;
    nlohmann::json js = nlohmann::json::array();
    const auto t0 = std::chrono::steady_clock::now();
    std::ostringstream md;
    for (const MapCase &mc : maps)
        for (const std::string vname : {"paper-c-robot", "paper-c-car"})
        {
            std::fprintf(stderr, "[paper-c] %s with %s: distance field, footprint checker, %d pairs\n", mc.key.c_str(),
                         vname.c_str(), o.pairs);
            GridSetup setup = makeGridSetup(mc.grid, VehicleParams::preset(vname));
            const auto pairs = randomPairs(setup, o.pairs, o.seed);
            for (std::size_t k = 0; k < pairs.size(); ++k)
            {
                PairResult pr;
                pr.map = mc.key;
                pr.vehicle = vname;
                pr.pair = int(k + 1);
                pr.straight = std::hypot(pairs[k].first.x - pairs[k].second.x, pairs[k].first.y - pairs[k].second.y);
                for (std::size_t c = 0; c < configs.size(); ++c)
                {
                    ompl::base::PlannerPtr pl = makePlanner(setup.ss->getSpaceInformation(), configs[c].first);
                    freeStartHeading(*pl);
                    applyParams(*pl, configs[c].second);
                    const QueryResult q = runQuery(setup, pl, pairs[k].first, pairs[k].second, o.timeLimit, false);
                    pr.planners.push_back(labels[c]);
                    if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
                    {
                        pr.length.push_back(NAN), pr.turnsV.push_back(NAN), pr.profileTime.push_back(NAN), pr.simTime.push_back(NAN);
                        pr.outcome.push_back("no plan (" + q.status.asString() + ")");
                        continue;
                    }
                    FollowerParams fp;
                    fp.recordTrajectory = false;
                    const DriveResult r = drivePath(q.path, *setup.checker, Scenario(), fp);
                    pr.length.push_back(q.metrics.length);
                    pr.turnsV.push_back(q.metrics.turns);
                    pr.profileTime.push_back(drivingTime(q.path, setup.checker->vehicle()));
                    pr.simTime.push_back(r.outcome == DriveResult::Outcome::Reached ? r.drivingTime : NAN);
                    pr.outcome.push_back(DriveResult::outcomeName(r.outcome));
                }
                const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                std::fprintf(stderr, "[paper-c] %s %s pair %zu/%zu: A* %.1f s, corner paper %.1f s, corner physics %.1f s "
                                     "(simulated; elapsed %.0f s)\n",
                             mc.key.c_str(), vname.c_str(), k + 1, pairs.size(), pr.simTime[0], pr.simTime[1], pr.simTime[2], el);
                nlohmann::json jp = {{"map", pr.map}, {"vehicle", pr.vehicle}, {"pair", pr.pair}, {"straight", pr.straight},
                                     {"start", {pairs[k].first.x, pairs[k].first.y}}, {"goal", {pairs[k].second.x, pairs[k].second.y}}};
                for (std::size_t c = 0; c < configs.size(); ++c)
                    jp[labels[c]] = {{"length", pr.length[c]}, {"turns", pr.turnsV[c]}, {"profile_time", pr.profileTime[c]},
                                     {"sim_time", pr.simTime[c]}, {"outcome", pr.outcome[c]}};
                js.push_back(jp);
                all.push_back(pr);
            }
        }
    // tables: per pair and aggregate, per map and vehicle
    auto pct = [](double a, double b) { return 100.0 * (b - a) / a; };
    md << "| map | vehicle | pairs driven by all three | A* total s | corner (paper) total s | change | corner (physics) "
          "total s | change | per-pair change, paper weights: median (min .. max) | physics weights: median (min .. max) |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const MapCase &mc : maps)
        for (const std::string vname : {"paper-c-robot", "paper-c-car"})
        {
            double tot[3] = {0, 0, 0};
            std::vector<double> ch1, ch2;
            int n = 0;
            for (const PairResult &pr : all)
            {
                if (pr.map != mc.key || pr.vehicle != vname) continue;
                if (std::isnan(pr.simTime[0]) || std::isnan(pr.simTime[1]) || std::isnan(pr.simTime[2])) continue;
                ++n;
                for (int c = 0; c < 3; ++c) tot[c] += pr.simTime[c];
                ch1.push_back(pct(pr.simTime[0], pr.simTime[1]));
                ch2.push_back(pct(pr.simTime[0], pr.simTime[2]));
            }
            auto summary = [](std::vector<double> v) {
                if (v.empty()) return std::string("-");
                std::sort(v.begin(), v.end());
                const double med = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
                return fixed(med, 1) + " % (" + fixed(v.front(), 1) + " .. " + fixed(v.back(), 1) + ")";
            };
            md << "| " << mc.key << " | " << vname << " | " << n << " | " << fixed(tot[0], 1) << " | " << fixed(tot[1], 1) << " | "
               << (n ? fixed(pct(tot[0], tot[1]), 1) + " %" : "-") << " | " << fixed(tot[2], 1) << " | "
               << (n ? fixed(pct(tot[0], tot[2]), 1) + " %" : "-") << " | " << summary(ch1) << " | " << summary(ch2) << " |\n";
        }
    md << "\n### Per pair (simulated driving time s; length m; turns)\n\n"
          "| map | vehicle | pair | straight m | A* | corner (paper) | corner (physics) |\n|---|---|---|---|---|---|---|\n";
    for (const PairResult &pr : all)
    {
        md << "| " << pr.map << " | " << pr.vehicle << " | " << pr.pair << " | " << fixed(pr.straight, 0);
        for (int c = 0; c < 3; ++c)
            md << " | " << (std::isnan(pr.simTime[c]) ? pr.outcome[c] : fixed(pr.simTime[c], 1) + " s; " + fixed(pr.length[c], 0) +
                                                                             " m; " + fixed(pr.turnsV[c], 0));
        md << " |\n";
    }

    // corner-weight sweep: the paper's weights scaled, robot on the campus, the first pairs
    std::fprintf(stderr, "[paper-c] corner-weight sweep on the campus with paper-c-robot\n");
    GridSetup setup = makeGridSetup(maps.front().grid, VehicleParams::preset("paper-c-robot"));
    const auto pairs = randomPairs(setup, std::min(o.pairs, 10), o.seed);
    std::vector<double> base(pairs.size(), NAN);
    md << "\n### Corner-weight sweep (paper-c-robot, campus, " << pairs.size()
       << " pairs; weights = factor x (2.7, 7.0, 11.3) m)\n\n| factor | total simulated driving time s | change vs A* | "
          "total length m | total turns |\n|---|---|---|---|---|\n";
    nlohmann::json jsweep = nlohmann::json::array();
    for (double f : {-1.0, 0.0, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0})
    {
        double tt = 0, tl = 0, tn = 0, baseTotal = 0;  // baseTotal: A* on the same pairs
        int ok = 0;
        for (std::size_t k = 0; k < pairs.size(); ++k)
        {
            ompl::base::PlannerPtr pl = makePlanner(setup.ss->getSpaceInformation(), f < 0 ? "astar-euclidean" : "corner-astar");
            freeStartHeading(*pl);
            if (f >= 0)
                applyParams(*pl, {"corner_weight_45=" + std::to_string(2.7 * f), "corner_weight_90=" + std::to_string(7.0 * f),
                                  "corner_weight_135=" + std::to_string(11.3 * f)});
            const QueryResult q = runQuery(setup, pl, pairs[k].first, pairs[k].second, o.timeLimit, false);
            if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
            FollowerParams fp;
            fp.recordTrajectory = false;
            const DriveResult r = drivePath(q.path, *setup.checker, Scenario(), fp);
            if (r.outcome != DriveResult::Outcome::Reached) continue;
            if (f < 0) base[k] = r.drivingTime;
            if (std::isnan(base[k])) continue;
            tt += r.drivingTime;
            baseTotal += base[k];
            tl += q.metrics.length;
            tn += q.metrics.turns;
            ++ok;
        }
        md << "| " << (f < 0 ? std::string("A* Euclidean") : fixed(f, 2)) << " | " << fixed(tt, 1) << " (" << ok << " pairs) | "
           << (f < 0 ? std::string("-") : fixed(pct(baseTotal, tt), 1) + " %") << " | " << fixed(tl, 0) << " | " << fixed(tn, 0) << " |\n";
        jsweep.push_back({{"factor", f}, {"total_time", tt}, {"pairs", ok}, {"total_length", tl}, {"total_turns", tn}});
        std::fprintf(stderr, "[paper-c] sweep factor %g: %.1f s over %d pairs\n", f, tt, ok);
    }
    std::ofstream(fs::path(o.outDir) / "paper_c_tables.md") << md.str();
    std::ofstream(fs::path(o.outDir) / "paper_c.json") << nlohmann::json{{"pairs", js}, {"sweep", jsweep}}.dump(1) << "\n";
    std::fprintf(stderr, "[paper-c] wrote %s/paper_c_tables.md and paper_c.json\n", o.outDir.c_str());
    return 0;
}

}  // namespace gridcar::cli
