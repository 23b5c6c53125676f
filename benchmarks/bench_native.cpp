// The car-lattice benchmark of the issue "fast, drivable search at the map's native resolution":
// seeded random pairs on a real map at its own resolution, each of gridcar's car-lattice planners
// on each vehicle, every path checked independently (checkDrivable: exact FCL at 2 cm, curvature
// <= K_max), solve() times, set-up time and peak RSS; OMPL's BIT* on a Reeds-Shepp space with
// the same footprint checker and the same start / goal poses on the first pairs; and on the
// embedded campus the old grid lattice beside the car lattice from the same run.
// Output: Markdown tables on stdout, progress on stderr. See docs/performance.md.
#include "gridcar/bench/Quantile.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/bench/RandomPairs.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/vehicle/Dynamics.h"

#include <CLI/CLI.hpp>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/util/Console.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
double peakRssMb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss / 1024.0;
}

double seconds(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Row
{
    std::string label;
    int runs{0}, solved{0}, drivable{0}, reached{0};
    std::vector<double> times, lengths, drive;
};

/// OMPL's BIT* on a Reeds-Shepp space (radius R_min), gridcar's footprint checker as the
/// validity checker, motions checked every 2 cm along the curve.
struct RsResult
{
    bool solved{false};
    double length{0}, drive{0};
};
RsResult bitstarReedsShepp(const FootprintChecker &fc, const Pose2 &s, const Pose2 &t, double limit)
{
    const OccupancyGrid &g = fc.grid();
    auto space = std::make_shared<ompl::base::ReedsSheppStateSpace>(fc.vehicle().minTurningRadius());
    ompl::base::RealVectorBounds b(2);
    b.setLow(0, g.originX());
    b.setHigh(0, g.originX() + g.sizeX());
    b.setLow(1, g.originY());
    b.setHigh(1, g.originY() + g.sizeY());
    space->setBounds(b);
    ompl::geometric::SimpleSetup ss(space);
    ss.setStateValidityChecker([&fc](const ompl::base::State *st) {
        const auto *p = st->as<ompl::base::SE2StateSpace::StateType>();
        return fc.isValid(p->getX(), p->getY(), p->getYaw());
    });
    ss.getSpaceInformation()->setStateValidityCheckingResolution(0.02 / space->getMaximumExtent());
    ompl::base::ScopedState<> a(space), z(space);
    a[0] = s.x, a[1] = s.y, a[2] = s.yaw;
    z[0] = t.x, z[1] = t.y, z[2] = t.yaw;
    ss.setStartAndGoalStates(a, z);
    ss.setPlanner(std::make_shared<ompl::geometric::BITstar>(ss.getSpaceInformation()));
    RsResult r;
    if (ss.solve(limit) != ompl::base::PlannerStatus::EXACT_SOLUTION) return r;
    auto path = ss.getSolutionPath();
    r.solved = true;
    r.length = path.length();
    path.interpolate(std::max<unsigned>(2, unsigned(r.length / 0.05)));
    std::vector<Pose2> poses;
    for (auto *st : path.getStates())
    {
        const auto *p = st->as<ompl::base::SE2StateSpace::StateType>();
        poses.push_back({p->getX(), p->getY(), p->getYaw()});
    }
    r.drive = drivingTime(poses, fc.vehicle());
    return r;
}

void printRows(const std::vector<Row> &rows)
{
    std::printf("| planner | solved | drivable | driven to the goal | solve() median / p90 / max (ms) | mean length (m) | mean "
                "driving time (s) |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (const Row &r : rows)
    {
        double len = 0, dr = 0;
        for (double v : r.lengths) len += v;
        for (double v : r.drive) dr += v;
        const double k = r.lengths.empty() ? NAN : 1.0 / double(r.lengths.size());
        std::printf("| %s | %d/%d | %d/%d | %d/%d | %.1f / %.1f / %.1f | %.1f | %.1f |\n", r.label.c_str(), r.solved, r.runs,
                    r.drivable, r.runs, r.reached, r.runs, 1e3 * quantile(r.times, 0.5), 1e3 * quantile(r.times, 0.9),
                    1e3 * quantile(r.times, 1.0), len * k, dr * k);
    }
    std::fflush(stdout);
}

struct Options
{
    std::string map{"../shared/maps/ros/tsudanuma_campus/tsudanuma_all.yaml"};
    std::vector<std::string> vehicles{"paper-i", "paper-c-car"};
    int pairs{20};
    unsigned seed{1};
    double limit{10.0};
    int bitstarPairs{5};
    double bitstarTime{10.0};
    int campusPairs{20};
    std::vector<int> only;  ///< indices into kPlanners (empty: all)
    bool goalYaw{false};    ///< the goal's yaw is part of the query (a pose to arrive at)
    std::vector<std::string> params;  ///< NAME=VALUE for every car-lattice planner
    int repeat{1};                    ///< solves per query; the least time is reported
};

const std::vector<std::pair<std::string, PlannerParams>> kPlanners = {
    {"improved-astar", {{"mode", "paper"}}},
    {"improved-astar", {{"mode", "integral"}}},
    {"corner-astar", {}},
};

std::string labelOf(const std::string &name, const PlannerParams &p)
{
    std::string s = name;
    for (const auto &kv : p) s += " " + kv.first + "=" + kv.second;
    return s;
}

/// One query of @p planner; fills @p row and says in @p driven how the simulation's drive of an
/// exact path ended ("driven" or the outcome and its reason).
QueryResult runOne(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &s, const Pose2 &t,
                   double limit, bool goalYaw, int repeat, Row &row, std::string &driven)
{
    driven = "not driven";
    // the pairs have no goal yaw unless --goal-yaw gives them the one they fit at; repeated,
    // the least time (a shared machine's noise only ever adds time; the searches are the same)
    QueryResult r = runQuery(setup, planner, s, t, limit, /*freeGoalHeading=*/!goalYaw);
    for (int k = 1; k < repeat; ++k)
    {
        const double least = r.seconds;
        r = runQuery(setup, planner, s, t, limit, /*freeGoalHeading=*/!goalYaw);
        r.seconds = std::min(r.seconds, least);
    }
    ++row.runs;
    row.times.push_back(r.seconds);
    if (r.status == ompl::base::PlannerStatus::EXACT_SOLUTION)
    {
        ++row.solved;
        row.lengths.push_back(r.metrics.length);
        row.drive.push_back(drivingTime(r.path, setup.checker->vehicle()));
        if (r.drivability.drivable) ++row.drivable;
        // the path driven by paper C's follower in the kinematic simulation
        const DriveResult d = drivePath(r.path, *setup.checker, Scenario());
        if (d.outcome == DriveResult::Outcome::Reached) ++row.reached;
        driven = d.outcome == DriveResult::Outcome::Reached ? "driven" : DriveResult::outcomeName(d.outcome) + ": " + d.reason;
    }
    return r;
}

void nativeMap(const Options &o)
{
    for (const std::string &vname : o.vehicles)
    {
        const VehicleParams v = VehicleParams::preset(vname);
        const double rss0 = peakRssMb();
        auto t0 = std::chrono::steady_clock::now();
        auto grid = std::make_shared<const OccupancyGrid>(loadMap(o.map));
        const double loadSec = seconds(t0);
        t0 = std::chrono::steady_clock::now();
        GridSetup setup = makeGridSetup(grid, v);
        const double setupSec = seconds(t0);
        std::fprintf(stderr, "%s: map loaded in %.2f s, set-up %.2f s\n", vname.c_str(), loadSec, setupSec);
        const auto pairs = randomPairs(*setup.checker, o.pairs, o.seed, 60.0, 250.0);
        std::vector<Row> rows;
        std::vector<std::pair<Pose2, Pose2>> posesForBit;
        std::vector<std::size_t> bitPairs;  // pair index of each posesForBit entry
        for (std::size_t pi = 0; pi < kPlanners.size(); ++pi)
        {
            if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), int(pi)) == o.only.end()) continue;
            const auto &[name, params] = kPlanners[pi];
            PlannerParams all = params;
            for (const auto &kv : parsePlannerParams(o.params)) all.push_back(kv);
            PlannerConfig cfg{name, all, true, false};
            auto planner = configurePlanner(setup.ss->getSpaceInformation(), cfg);
            Row row{labelOf(name, params)};
            for (std::size_t k = 0; k < pairs.size(); ++k)
            {
                const Pose2 s = withFittingYaw(*setup.checker, pairs[k].first), t = withFittingYaw(*setup.checker, pairs[k].second);
                std::string driven;
                const QueryResult r = runOne(setup, planner, s, t, o.limit, o.goalYaw, o.repeat, row, driven);
                // poses as gridcar plan takes them (--start x,y,yaw_deg): a query a user can run again
                std::fprintf(stderr, "  %s pair %zu (%.2f,%.2f,%.1f -> %.2f,%.2f,%.1f): %s %.3f s, %llu expansions, %s, %s\n",
                             row.label.c_str(), k, s.x, s.y, s.yaw * 180 / M_PI, t.x, t.y, t.yaw * 180 / M_PI,
                             r.status.asString().c_str(), r.seconds,
                             static_cast<unsigned long long>(r.expanded),
                             r.drivability.drivable ? "drivable" : r.drivability.reason.c_str(), driven.c_str());
                if (name == "improved-astar" && params[0].second == "integral" && int(k) < o.bitstarPairs && !r.path.empty() &&
                    r.status == ompl::base::PlannerStatus::EXACT_SOLUTION)
                {
                    posesForBit.push_back({r.path.front(), r.path.back()});
                    bitPairs.push_back(k);
                }
            }
            rows.push_back(row);
        }
        std::printf("\n### %s, %s (%zu pairs, limit %.0f s, map load %.2f s, set-up %.2f s, peak RSS %.0f MB -> %.0f MB)\n\n", o.map.c_str(),
                    vname.c_str(), pairs.size(), o.limit, loadSec, setupSec, rss0, peakRssMb());
        printRows(rows);
        if (posesForBit.empty()) continue;
        std::printf("\nBIT* on Reeds-Shepp (R_min %.2f m), %.0f s, from the start pose and to the end pose of improved-astar "
                    "integral's path; ours / BIT* (below 1: ours better):\n\n",
                    v.minTurningRadius(), o.bitstarTime);
        std::printf("| pair | BIT* length (m) | BIT* driving time (s) | integral length | integral driving time | corner-astar "
                    "length | corner-astar driving time |\n|---|---|---|---|---|---|---|\n");
        // per planner row: the k-th solved query's metrics (every pair solved: see the table)
        auto metric = [&](const char *label, std::size_t pair, bool drive) {
            for (const Row &r : rows)
                if (r.label.find(label) != std::string::npos && r.solved == r.runs)
                    return drive ? r.drive[pair] : r.lengths[pair];
            return double(NAN);
        };
        std::vector<double> best[2];
        for (std::size_t k = 0; k < posesForBit.size(); ++k)
        {
            const RsResult b = bitstarReedsShepp(*setup.checker, posesForBit[k].first, posesForBit[k].second, o.bitstarTime);
            if (!b.solved)
            {
                std::printf("| %zu | not solved | | | | | |\n", bitPairs[k]);
                continue;
            }
            const std::size_t p = bitPairs[k];
            const double il = metric("integral", p, false) / b.length, id = metric("integral", p, true) / b.drive;
            const double cl = metric("corner", p, false) / b.length, cd = metric("corner", p, true) / b.drive;
            best[0].push_back(std::min(il, cl));
            best[1].push_back(std::min(id, cd));
            std::printf("| %zu | %.1f | %.1f | %.3f | %.3f | %.3f | %.3f |\n", p, b.length, b.drive, il, id, cl, cd);
            std::fflush(stdout);
        }
        std::printf("\nbest of ours / BIT*: length median %.3f max %.3f; driving time median %.3f max %.3f\n",
                    quantile(best[0], 0.5), quantile(best[0], 1.0), quantile(best[1], 0.5), quantile(best[1], 1.0));
    }
}

void campus(const Options &o)
{
    auto grid = std::make_shared<const OccupancyGrid>(generateCampus());
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset("paper-i"));
    const auto pairs = randomPairs(*setup.checker, o.campusPairs, o.seed, 20.0, 150.0);
    std::vector<Row> rows;
    // (grid lattice, car lattice) pairs: the papers' searches on the map's cells, then ours
    const std::vector<std::pair<std::string, PlannerParams>> configs = {
        {"improved-astar", {{"mode", "paper"}, {"lattice", "grid"}}}, {"improved-astar", {{"mode", "paper"}, {"lattice", "car"}}},
        {"improved-astar", {{"mode", "integral"}, {"lattice", "grid"}}}, {"improved-astar", {{"mode", "integral"}, {"lattice", "car"}}},
        {"corner-astar", {{"mode", "paper"}}}, {"corner-astar", {{"mode", "drivable"}}}};
    for (const auto &[name, params] : configs)
    {
        auto planner = configurePlanner(setup.ss->getSpaceInformation(), {name, params, true, false});
        Row row{labelOf(name, params)};
        std::string driven;
        for (const auto &[s0, t0] : pairs)
            runOne(setup, planner, withFittingYaw(*setup.checker, s0), withFittingYaw(*setup.checker, t0), o.limit, false, 1,
                   row, driven);
        rows.push_back(row);
    }
    std::printf("\n### embedded campus (0.298 m), paper-i, %zu pairs 20-150 m\n\n", pairs.size());
    printRows(rows);
    std::printf("\nmedian solve() time, car lattice / grid lattice: improved-astar paper %.3f, integral %.3f, corner-astar %.3f\n",
                quantile(rows[1].times, 0.5) / quantile(rows[0].times, 0.5),
                quantile(rows[3].times, 0.5) / quantile(rows[2].times, 0.5),
                quantile(rows[5].times, 0.5) / quantile(rows[4].times, 0.5));
}
}  // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    Options o;
    CLI::App app{"Car-lattice benchmark on a real map at its native resolution (see docs/performance.md)"};
    app.add_option("--map", o.map, "ROS map (.yaml) or any map gridcar reads")->capture_default_str();
    app.add_option("--vehicle", o.vehicles, "vehicle presets")->capture_default_str();
    app.add_option("--pairs", o.pairs, "random start / goal pairs per vehicle")->capture_default_str();
    app.add_option("--seed", o.seed, "random seed of the pairs")->capture_default_str();
    app.add_option("--time-limit", o.limit, "solve() limit per query, s")->capture_default_str();
    app.add_option("--bitstar-pairs", o.bitstarPairs, "pairs also given to BIT* on Reeds-Shepp (0: none)")->capture_default_str();
    app.add_option("--bitstar-time", o.bitstarTime, "BIT*'s time per pair, s")->capture_default_str();
    app.add_option("--campus-pairs", o.campusPairs, "pairs on the embedded campus (0: skip)")->capture_default_str();
    app.add_option("--param", o.params, "NAME=VALUE set on every planner of the native-map runs (repeatable)");
    app.add_option("--only", o.only, "planner indices to run: 0 improved-astar paper, 1 integral, 2 corner-astar");
    app.add_flag("--goal-yaw", o.goalYaw,
                 "native-map pairs: the goal is a pose, arrived at with the yaw the car fits at there (default: a "
                 "position, any heading)");
    app.add_option("--repeat", o.repeat,
                   "native-map queries: solves per query, the least solve() time reported (a shared machine's noise only "
                   "adds time; the path of the last solve is checked and driven)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try
    {
        if (o.pairs > 0) nativeMap(o);
        if (o.campusPairs > 0) campus(o);
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "bench_native: %s\n", e.what());
        return 2;
    }
    return 0;
}
