// gridcar paper-c: paper C's driving-time comparison (plain A* against corner-weighted A*,
// driven in the simulation; with --corner-mode drivable also the driving-time planner) and a
// corner-weight sweep.
#include "gridcar/bench/PaperC.h"

#include "gridcar/bench/Format.h"
#include "gridcar/core/Errors.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace gridcar::bench
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const char *kVehicles[] = {"paper-c-robot", "paper-c-car"};

struct MapCase
{
    std::string key;
    std::shared_ptr<const OccupancyGrid> grid;
};

/// One planner configuration of the comparison.
struct Config
{
    std::string label, planner;
    PlannerParams params;
};

/// The configurations; corner A* in @p cornerMode (`paper`: paper C's 8-connected grid;
/// `drivable`: the car lattice, and then also paper C's future work beside them, the
/// driving-time planner: corner-astar `cost=time`).
std::vector<Config> configs(const std::string &cornerMode)
{
    std::vector<Config> c = {{"A* Euclidean", "astar-euclidean", {}},
                             {"corner A* (paper weights)", "corner-astar", {{"mode", cornerMode}, {"weights", "paper"}}},
                             {"corner A* (physics weights)", "corner-astar", {{"mode", cornerMode}, {"weights", "physics"}}}};
    if (cornerMode == "drivable") c.push_back({"driving-time planner (cost=time)", "corner-astar", {{"mode", "drivable"}, {"cost", "time"}}});
    return c;
}

/// How one configuration did on one pair.
struct Drive
{
    double length{NAN}, turns{NAN}, profileTime{NAN}, simTime{NAN};
    std::string outcome;
};

struct PairResult
{
    std::string map, vehicle;
    int pair{0};
    double straight{0.0};  ///< m between start and goal
    std::vector<Drive> drives;  ///< per configuration
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
            double yaw;
            if (!s.checker->fitsAtSomeHeading(g.cellCenterX(c), g.cellCenterY(r), 8, &yaw)) continue;
            p = {g.cellCenterX(c), g.cellCenterY(r), yaw};
            return true;
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

/// Plans with @p planner and @p params and drives the path (no moving obstacles).
Drive planAndDrive(GridSetup &setup, const std::string &planner, const PlannerParams &params, const Pose2 &start,
                   const Pose2 &goal, double timeLimit)
{
    Drive d;
    const auto pl = configurePlanner(setup.ss->getSpaceInformation(), {planner, params, true, false});
    const QueryResult q = runQuery(setup, pl, start, goal, timeLimit);
    if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        d.outcome = "no plan (" + q.status.asString() + ")";
        return d;
    }
    FollowerParams fp;
    fp.recordTrajectory = false;
    const DriveResult r = drivePath(q.path, *setup.checker, Scenario(), fp);
    d.length = q.metrics.length;
    d.turns = q.metrics.turns;
    d.profileTime = drivingTime(q.path, setup.checker->vehicle());
    d.simTime = r.outcome == DriveResult::Outcome::Reached ? r.drivingTime : NAN;
    d.outcome = DriveResult::outcomeName(r.outcome);
    return d;
}

/// Every configuration on every pair of one map and vehicle.
void runPairs(const PaperCOptions &o, const MapCase &mc, const std::string &vname, std::vector<PairResult> &all,
              nlohmann::json &js, Clock::time_point t0)
{
    std::fprintf(stderr, "[paper-c] %s with %s: distance field, footprint checker, %d pairs\n", mc.key.c_str(),
                 vname.c_str(), o.pairs);
    GridSetup setup = makeGridSetup(mc.grid, VehicleParams::preset(vname));
    const auto pairs = randomPairs(setup, o.pairs, o.seed);
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        PairResult pr{mc.key, vname, int(k + 1),
                      std::hypot(pairs[k].first.x - pairs[k].second.x, pairs[k].first.y - pairs[k].second.y), {}};
        nlohmann::json jp = {{"map", pr.map}, {"vehicle", pr.vehicle}, {"pair", pr.pair}, {"straight", pr.straight},
                             {"start", {pairs[k].first.x, pairs[k].first.y}}, {"goal", {pairs[k].second.x, pairs[k].second.y}}};
        for (const Config &c : configs(o.cornerMode))
        {
            const Drive d = planAndDrive(setup, c.planner, c.params, pairs[k].first, pairs[k].second, o.timeLimit);
            jp[c.label] = {{"length", d.length}, {"turns", d.turns}, {"profile_time", d.profileTime},
                           {"sim_time", d.simTime}, {"outcome", d.outcome}};
            pr.drives.push_back(d);
        }
        const double el = std::chrono::duration<double>(Clock::now() - t0).count();
        std::fprintf(stderr, "[paper-c] %s %s pair %zu/%zu: A* %.1f s, corner paper %.1f s, corner physics %.1f s%s "
                             "(simulated; elapsed %.0f s)\n",
                     mc.key.c_str(), vname.c_str(), k + 1, pairs.size(), pr.drives[0].simTime, pr.drives[1].simTime,
                     pr.drives[2].simTime,
                     pr.drives.size() > 3 ? (", driving-time planner " + fixed(pr.drives[3].simTime, 1) + " s").c_str() : "", el);
        js.push_back(jp);
        all.push_back(pr);
    }
}

double pct(double a, double b) { return 100.0 * (b - a) / a; }

/// The driving-time planner beside A* and corner A* (physics weights, the same dynamics): totals
/// over the pairs all three drove to the goal.
void writeTimedTable(std::ostringstream &md, const std::vector<MapCase> &maps, const std::vector<PairResult> &all)
{
    md << "\n### The driving-time planner (corner-astar cost=time) beside them\n\n"
          "| map | vehicle | pairs driven by A*, corner (physics) and it | A* total s | corner (physics) total s | "
          "driving-time planner total s | change against A* | against corner (physics) |\n|---|---|---|---|---|---|---|---|\n";
    for (const MapCase &mc : maps)
        for (const std::string vname : kVehicles)
        {
            double tot[3] = {0, 0, 0};
            int n = 0;
            for (const PairResult &pr : all)
            {
                if (pr.map != mc.key || pr.vehicle != vname || pr.drives.size() < 4) continue;
                const double t[3] = {pr.drives[0].simTime, pr.drives[2].simTime, pr.drives[3].simTime};
                if (std::isnan(t[0]) || std::isnan(t[1]) || std::isnan(t[2])) continue;
                ++n;
                for (int c = 0; c < 3; ++c) tot[c] += t[c];
            }
            md << "| " << mc.key << " | " << vname << " | " << n << " | " << fixed(tot[0], 1) << " | " << fixed(tot[1], 1) << " | "
               << fixed(tot[2], 1) << " | " << (n ? fixed(pct(tot[0], tot[2]), 1) + " %" : "-") << " | "
               << (n ? fixed(pct(tot[1], tot[2]), 1) + " %" : "-") << " |\n";
        }
}

/// The aggregate table (per map and vehicle) and the per-pair table.
void writeTables(std::ostringstream &md, const std::vector<MapCase> &maps, const std::vector<PairResult> &all)
{
    md << "| map | vehicle | pairs driven by all three | A* total s | corner (paper) total s | change | corner (physics) "
          "total s | change | per-pair change, paper weights: median (min .. max) | physics weights: median (min .. max) |\n"
          "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const MapCase &mc : maps)
        for (const std::string vname : kVehicles)
        {
            double tot[3] = {0, 0, 0};
            std::vector<double> ch1, ch2;
            int n = 0;
            for (const PairResult &pr : all)
            {
                if (pr.map != mc.key || pr.vehicle != vname) continue;
                if (std::isnan(pr.drives[0].simTime) || std::isnan(pr.drives[1].simTime) || std::isnan(pr.drives[2].simTime))
                    continue;
                ++n;
                for (int c = 0; c < 3; ++c) tot[c] += pr.drives[c].simTime;
                ch1.push_back(pct(pr.drives[0].simTime, pr.drives[1].simTime));
                ch2.push_back(pct(pr.drives[0].simTime, pr.drives[2].simTime));
            }
            md << "| " << mc.key << " | " << vname << " | " << n << " | " << fixed(tot[0], 1) << " | " << fixed(tot[1], 1) << " | "
               << (n ? fixed(pct(tot[0], tot[1]), 1) + " %" : "-") << " | " << fixed(tot[2], 1) << " | "
               << (n ? fixed(pct(tot[0], tot[2]), 1) + " %" : "-") << " | " << percentSummary(ch1) << " | "
               << percentSummary(ch2) << " |\n";
        }
    const bool timed = !all.empty() && all.front().drives.size() > 3;
    if (timed) writeTimedTable(md, maps, all);
    md << "\n### Per pair (simulated driving time s; length m; turns)\n\n"
          "| map | vehicle | pair | straight m | A* | corner (paper) | corner (physics) |"
       << (timed ? " driving-time planner |\n|---|---|---|---|---|---|---|---|\n" : "\n|---|---|---|---|---|---|---|\n");
    for (const PairResult &pr : all)
    {
        md << "| " << pr.map << " | " << pr.vehicle << " | " << pr.pair << " | " << fixed(pr.straight, 0);
        for (const Drive &d : pr.drives)
            md << " | " << (std::isnan(d.simTime) ? d.outcome : fixed(d.simTime, 1) + " s; " + fixed(d.length, 0) + " m; " +
                                                                  fixed(d.turns, 0));
        md << " |\n";
    }
}

/// Corner-weight sweep: the paper's weights scaled, robot on the campus, the first pairs.
nlohmann::json weightSweep(const PaperCOptions &o, const MapCase &campus, std::ostringstream &md)
{
    std::fprintf(stderr, "[paper-c] corner-weight sweep on the campus with paper-c-robot\n");
    GridSetup setup = makeGridSetup(campus.grid, VehicleParams::preset("paper-c-robot"));
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
        const PlannerParams weights = {{"mode", o.cornerMode},
                                       {"corner_weight_45", std::to_string(2.7 * f)},
                                       {"corner_weight_90", std::to_string(7.0 * f)},
                                       {"corner_weight_135", std::to_string(11.3 * f)}};
        for (std::size_t k = 0; k < pairs.size(); ++k)
        {
            const Drive d = planAndDrive(setup, f < 0 ? "astar-euclidean" : "corner-astar", f < 0 ? PlannerParams() : weights,
                                         pairs[k].first, pairs[k].second, o.timeLimit);
            if (std::isnan(d.simTime)) continue;
            if (f < 0) base[k] = d.simTime;
            if (std::isnan(base[k])) continue;
            tt += d.simTime;
            baseTotal += base[k];
            tl += d.length;
            tn += d.turns;
            ++ok;
        }
        md << "| " << (f < 0 ? std::string("A* Euclidean") : fixed(f, 2)) << " | " << fixed(tt, 1) << " (" << ok << " pairs) | "
           << (f < 0 ? std::string("-") : fixed(pct(baseTotal, tt), 1) + " %") << " | " << fixed(tl, 0) << " | " << fixed(tn, 0) << " |\n";
        jsweep.push_back({{"factor", f}, {"total_time", tt}, {"pairs", ok}, {"total_length", tl}, {"total_turns", tn}});
        std::fprintf(stderr, "[paper-c] sweep factor %g: %.1f s over %d pairs\n", f, tt, ok);
    }
    return jsweep;
}
}  // namespace

int runPaperC(const PaperCOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    if (o.pairs < 1 || o.pairs > 1000) throw InputError("--pairs must be in 1..1000");
    checkTimeLimit(o.timeLimit);
    fs::create_directories(o.outDir);
    std::vector<MapCase> maps{{"campus", std::make_shared<const OccupancyGrid>(generateCampus())}};
    const fs::path tsu = fs::path(o.sharedDir) / "maps/ros/tsudanuma_campus/tsudanuma_all.yaml";
    std::error_code tsuError;  // a --shared path the file system refuses: no Tsudanuma map
    if (fs::exists(tsu, tsuError))
        maps.push_back({"tsudanuma-0.298", std::make_shared<const OccupancyGrid>(loadMap(tsu.string()).resampled(0.298))});
    else
        std::fprintf(stderr, "[paper-c] %s not found: only the embedded campus map is run\n", tsu.string().c_str());
    std::vector<PairResult> all;
    nlohmann::json js = nlohmann::json::array();
    const auto t0 = Clock::now();
    for (const MapCase &mc : maps)
        for (const std::string vname : kVehicles) runPairs(o, mc, vname, all, js, t0);
    std::ostringstream md;
    writeTables(md, maps, all);
    const nlohmann::json jsweep = weightSweep(o, maps.front(), md);
    std::ofstream(fs::path(o.outDir) / "paper_c_tables.md") << md.str();
    std::ofstream(fs::path(o.outDir) / "paper_c.json") << nlohmann::json{{"pairs", js}, {"sweep", jsweep}}.dump(1) << "\n";
    std::fprintf(stderr, "[paper-c] wrote %s/paper_c_tables.md and paper_c.json\n", o.outDir.c_str());
    return 0;
}

}  // namespace gridcar::bench
