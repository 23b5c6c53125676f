// gridcar bench PROBLEM.yaml: ompl::tools::Benchmark of our planners against OMPL's on one
// problem file, then the SQLite database (ompl_benchmark_statistics) and the report.
#include "CliUtil.h"
#include "Commands.h"

#include "gridcar/io/Render.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/objectives/Objectives.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/geometric/PathGeometric.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>

#ifndef GRIDCAR_REPORT_SCRIPT
#define GRIDCAR_REPORT_SCRIPT "scripts/bench_report.py"
#endif
#ifndef GRIDCAR_INSTALLED_REPORT_SCRIPT
#define GRIDCAR_INSTALLED_REPORT_SCRIPT "../share/gridcar/bench_report.py"  // relative to the executable
#endif

namespace gridcar::cli
{
namespace
{
namespace fs = std::filesystem;

struct QuerySpec
{
    Pose2 start, goal;
    bool startYaw{false};
};

struct PlannerSpec
{
    std::string name, label;
    std::vector<std::pair<std::string, std::string>> params;
};

struct Problem
{
    std::string file, name, map, vehicle{"paper-i"}, objective{"length"};
    bool unknownFree{false};
    double delta{1.0};
    double resample{0.0};  ///< > 0: resample the map to this many metres per cell
    double timeLimit{5.0};
    double memoryMb{4096.0};
    unsigned runs{3};
    std::vector<YAML::Node> queries;
    std::vector<PlannerSpec> planners;
};

[[noreturn]] void bad(const Problem &p, const std::string &why) { throw InputError(p.file + ": " + why); }

Problem readProblem(const std::string &file, const std::string &sharedDir, bool &skip, std::string &skipWhy)
{
    Problem p;
    p.file = file;
    YAML::Node y;
    try
    {
        y = YAML::LoadFile(file);
    }
    catch (const YAML::BadFile &)
    {
        throw InputError(file + ": cannot open the problem file");
    }
    catch (const YAML::Exception &e)
    {
        throw InputError(file + ": not valid YAML (" + std::string(e.what()) + ")");
    }
    if (!y.IsMap()) bad(p, "expected a mapping with map, queries and planners");
    try
    {
        p.name = y["name"] ? y["name"].as<std::string>() : fs::path(file).stem().string();
        if (!y["map"]) bad(p, "no 'map' (a map file, or 'embedded' for the generated campus)");
        p.map = y["map"].as<std::string>();
        const std::string tag = "${shared}";
        bool shared = false;
        if (auto pos = p.map.find(tag); pos != std::string::npos)
        {
            // --shared is relative to the working directory, not to the problem file
            p.map.replace(pos, tag.size(), fs::absolute(sharedDir).lexically_normal().string());
            shared = true;
        }
        if (p.map != "embedded")
        {
            if (fs::path(p.map).is_relative()) p.map = (fs::path(file).parent_path() / p.map).string();
            if (!fs::exists(p.map))
            {
                if (shared)
                {
                    skip = true;
                    skipWhy = p.map + " not found (the shared data folder is " + sharedDir + ")";
                    return p;
                }
                bad(p, "map file " + p.map + " does not exist");
            }
        }
        if (y["vehicle"]) p.vehicle = y["vehicle"].as<std::string>();
        if (y["objective"]) p.objective = y["objective"].as<std::string>();
        if (y["delta"]) p.delta = y["delta"].as<double>();
        if (y["unknown_free"]) p.unknownFree = y["unknown_free"].as<bool>();
        if (y["resample"]) p.resample = y["resample"].as<double>();
        if (y["time_limit"]) p.timeLimit = y["time_limit"].as<double>();
        if (y["memory_limit_mb"]) p.memoryMb = y["memory_limit_mb"].as<double>();
        if (y["runs"]) p.runs = y["runs"].as<unsigned>();
        if (!y["queries"] || !y["queries"].IsSequence() || y["queries"].size() == 0)
            bad(p, "'queries' must be a non-empty list of {start | start_cell, goal | goal_cell}");
        for (const auto &q : y["queries"]) p.queries.push_back(q);
        if (!y["planners"] || !y["planners"].IsSequence() || y["planners"].size() == 0)
            bad(p, "'planners' must be a non-empty list of {name, label?, params?}");
        std::set<std::string> labels;
        for (const auto &n : y["planners"])
        {
            PlannerSpec s;
            if (n.IsScalar())
                s.name = n.as<std::string>();
            else
            {
                if (!n["name"]) bad(p, "a planner entry has no 'name'");
                s.name = n["name"].as<std::string>();
                if (n["params"])
                    for (const auto &kv : n["params"]) s.params.push_back({kv.first.as<std::string>(), kv.second.as<std::string>()});
                if (n["label"]) s.label = n["label"].as<std::string>();
            }
            if (s.label.empty()) s.label = s.name;
            if (!labels.insert(s.label).second) bad(p, "two planners are labelled '" + s.label + "': give one a 'label'");
            p.planners.push_back(s);
        }
    }
    catch (const YAML::Exception &e)
    {
        bad(p, std::string("bad value (") + e.what() + ")");
    }
    if (!(p.timeLimit > 0) || !std::isfinite(p.timeLimit) || p.timeLimit > 86400) bad(p, "time_limit must be in (0, 86400] s");
    if (p.runs == 0 || p.runs > 100000) bad(p, "runs must be in 1..100000");
    if (!(p.memoryMb > 0)) bad(p, "memory_limit_mb must be positive");
    if (p.resample < 0 || !std::isfinite(p.resample) || (p.resample > 0 && p.resample < 1e-3))
        bad(p, "resample must be a cell size in metres (>= 0.001)");
    return p;
}

Pose2 readPose(const Problem &p, const YAML::Node &q, const std::string &key, const OccupancyGrid &g, bool &hasYaw,
               std::size_t index)
{
    const std::string where = "query " + std::to_string(index + 1) + ": ";
    const bool world = bool(q[key]), cell = bool(q[key + "_cell"]);
    if (world == cell) bad(p, where + "give exactly one of " + key + ": [x, y(, yaw_deg)] and " + key + "_cell: [col, row(, deg)]");
    const YAML::Node v = world ? q[key] : q[key + "_cell"];
    if (!v.IsSequence() || v.size() < 2 || v.size() > 3) bad(p, where + key + " must be a list of 2 or 3 numbers");
    double a, b, yaw = 0;
    try
    {
        a = v[0].as<double>();
        b = v[1].as<double>();
        if (v.size() == 3) yaw = v[2].as<double>() * M_PI / 180.0;
    }
    catch (const YAML::Exception &)
    {
        bad(p, where + key + " must hold numbers");
    }
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(yaw)) bad(p, where + key + " must be finite");
    hasYaw = v.size() == 3;
    if (cell)
    {
        if (a != std::floor(a) || b != std::floor(b) || !g.inBounds(int(a), int(b)))
            bad(p, where + key + "_cell [" + std::to_string(a) + ", " + std::to_string(b) + "] is not a cell of the " +
                       std::to_string(g.width()) + " x " + std::to_string(g.height()) + " map");
        return {g.cellCenterX(int(a)), g.cellCenterY(int(b)), GridSE2StateSpace::wrapYaw(yaw)};
    }
    return {a, b, GridSE2StateSpace::wrapYaw(yaw)};
}

bool parseShard(const std::string &s, unsigned &k, unsigned &n)
{
    k = 1;
    n = 1;
    if (s.empty()) return true;
    const auto slash = s.find('/');
    if (slash == std::string::npos) return false;
    try
    {
        std::size_t u1 = 0, u2 = 0;
        k = unsigned(std::stoul(s.substr(0, slash), &u1));
        n = unsigned(std::stoul(s.substr(slash + 1), &u2));
        if (u1 != slash || u2 != s.size() - slash - 1) return false;
    }
    catch (const std::exception &)
    {
        return false;
    }
    return n >= 1 && k >= 1 && k <= n;
}
}  // namespace

int runBench(const BenchOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    unsigned shardK, shardN;
    if (!parseShard(o.shard, shardK, shardN)) throw InputError("--shard must be K/N with 1 <= K <= N, got '" + o.shard + "'");
    bool skip = false;
    std::string skipWhy;
    Problem p = readProblem(o.problem, o.sharedDir, skip, skipWhy);
    if (skip)
    {
        std::fprintf(stderr, "[bench] %s: skipped: %s\n", o.problem.c_str(), skipWhy.c_str());
        return 0;
    }
    if (o.timeLimit > 0) p.timeLimit = o.timeLimit;
    if (o.runs > 0) p.runs = o.runs;
    const std::string script = o.reportScript.empty() ? defaultReportScript() : o.reportScript;
    if (!o.noDatabase && shardN == 1 && !fs::is_regular_file(script))  // fail before the runs, not after
        throw InputError("report script '" + script +
                         "' not found (give one with --report-script, or write only the logs with --no-database)");
    std::error_code ec;
    fs::create_directories(o.outDir, ec);
    if (ec) throw InputError("cannot create output folder '" + o.outDir + "': " + ec.message());

    std::fprintf(stderr, "[bench] %s: loading %s\n", p.name.c_str(), p.map.c_str());
    auto grid = std::make_shared<OccupancyGrid>(p.map == "embedded" ? generateCampus() : loadMap(p.map));
    if (p.resample > 0) *grid = grid->resampled(p.resample);
    grid->setUnknownIsFree(p.unknownFree);
    VehicleParams vehicle;
    try
    {
        const fs::path vf = fs::path(p.file).parent_path() / p.vehicle;
        vehicle = VehicleParams::fromNameOrFile(fs::exists(vf) && p.vehicle.find('.') != std::string::npos ? vf.string() : p.vehicle);
    }
    catch (const std::invalid_argument &e)
    {
        bad(p, e.what());
    }
    // every planner name must be known before anything runs
    for (const PlannerSpec &s : p.planners)
    {
        const auto known = plannerNames();
        const std::string base = s.name.size() > 7 && s.name.substr(s.name.size() - 7) == "+smooth" ? s.name.substr(0, s.name.size() - 7) : s.name;
        if (std::find(known.begin(), known.end(), base) == known.end())
            bad(p, "unknown planner '" + s.name + "'");
    }
    std::fprintf(stderr, "[bench] %s: distance field and footprint checker for %d x %d cells...\n", p.name.c_str(),
                 grid->width(), grid->height());
    GridSetup setup = makeGridSetup(grid, vehicle);
    try
    {
        setup.ss->setOptimizationObjective(makeObjective(p.objective, setup.ss->getSpaceInformation(), *setup.checker, p.delta));
    }
    catch (const std::invalid_argument &e)
    {
        bad(p, e.what());
    }

    // units of work: (query, planner); shard K of N takes every N-th
    std::vector<std::vector<std::size_t>> mine(p.queries.size());
    std::size_t unit = 0, total = 0;
    for (std::size_t q = 0; q < p.queries.size(); ++q)
        for (std::size_t k = 0; k < p.planners.size(); ++k, ++unit)
            if (unit % shardN == shardK - 1)
            {
                mine[q].push_back(k);
                ++total;
            }
    const std::string tag = shardN > 1 ? "-shard" + std::to_string(shardK) + "of" + std::to_string(shardN) : "";
    nlohmann::json pathsJson = nlohmann::json::object();
    const fs::path pathsFile = fs::path(o.outDir) / (p.name + tag + "-paths.json");
    std::vector<std::string> logs;
    const auto t0 = std::chrono::steady_clock::now();
    std::size_t unitsStarted = 0;
    for (std::size_t qi = 0; qi < p.queries.size(); ++qi)
    {
        if (mine[qi].empty()) continue;
        bool startYaw = false, goalYaw = false;
        const Pose2 start = readPose(p, p.queries[qi], "start", *grid, startYaw, qi);
        const Pose2 goal = readPose(p, p.queries[qi], "goal", *grid, goalYaw, qi);
        const std::string q = "query " + std::to_string(qi + 1);
        if (!setup.checker->isValid(start)) bad(p, q + ": the start is off the map or in collision for " + vehicle.name);
        if (!setup.checker->isValid(goal)) bad(p, q + ": the goal is off the map or in collision for " + vehicle.name);
        setup.ss->clear();
        setup.setStartAndGoal(start, goal);
        const std::string expName = p.name + "-q" + std::to_string(qi + 1);
        ompl::tools::Benchmark b(*setup.ss, expName);
        b.addExperimentParameter("query", "INTEGER", std::to_string(qi + 1));
        b.addExperimentParameter("start_x", "REAL", std::to_string(start.x));
        b.addExperimentParameter("start_y", "REAL", std::to_string(start.y));
        b.addExperimentParameter("goal_x", "REAL", std::to_string(goal.x));
        b.addExperimentParameter("goal_y", "REAL", std::to_string(goal.y));
        for (std::size_t k : mine[qi])
        {
            const PlannerSpec spec = p.planners[k];
            b.addPlannerAllocator([spec, startYaw, &p](const ompl::base::SpaceInformationPtr &si) {
                ompl::base::PlannerPtr pl = makePlanner(si, spec.name);
                if (!startYaw) freeStartHeading(*pl);
                for (const auto &kv : spec.params)
                {
                    bool ok = false;
                    try
                    {
                        ok = pl->params().hasParam(kv.first) && pl->params().setParam(kv.first, kv.second);
                    }
                    catch (const std::exception &e)
                    {
                        bad(p, "planner " + spec.label + ": parameter " + kv.first + "=" + kv.second + ": " + e.what());
                    }
                    if (!ok) bad(p, "planner " + spec.label + ": parameter " + kv.first + "=" + kv.second + " not accepted");
                }
                pl->setName(spec.label);
                return pl;
            });
        }
        std::map<std::string, unsigned> runOf;
        b.setPreRunEvent([&](const ompl::base::PlannerPtr &pl) {
            const unsigned r = ++runOf[pl->getName()];
            if (r == 1) ++unitsStarted;
            const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::fprintf(stderr, "[bench] %s %s (%zu/%zu): %-22s run %u/%u  (elapsed %.0f s)\n", p.name.c_str(), q.c_str(),
                         unitsStarted, total, pl->getName().c_str(), r, p.runs, el);
        });
        b.setPostRunEvent([&](const ompl::base::PlannerPtr &pl, ompl::tools::Benchmark::RunProperties &run) {
            const auto &pdef = setup.ss->getProblemDefinition();
            if (!pdef->hasSolution()) return;
            auto *path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
            std::vector<Pose2> poses;
            for (const auto *s : path->getStates()) poses.push_back(toPose(s));
            const PathMetrics m = computePathMetrics(poses, setup.checker.get());
            run["path length REAL"] = std::to_string(m.length);  // OMPL's solution length adds yaw distance
            run["turns INTEGER"] = std::to_string(m.turns);
            run["max turn deg REAL"] = std::to_string(m.maxTurnDeg);
            run["max curvature REAL"] = std::to_string(std::isfinite(m.maxCurvature) ? m.maxCurvature : 1e9);
            run["min clearance REAL"] = std::to_string(m.minClearance);
            run["path distance REAL"] = std::to_string(m.minPathDistance);
            run["driving time REAL"] = std::to_string(drivingTime(poses, vehicle));
            // the path driven by paper C's potential-field follower in the kinematic simulation
            FollowerParams fp;
            fp.recordTrajectory = false;
            const DriveResult dr = drivePath(poses, *setup.checker, Scenario(), fp);
            run["sim reached BOOLEAN"] = dr.outcome == DriveResult::Outcome::Reached ? "1" : "0";
            if (dr.outcome == DriveResult::Outcome::Reached) run["sim driving time REAL"] = std::to_string(dr.drivingTime);
            if (auto *gp = dynamic_cast<GridPlanner *>(pl.get())) run["expanded nodes INTEGER"] = std::to_string(gp->expandedNodes());
            const std::string key = expName + "|" + pl->getName();
            if (!pathsJson.contains(key) && !pdef->hasApproximateSolution())
            {
                nlohmann::json pts = nlohmann::json::array();
                for (const Pose2 &pp : poses) pts.push_back({pp.x, pp.y});
                pathsJson[key] = pts;
            }
        });
        ompl::tools::Benchmark::Request req(p.timeLimit, p.memoryMb, p.runs, 0.5, false, false, /*simplify=*/false);
        b.benchmark(req);
        const std::string log = (fs::path(o.outDir) / (expName + tag + ".log")).string();
        if (!b.saveResultsToFile(log.c_str())) throw std::runtime_error("cannot write " + log);
        logs.push_back(log);
        // a picture of the query's surroundings for the report
        WorldBox box;
        box.add(start.x, start.y);
        box.add(goal.x, goal.y);
        for (auto it = pathsJson.begin(); it != pathsJson.end(); ++it)
            if (it.key().rfind(expName + "|", 0) == 0)
                for (const auto &pt : *it) box.add(pt[0].get<double>(), pt[1].get<double>());
        const OccupancyGrid crop = cropAround(*grid, box, 15.0);
        MapCanvas canvas(crop, 1200);
        const std::string png = expName + tag + "-map.png";
        canvas.save((fs::path(o.outDir) / png).string());
        pathsJson["_maps"][expName] = {{"image", png},
                                       {"extent", {crop.originX(), crop.originX() + crop.sizeX(), crop.originY(),
                                                   crop.originY() + crop.sizeY()}},
                                       {"start", {start.x, start.y}},
                                       {"goal", {goal.x, goal.y}}};
    }
    std::ofstream(pathsFile) << pathsJson.dump() << "\n";
    const double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "[bench] %s: %zu logs written in %.0f s\n", p.name.c_str(), logs.size(), el);
    if (o.noDatabase || shardN > 1)
    {
        if (shardN > 1)
            std::fprintf(stderr, "[bench] shard %u/%u done; merge the shards' .log files with ompl_benchmark_statistics "
                                 "(see docs/benchmark.md)\n", shardK, shardN);
        return 0;
    }
    // database and report
    const fs::path db = fs::path(o.outDir) / (p.name + ".db");
    fs::remove(db, ec);
    std::string cmd = "ompl_benchmark_statistics -d '" + db.string() + "'";
    for (const auto &l : logs) cmd += " '" + l + "'";
    cmd += " > '" + (fs::path(o.outDir) / "ompl_benchmark_statistics.out").string() + "' 2>&1";
    std::fprintf(stderr, "[bench] %s: building %s with ompl_benchmark_statistics\n", p.name.c_str(), db.string().c_str());
    if (std::system(cmd.c_str()) != 0)
        throw std::runtime_error("ompl_benchmark_statistics failed (is Debian's ompl-demos installed? see " +
                                 (fs::path(o.outDir) / "ompl_benchmark_statistics.out").string() + ")");
    cmd = "/usr/bin/python3 '" + script + "' --db '" + db.string() + "' --paths '" + pathsFile.string() + "' --out '" +
          o.outDir + "' --title '" + p.name + "'";
    std::fprintf(stderr, "[bench] %s: report and plots\n", p.name.c_str());
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("the report script failed: " + cmd);
    std::fprintf(stderr, "[bench] %s: done: %s/report.md\n", p.name.c_str(), o.outDir.c_str());
    return 0;
}

std::string defaultReportScript()
{
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
    {
        const fs::path installed = (exe.parent_path() / GRIDCAR_INSTALLED_REPORT_SCRIPT).lexically_normal();
        if (fs::is_regular_file(installed, ec)) return installed.string();
    }
    return GRIDCAR_REPORT_SCRIPT;
}

}  // namespace gridcar::cli
