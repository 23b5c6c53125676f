// gridcar bench PROBLEM.yaml: ompl::tools::Benchmark of our planners against OMPL's on one
// problem file, then the SQLite database (ompl_benchmark_statistics) and the report.
#include "gridcar/bench/Bench.h"

#include "gridcar/bench/ParamsFile.h"
#include "ArenaBenchmark.h"
#include "gridcar/bench/Problem.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/objectives/Objectives.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/render/Render.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/geometric/PathGeometric.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#ifndef GRIDCAR_REPORT_SCRIPT
#define GRIDCAR_REPORT_SCRIPT "scripts/bench_report.py"
#endif
#ifndef GRIDCAR_INSTALLED_REPORT_SCRIPT
#define GRIDCAR_INSTALLED_REPORT_SCRIPT "../share/gridcar/bench_report.py"  // relative to the executable
#endif

namespace gridcar::bench
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// The map, vehicle, setup and objective of a problem, checked before anything runs.
struct BenchWorld
{
    std::shared_ptr<OccupancyGrid> grid;
    VehicleParams vehicle;
    GridSetup setup;
};

BenchWorld loadWorld(const Problem &p)
{
    BenchWorld w;
    std::fprintf(stderr, "[bench] %s: loading %s\n", p.name.c_str(), p.map.c_str());
    w.grid = std::make_shared<OccupancyGrid>(p.map == "embedded" ? generateCampus() : loadMap(p.map));
    if (p.resample > 0) *w.grid = w.grid->resampled(p.resample);
    w.grid->setUnknownIsFree(p.unknownFree);
    try
    {
        const fs::path vf = fs::path(p.file).parent_path() / p.vehicle;
        std::error_code ec;
        w.vehicle = VehicleParams::fromNameOrFile(fs::exists(vf, ec) && p.vehicle.find('.') != std::string::npos ? vf.string() : p.vehicle);
    }
    catch (const std::invalid_argument &e)
    {
        bad(p, e.what());
    }
    // every planner name must be known before anything runs
    for (const PlannerSpec &s : p.planners)
        if (!isPlannerName(s.name))
        {
            const std::string guess = suggestPlanner(s.name);
            bad(p, "unknown planner '" + s.name + "'" + (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
        }
    std::fprintf(stderr, "[bench] %s: distance field and footprint checker for %d x %d cells...\n", p.name.c_str(),
                 w.grid->width(), w.grid->height());
    SetupOptions so;
    so.space = p.space;
    try
    {
        w.setup = makeGridSetup(w.grid, w.vehicle, so);
    }
    catch (const std::invalid_argument &e)
    {
        bad(p, e.what());
    }
    try
    {
        w.setup.ss->setOptimizationObjective(
            makeObjective(p.objective, w.setup.ss->getSpaceInformation(), *w.setup.checker, p.delta));
    }
    catch (const std::invalid_argument &e)
    {
        bad(p, e.what());
    }
    return w;
}

/// Path measures, driving time and the simulated drive of a run's solution, as Benchmark run
/// properties.
void addRunProperties(const BenchWorld &w, const ompl::base::Planner &planner, const std::vector<Pose2> &poses,
                      ompl::tools::Benchmark::RunProperties &run)
{
    const bool rev = w.setup.reversing();
    const PathMetrics m = computePathMetrics(poses, w.setup.checker.get(), TurnParams(), rev);
    run["path length REAL"] = std::to_string(m.length);  // OMPL's solution length adds yaw distance
    run["turns INTEGER"] = std::to_string(m.turns);
    run["max turn deg REAL"] = std::to_string(m.maxTurnDeg);
    run["max curvature REAL"] = std::to_string(std::isfinite(m.maxCurvature) ? m.maxCurvature : 1e9);
    run["min clearance REAL"] = std::to_string(m.minClearance);
    run["path distance REAL"] = std::to_string(m.minPathDistance);
    run["cusps INTEGER"] = std::to_string(m.cusps);
    DrivingTimeParams tp;
    tp.reversing = rev;  // a stop at each cusp
    run["driving time REAL"] = std::to_string(drivingTime(poses, w.vehicle, tp));
    DrivabilityOptions dopt;
    dopt.reversing = rev;
    run["drivable BOOLEAN"] = checkDrivable(poses, *w.setup.checker, dopt).drivable ? "1" : "0";
    // the path driven by paper C's potential-field follower in the kinematic simulation
    FollowerParams fp;
    fp.recordTrajectory = false;
    const DriveResult dr = drivePath(poses, *w.setup.checker, Scenario(), fp);
    run["sim reached BOOLEAN"] = dr.outcome == DriveResult::Outcome::Reached ? "1" : "0";
    if (dr.outcome == DriveResult::Outcome::Reached) run["sim driving time REAL"] = std::to_string(dr.drivingTime);
    if (const auto expanded = reportOf(planner).expanded) run["expanded nodes INTEGER"] = std::to_string(*expanded);
}

/// A picture of a query's surroundings for the report; its entry in the paths file.
void drawQuery(const BenchWorld &w, const std::string &outDir, const std::string &expName, const std::string &tag,
               const Pose2 &start, const Pose2 &goal, nlohmann::json &pathsJson)
{
    WorldBox box;
    box.add(start.x, start.y);
    box.add(goal.x, goal.y);
    for (auto it = pathsJson.begin(); it != pathsJson.end(); ++it)
        if (it.key().rfind(expName + "|", 0) == 0)
            for (const auto &pt : *it) box.add(pt[0].get<double>(), pt[1].get<double>());
    const OccupancyGrid crop = cropAround(*w.grid, box, 15.0);
    MapCanvas canvas(crop, 1200);
    const std::string png = expName + tag + "-map.png";
    canvas.save((fs::path(outDir) / png).string());
    pathsJson["_maps"][expName] = {{"image", png},
                                   {"extent", {crop.originX(), crop.originX() + crop.sizeX(), crop.originY(),
                                               crop.originY() + crop.sizeY()}},
                                   {"start", {start.x, start.y}},
                                   {"goal", {goal.x, goal.y}}};
}

/// The state of a benchmark run over several queries: what this shard runs, the progress
/// counters, the solution paths for the plots and the logs written.
struct BenchRun
{
    BenchRun(const Problem &problem, BenchWorld &world, const BenchOptions &options, std::string shardTag)
      : p(problem), w(world), o(options), tag(std::move(shardTag))
    {
    }
    const Problem &p;
    BenchWorld &w;
    const BenchOptions &o;
    std::string tag;  ///< "-shardKofN" or empty
    std::vector<std::vector<std::size_t>> mine;  ///< per query: the planners this shard runs
    std::size_t total{0}, unitsStarted{0};
    Clock::time_point t0{Clock::now()};
    nlohmann::json pathsJson = nlohmann::json::object();
    std::vector<std::string> logs;
};

/// Benchmarks query @p qi with this shard's planners and writes its .log and picture.
void benchmarkQuery(BenchRun &run, std::size_t qi, double timeLimit, const std::string &limitTag)
{
    const Problem &p = run.p;
    GridSetup &setup = run.w.setup;
    bool startYaw = false, goalYaw = false;
    Pose2 start = readPose(p, p.queries[qi], "start", *run.w.grid, startYaw, qi);
    Pose2 goal = readPose(p, p.queries[qi], "goal", *run.w.grid, goalYaw, qi);
    char limitText[48] = "";
    if (!limitTag.empty()) std::snprintf(limitText, sizeof limitText, " at %g s", timeLimit);
    const std::string q = "query " + std::to_string(qi + 1) + limitText;
    // without a yaw the heading is free: the pose gets the first yaw at which the vehicle fits
    // (OMPL's planners start there; ours choose their own)
    if (!startYaw) setup.checker->fitsAtSomeHeading(start.x, start.y, 72, &start.yaw);
    if (!goalYaw) setup.checker->fitsAtSomeHeading(goal.x, goal.y, 72, &goal.yaw);
    if (!setup.checker->isValid(start)) bad(p, q + ": the start is off the map or in collision for " + run.w.vehicle.name);
    if (!setup.checker->isValid(goal)) bad(p, q + ": the goal is off the map or in collision for " + run.w.vehicle.name);
    setup.ss->clear();
    setup.setStartAndGoal(start, goal, /*freeGoalHeading=*/!goalYaw);
    // one experiment per query: its runs at several time limits share the name and differ in the
    // time_limit parameter, which Planner Arena groups by
    const std::string expName = p.name + "-q" + std::to_string(qi + 1);
    ArenaBenchmark b(*setup.ss, expName);
    b.addExperimentParameter("query", "INTEGER", std::to_string(qi + 1));
    b.addExperimentParameter("start_x", "REAL", std::to_string(start.x));
    b.addExperimentParameter("start_y", "REAL", std::to_string(start.y));
    b.addExperimentParameter("goal_x", "REAL", std::to_string(goal.x));
    b.addExperimentParameter("goal_y", "REAL", std::to_string(goal.y));
    b.addExperimentParameter("space", "VARCHAR(16)", spaceKindName(p.space));
    b.addExperimentParameter("time_limit", "REAL", std::to_string(timeLimit));
    for (std::size_t k : run.mine[qi])
    {
        const PlannerSpec spec = p.planners[k];
        b.addPlannerAllocator([spec, startYaw, &p](const ompl::base::SpaceInformationPtr &si) {
            ompl::base::PlannerPtr pl;
            try
            {
                pl = configurePlanner(si, {spec.name, spec.params, !startYaw, false});
            }
            catch (const InputError &e)
            {
                bad(p, "planner " + spec.label + ": " + e.what());
            }
            pl->setName(spec.label);
            return pl;
        });
    }
    std::map<std::string, unsigned> runOf;  // runs per planner of this experiment
    Clock::time_point solveStart;
    double firstSolution = -1;  // s after the run's start; -1: not reported by the planner
    b.setPreRunEvent([&](const ompl::base::PlannerPtr &pl) {
        solveStart = Clock::now();
        firstSolution = -1;
        // anytime planners (RRT*, BIT*) report each better path: the first is the time to first solution
        setup.ss->getProblemDefinition()->setIntermediateSolutionCallback(
            [&](const ompl::base::Planner *, const std::vector<const ompl::base::State *> &, const ompl::base::Cost &) {
                if (firstSolution < 0) firstSolution = std::chrono::duration<double>(Clock::now() - solveStart).count();
            });
        const unsigned r = ++runOf[pl->getName()];
        if (r == 1) ++run.unitsStarted;
        const double el = std::chrono::duration<double>(Clock::now() - run.t0).count();
        std::fprintf(stderr, "[bench] %s %s (%zu/%zu): %-22s run %u/%u  (elapsed %.0f s)\n", p.name.c_str(), q.c_str(),
                     run.unitsStarted, run.total, pl->getName().c_str(), r, p.runs, el);
    });
    b.setPostRunEvent([&](const ompl::base::PlannerPtr &pl, ompl::tools::Benchmark::RunProperties &props) {
        const auto &pdef = setup.ss->getProblemDefinition();
        // path attributes only for an exact solution: an approximate one keeps OMPL's time and
        // status, and is not plotted beside real solutions
        if (!pdef->hasExactSolution()) return;
        const double total = std::chrono::duration<double>(Clock::now() - solveStart).count();
        const std::vector<Pose2> poses = solutionPoses(setup, *pl);
        addRunProperties(run.w, *pl, poses, props);
        // planners that stop at their first solution (ours, RRTConnect, RRT) found it at the end
        // of the run; PRM-style planners report none before the time limit
        const bool anytime = pl->getSpecs().optimizingPaths;
        if (firstSolution >= 0 && firstSolution <= total)
            props["time to first solution REAL"] = std::to_string(firstSolution);
        else if (!anytime)  // OMPL's own solve time when it has recorded it already
            props["time to first solution REAL"] = props.count("time REAL") ? props["time REAL"] : std::to_string(total);
        const std::string key = expName + "|" + pl->getName();
        if (!run.pathsJson.contains(key))
        {
            nlohmann::json pts = nlohmann::json::array();
            for (const Pose2 &pp : poses) pts.push_back({pp.x, pp.y, pp.yaw});
            run.pathsJson[key] = pts;
        }
    });
    ompl::tools::Benchmark::Request req(timeLimit, p.memoryMb, p.runs, 0.5, false, false, /*simplify=*/false);
    b.benchmark(req);
    b.tidy(*setup.ss);
    const std::string log = (fs::path(run.o.outDir) / (expName + limitTag + run.tag + ".log")).string();
    b.save(log);
    run.logs.push_back(log);
    if (!run.pathsJson["_maps"].contains(expName))
        drawQuery(run.w, run.o.outDir, expName, run.tag, start, goal, run.pathsJson);
}

/// @p text as one single-quoted shell word (a ' inside becomes '\'').
std::string shellQuoted(const std::string &text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// The SQLite database of the logs (ompl_benchmark_statistics), then report.md and the plots.
void writeReport(const Problem &p, const BenchOptions &o, const std::vector<std::string> &logs, const fs::path &pathsFile,
                 const std::string &script)
{
    std::error_code ec;
    const fs::path db = fs::path(o.outDir) / (p.name + ".db");
    fs::remove(db, ec);
    const auto q = [](const std::string &t) { return shellQuoted(t); };
    std::string cmd = "ompl_benchmark_statistics -d " + q(db.string());
    for (const auto &l : logs) cmd += " " + q(l);
    cmd += " > " + q((fs::path(o.outDir) / "ompl_benchmark_statistics.out").string()) + " 2>&1";
    std::fprintf(stderr, "[bench] %s: building %s with ompl_benchmark_statistics\n", p.name.c_str(), db.string().c_str());
    if (std::system(cmd.c_str()) != 0)
        throw std::runtime_error("ompl_benchmark_statistics failed (is Debian's ompl-demos installed? see " +
                                 (fs::path(o.outDir) / "ompl_benchmark_statistics.out").string() + ")");
    cmd = "/usr/bin/python3 " + q(script) + " --db " + q(db.string()) + " --paths " + q(pathsFile.string()) + " --out " +
          q(o.outDir) + " --title " + q(p.name) + (o.reportNote.empty() ? "" : " --note " + q(o.reportNote));
    std::fprintf(stderr, "[bench] %s: report and plots\n", p.name.c_str());
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("the report script failed: " + cmd);
    std::fprintf(stderr, "[bench] %s: done: %s/report.md\n", p.name.c_str(), o.outDir.c_str());
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
    if (!o.paramsFile.empty()) applyParamsFile(p, readParamsFile(o.paramsFile));
    if (o.timeLimit > 0)
    {
        p.timeLimit = o.timeLimit;
        p.timeLimits.clear();  // --time-limit replaces the problem's list too
    }
    if (o.runs > 0) p.runs = o.runs;
    const std::string script = o.reportScript.empty() ? defaultReportScript() : o.reportScript;
    if (!o.noDatabase && shardN == 1 && !fs::is_regular_file(script))  // fail before the runs, not after
        throw InputError("report script '" + script +
                         "' not found (give one with --report-script, or write only the logs with --no-database)");
    std::error_code ec;
    fs::create_directories(o.outDir, ec);
    if (ec) throw InputError("cannot create output folder '" + o.outDir + "': " + ec.message());
    BenchWorld world = loadWorld(p);

    // units of work: (query, planner); shard K of N takes every N-th
    BenchRun run(p, world, o, shardN > 1 ? "-shard" + std::to_string(shardK) + "of" + std::to_string(shardN) : "");
    run.mine.resize(p.queries.size());
    std::size_t unit = 0;
    for (std::size_t q = 0; q < p.queries.size(); ++q)
        for (std::size_t k = 0; k < p.planners.size(); ++k, ++unit)
            if (unit % shardN == shardK - 1)
            {
                run.mine[q].push_back(k);
                ++run.total;
            }
    const std::vector<double> limits = p.timeLimits.empty() ? std::vector<double>{p.timeLimit} : p.timeLimits;
    run.total *= limits.size();
    for (std::size_t qi = 0; qi < p.queries.size(); ++qi)
        if (!run.mine[qi].empty())
            for (double limit : limits)
            {
                char tag[32] = "";
                if (p.timeLimits.size() > 0) std::snprintf(tag, sizeof tag, "-t%gs", limit);
                benchmarkQuery(run, qi, limit, tag);
            }
    const VehicleParams &v = world.vehicle;
    if (!v.isPoint())
        run.pathsJson["_vehicle"] = {
            {"length", v.length}, {"width", v.width}, {"rear_overhang", v.rearOverhang}, {"footprint", v.footprint}};
    const fs::path pathsFile = fs::path(o.outDir) / (p.name + run.tag + "-paths.json");
    std::ofstream(pathsFile) << run.pathsJson.dump() << "\n";
    const double el = std::chrono::duration<double>(Clock::now() - run.t0).count();
    std::fprintf(stderr, "[bench] %s: %zu logs written in %.0f s\n", p.name.c_str(), run.logs.size(), el);
    if (shardN > 1)
        std::fprintf(stderr, "[bench] shard %u/%u done; merge the shards' .log files with ompl_benchmark_statistics "
                             "(see docs/benchmark.md)\n", shardK, shardN);
    if (o.noDatabase || shardN > 1) return 0;
    writeReport(p, o, run.logs, pathsFile, script);
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

}  // namespace gridcar::bench
