// The drive suite of the issue "Paths a vehicle can follow and a follower that arrives": seeded
// pairs on the real maps in ../shared (indoor maps with paper C's robot, the Tsudanuma campus at
// 0.05 m with both cars) and on the embedded campus, planned by corner-astar and improved-astar
// (integral) and corner-astar's driving-time cost (cost=time), every exact plan checked independently (checkDrivable: exact FCL at 2 cm, K_max,
// and its curvature rate measured), then driven by paper C's potential-field follower in the
// kinematic simulation: without moving obstacles, and with a pedestrian crossing the path at its
// middle when the vehicle gets there. Output: Markdown tables on stdout (and every run that does
// not arrive, with the follower's reason), progress on stderr. See docs/simulation.md.
#include "gridcar/query/PlanQuery.h"
#include "gridcar/bench/RandomPairs.h"
#include "gridcar/objectives/Objectives.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/vehicle/Dynamics.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
using Area = BenchArea;

const std::vector<Area> kAreas = {
    {"willow-garage", "maps/ros/willow_garage/willow-2010-02-18-0.10.yaml", "paper-c-robot", 5, 40},
    {"mit-stata", "maps/ros/mit_stata_basement/stata_basement.yaml", "paper-c-robot", 5, 40},
    {"ut-gdc-3ne", "maps/ros/utexas_gdc_3ne/3ne.yaml", "paper-c-robot", 5, 40},
    {"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-i", 30, 150},
    {"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-c-car", 30, 150},
    {"campus", "embedded", "paper-c-car", 50, 300},
};

const std::vector<std::pair<std::string, PlannerParams>> kPlanners = {
    {"corner-astar", {}},
    {"corner-astar", {{"cost", "time"}}},
    {"improved-astar", {{"mode", "integral"}}},
};

struct Options
{
    std::string shared{"../shared"};
    int pairs{10};
    unsigned seed{1};
    double limit{10.0};
    std::vector<std::string> only;
    std::vector<std::string> params;
    bool noMoving{false};
    std::string dumpDir;
    double omplSeconds{0.0};  ///< > 0: OMPL's planners under the driving-time objective too
};

/// OMPL's optimizing planners compared under DrivingTimeObjective on OMPL's Dubins space (the
/// suite's paths drive forwards), with --ompl-seconds.
const std::vector<std::string> kOmpl = {"rrtstar", "bitstar"};

void writeCsv(const std::string &file, const std::vector<Pose2> &path)
{
    if (FILE *f = std::fopen(file.c_str(), "w"))
    {
        std::fprintf(f, "x,y,yaw\n");
        for (const Pose2 &p : path) std::fprintf(f, "%.6f,%.6f,%.6f\n", p.x, p.y, p.yaw);
        std::fclose(f);
    }
}

struct Tally
{
    int plans{0}, exact{0}, drivable{0}, withinRate{0};
    int reached[2]{0, 0}, collided[2]{0, 0}, stuck[2]{0, 0}, timeout[2]{0, 0}, driven[2]{0, 0};
    std::vector<double> crossTrack, crossTrackMax, simTime, planTime;
    /// Per pair: simulated driving time when driven to the goal without the pedestrian, else NaN.
    std::vector<double> arrivedTime;
};

double median(std::vector<double> v)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

Tally runPlanner(const Options &o, const Area &area, GridSetup &setup, const std::vector<std::pair<Pose2, Pose2>> &pairs,
                 const ompl::base::PlannerPtr &planner, const std::string &label, double limit, std::vector<std::string> &failures);

void runArea(const Options &o, const Area &area, std::vector<std::string> &failures)
{
    const std::shared_ptr<const OccupancyGrid> grid = loadAreaMap(o.shared, area);
    if (!grid) return;
    const VehicleParams v = VehicleParams::preset(area.vehicle);
    GridSetup setup = makeGridSetup(grid, v);
    const auto pairs = randomPairs(*setup.checker, o.pairs, o.seed, area.lo, area.hi);
    std::printf("\n### %s, %s (%zu seeded pairs %.0f-%.0f m apart, limit %.0f s)\n\n", area.name.c_str(), area.vehicle.c_str(),
                pairs.size(), area.lo, area.hi, o.limit);
    std::printf("| planner | exact | drivable (checked) | within the curvature rate | reached | collided | stuck / timeout | "
                "with a pedestrian: reached | collided | stuck / timeout | cross-track median / max of means (m) | "
                "simulated driving time, median / sum (s) | solve() median (ms) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::vector<std::pair<std::string, Tally>> rows;
    for (const auto &[name, params] : kPlanners)
    {
        PlannerParams all = params;
        for (const auto &kv : parsePlannerParams(o.params)) all.push_back(kv);
        auto planner = configurePlanner(setup.ss->getSpaceInformation(), {name, all, true, false});
        const std::string label = name + (params.empty() ? "" : " " + params[0].first + "=" + params[0].second);
        rows.push_back({label, runPlanner(o, area, setup, pairs, planner, label, o.limit, failures)});
    }
    if (o.omplSeconds > 0)
    {
        // OMPL's planners on the Dubins space at R_min, minimising DrivingTimeObjective; they
        // start at the pair's start yaw (they have no free start heading) and end at any heading
        SetupOptions dubins;
        dubins.space = SpaceKind::Dubins;
        GridSetup dub = makeGridSetup(grid, v, dubins, setup.field);
        dub.ss->setOptimizationObjective(makeObjective("driving-time", dub.ss->getSpaceInformation(), *dub.checker));
        for (const std::string &name : kOmpl)
        {
            auto planner = configurePlanner(dub.ss->getSpaceInformation(), {name, {}, false, false});
            const std::string label = name + " driving-time (Dubins)";
            rows.push_back({label, runPlanner(o, area, dub, pairs, planner, label, o.omplSeconds, failures)});
        }
    }
    // the same pairs for every row: those every planner above drove to the goal
    std::vector<std::size_t> common;
    for (std::size_t k = 0; k < pairs.size(); ++k)
        if (std::all_of(rows.begin(), rows.end(), [k](const auto &r) { return !std::isnan(r.second.arrivedTime[k]); }))
            common.push_back(k);
    std::printf("\nSimulated driving time on the %zu pairs every planner above drove to the goal (no pedestrian), sum:", common.size());
    for (const auto &[label, t] : rows)
    {
        double sum = 0;
        for (std::size_t k : common) sum += t.arrivedTime[k];
        std::printf(" %s %.0f s%s", label.c_str(), sum, &label == &rows.back().first ? ".\n" : ";");
    }
    std::fflush(stdout);
}

/// One planner over an area's pairs: plan, check, drive; one table row.
Tally runPlanner(const Options &o, const Area &area, GridSetup &setup, const std::vector<std::pair<Pose2, Pose2>> &pairs,
                 const ompl::base::PlannerPtr &planner, const std::string &label, double limit, std::vector<std::string> &failures)
{
    const VehicleParams &v = setup.checker->vehicle();
    {
        // the files of --failed-dir, one name per planner configuration (corner-astar and
        // corner-astar cost=time wrote over each other's)
        std::string fileLabel = label;
        std::replace_if(fileLabel.begin(), fileLabel.end(), [](char ch) { return ch == ' ' || ch == '=' || ch == '(' || ch == ')'; }, '-');
        const std::string stemBase = o.dumpDir + "/" + area.name + "-" + area.vehicle + "-" + fileLabel + "-";
        Tally t;
        t.arrivedTime.assign(pairs.size(), NAN);
        for (std::size_t k = 0; k < pairs.size(); ++k)
        {
            const Pose2 s = withFittingYaw(*setup.checker, pairs[k].first), g = withFittingYaw(*setup.checker, pairs[k].second);
            const QueryResult r = runQuery(setup, planner, s, g, limit, /*freeGoalHeading=*/true);
            ++t.plans;
            t.planTime.push_back(r.seconds);
            if (r.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
            ++t.exact;
            if (!r.drivability.drivable) continue;
            ++t.drivable;
            if (r.drivability.maxCurvatureRate <= 1.02 * v.curvatureRateLimit())
                ++t.withinRate;
            else
            {
                std::fprintf(stderr, "  %s %s %s pair %zu (%.2f, %.2f, yaw %.4f -> %.2f, %.2f): curvature rate %.3g 1/m^2, "
                             "over the vehicle's %.3g\n", area.name.c_str(), area.vehicle.c_str(), label.c_str(), k, s.x, s.y,
                             s.yaw, g.x, g.y, r.drivability.maxCurvatureRate, v.curvatureRateLimit());
                if (!o.dumpDir.empty())
                    writeCsv(stemBase + std::to_string(k) + "-rate-path.csv", r.path);
            }
            for (int m = 0; m < (o.noMoving ? 1 : 2); ++m)
            {
                const DriveResult d = drivePath(r.path, *setup.checker, m ? Scenario{{crossingPedestrian(r.path, v)}} : Scenario());
                ++t.driven[m];
                switch (d.outcome)
                {
                    case DriveResult::Outcome::Reached: ++t.reached[m]; break;
                    case DriveResult::Outcome::Collided: ++t.collided[m]; break;
                    case DriveResult::Outcome::Stuck: ++t.stuck[m]; break;
                    default: ++t.timeout[m]; break;
                }
                if (m == 0)
                {
                    t.crossTrack.push_back(d.crossTrackMean);
                    t.simTime.push_back(d.drivingTime);
                    if (d.outcome == DriveResult::Outcome::Reached) t.arrivedTime[k] = d.drivingTime;
                }
                if (d.outcome != DriveResult::Outcome::Reached)
                {
                    char buf[160];
                    std::snprintf(buf, sizeof buf, "%s %s %s pair %zu (%.2f, %.2f -> %.2f, %.2f)%s: ", area.name.c_str(),
                                  area.vehicle.c_str(), label.c_str(), k, s.x, s.y, g.x, g.y, m ? " with a pedestrian" : "");
                    failures.push_back(buf + DriveResult::outcomeName(d.outcome) + ": " + d.reason);
                    if (!o.dumpDir.empty())
                    {
                        const std::string stem = stemBase + std::to_string(k) + (m ? "-pedestrian" : "");
                        writeCsv(stem + "-path.csv", r.path);
                        if (FILE *f = std::fopen((stem + "-drive.csv").c_str(), "w"))
                        {
                            std::fprintf(f, "t,x,y,yaw,v,steer,ox,oy\n");
                            const Scenario sc = m ? Scenario{{crossingPedestrian(r.path, v)}} : Scenario();
                            for (const TrajectorySample &q : d.trajectory)
                            {
                                double ox = NAN, oy = NAN;
                                if (!sc.obstacles.empty()) sc.obstacles[0].positionAt(q.t, ox, oy);
                                std::fprintf(f, "%.2f,%.4f,%.4f,%.4f,%.3f,%.3f,%.3f,%.3f\n", q.t, q.x, q.y, q.yaw, q.v, q.steer, ox, oy);
                            }
                            std::fclose(f);
                        }
                    }
                }
                // the start yaw in degrees, as gridcar drive --start x,y,yaw takes it
                std::fprintf(stderr, "  %s %s %s pair %zu (%.2f, %.2f, %.1f deg -> %.2f, %.2f)%s: %s, %.1f s, path %.1f m\n",
                             area.name.c_str(), area.vehicle.c_str(), label.c_str(), k, s.x, s.y, s.yaw * 180 / M_PI, g.x,
                             g.y, m ? " (pedestrian)" : "",
                             DriveResult::outcomeName(d.outcome).c_str(), d.drivingTime, r.metrics.length);
            }
        }
        std::vector<double> ct = t.crossTrack;
        double simSum = 0;
        for (double x : t.simTime) simSum += x;
        std::printf("| %s | %d/%d | %d | %d | %d/%d | %d | %d / %d | %d/%d | %d | %d / %d | %.3f / %.3f | %.1f / %.0f | %.1f |\n",
                    label.c_str(), t.exact, t.plans, t.drivable, t.withinRate, t.reached[0], t.driven[0], t.collided[0],
                    t.stuck[0], t.timeout[0], t.reached[1], t.driven[1], t.collided[1], t.stuck[1], t.timeout[1], median(ct),
                    ct.empty() ? NAN : *std::max_element(ct.begin(), ct.end()), median(t.simTime), simSum,
                    1e3 * median(t.planTime));
        std::fflush(stdout);
        return t;
    }
}
}  // namespace

int main(int argc, char **argv)
{
    Options o;
    CLI::App app{"Drive suite: seeded pairs on real maps, planned by gridcar's car-lattice planners, every exact and "
                 "drivable plan driven by paper C's follower without and with a crossing pedestrian (see docs/simulation.md)"};
    app.add_option("--shared", o.shared, "the shared folder holding maps/ (areas whose map is absent are skipped)")->capture_default_str();
    app.add_option("--pairs", o.pairs, "seeded pairs per area")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--seed", o.seed, "random seed of the pairs")->capture_default_str();
    app.add_option("--time-limit", o.limit, "solve() limit per query, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--only", o.only, "areas to run: willow-garage, mit-stata, ut-gdc-3ne, tsudanuma, campus (default: all)");
    app.add_option("--param", o.params, "NAME=VALUE set on every planner (repeatable)");
    app.add_flag("--no-moving", o.noMoving, "drive without the pedestrian only");
    app.add_option("--ompl-seconds", o.omplSeconds,
                   "also plan each pair with OMPL's RRT* and BIT* on the Dubins space under the driving-time objective, "
                   "this long per query (s; 0: skip them)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    app.add_option("--failed-dir", o.dumpDir, "write the path and the simulated trajectory (with the pedestrian's position) of "
                                              "every run that does not arrive, and every path over the curvature rate "
                                              "(NAME-rate-path.csv), here as CSV (an existing directory)");
    CLI11_PARSE(app, argc, argv);
    for (const std::string &a : o.only)
        if (std::none_of(kAreas.begin(), kAreas.end(), [&](const Area &x) { return x.name == a; }))
        {
            std::fprintf(stderr, "bench_drive: unknown area '%s'\n", a.c_str());
            return 2;
        }
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ompl::RNG::setSeed(o.seed);  // OMPL's planners (--ompl-seconds) sample reproducibly
    std::vector<std::string> failures;
    try
    {
        for (const Area &area : kAreas)
            if (o.only.empty() || std::find(o.only.begin(), o.only.end(), area.name) != o.only.end())
                runArea(o, area, failures);
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "bench_drive: %s\n", e.what());
        return 2;
    }
    std::printf("\nRuns that did not reach the goal (%zu):\n\n", failures.size());
    for (const std::string &f : failures) std::printf("- %s\n", f.c_str());
    return 0;
}
