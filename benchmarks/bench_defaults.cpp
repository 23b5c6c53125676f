// The defaults suite: what a user meets with no parameters set. Seeded queries on the real maps
// in ../shared with their vehicles (paper C's robot indoors and on the Tsudanuma campus, both
// cars on Tsudanuma and the embedded campus), half of them to a goal pose (arrived at with the
// yaw the car fits at there), half to a position, from a start without a heading (the planner
// chooses it; --start-yaw: at the yaw the car fits at); corner-astar and improved-astar with their
// defaults (or with --param). Every exact path is checked independently (checkDrivable: exact
// FCL at 2 cm, K_max; reversing pieces with the body turned round) and its length compared with
// the shortest drivable path any of the reference configurations found for the query. Then
// (--unreachable) seeded goal poses proven cut off from the start: how fast the defaults say so.
// Output: a Markdown table per area on stdout, progress on stderr. See docs/performance.md.
#include "gridcar/query/PlanQuery.h"
#include "gridcar/bench/RandomPairs.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
using Area = BenchArea;

const std::vector<Area> kAreas = {
    {"willow-garage", "maps/ros/willow_garage/willow-2010-02-18-0.10.yaml", "paper-c-robot", 5, 40},
    {"mit-stata", "maps/ros/mit_stata_basement/stata_basement.yaml", "paper-c-robot", 5, 40},
    {"ut-gdc-2", "maps/ros/utexas_gdc_2/2.yaml", "paper-c-robot", 5, 40},
    {"ut-gdc-3ne", "maps/ros/utexas_gdc_3ne/3ne.yaml", "paper-c-robot", 5, 40},
    {"intel-lab", "maps/ros/intel_lab/intel.yaml", "paper-c-robot", 5, 30},
    {"nav2-depot", "maps/ros/nav2_depot/depot.yaml", "paper-c-robot", 5, 25},
    {"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-c-robot", 30, 150},
    {"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-i", 30, 150},
    {"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-c-car", 30, 150},
    {"campus", "embedded", "paper-i", 50, 300},
};

/// The planners under test: their defaults.
const std::vector<NamedConfiguration> kDefaults = {{"corner-astar", {}}, {"improved-astar", {}}};
/// What else our planners can do for a query: the shortest drivable path of all of them (and of
/// the defaults) is each query's reference length.
const std::vector<NamedConfiguration> kReferences = {
    {"corner-astar", {{"reverse", "on"}}},
    {"improved-astar", {{"mode", "integral"}}},
    {"improved-astar", {{"mode", "integral"}, {"reverse", "on"}}},
    {"improved-astar", {{"mode", "paper"}}},
};

struct Options
{
    std::string shared{"../shared"};
    int pairs{6};
    unsigned seed{1};
    double limit{10.0};
    std::vector<std::string> only, params, planners;
    bool noReferences{false};
    int unreachable{2};
    bool startYaw{false};  ///< start at the fitting yaw (an OMPL application's start state), not a free heading
};

struct Run
{
    bool exact{false}, drivable{false};
    double length{NAN}, seconds{0};
    int cusps{0};
};

double quantile(std::vector<double> v, double q)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

/// One configuration over an area's queries, on one kept planner (as an application keeps it).
std::vector<Run> runConfiguration(GridSetup &setup, const NamedConfiguration &c, const PlannerParams &extra,
                                  const std::vector<std::pair<Pose2, Pose2>> &queries, double limit, double &setupSeconds,
                                  const std::string &cli, bool freeStart)
{
    PlannerParams params = c.second;
    params.insert(params.end(), extra.begin(), extra.end());
    auto planner = configurePlanner(setup.ss->getSpaceInformation(), {c.first, params, freeStart, false});
    const auto t0 = std::chrono::steady_clock::now();
    planner->setup();
    setupSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::vector<Run> runs;
    for (std::size_t k = 0; k < queries.size(); ++k)
    {
        const bool pose = k % 2 == 0;  // half of the queries to a goal pose
        const QueryResult r = runQuery(setup, planner, queries[k].first, queries[k].second, limit, !pose);
        Run run;
        run.seconds = r.seconds;
        if (r.seconds > 1.0)  // the query to look at, as a command
        {
            std::string goal = std::to_string(queries[k].second.x) + "," + std::to_string(queries[k].second.y);
            if (pose) goal += "," + std::to_string(queries[k].second.yaw * 180 / M_PI);
            std::string set;
            for (const auto &kv : params) set += " --param " + kv.first + "=" + kv.second;
            // with a free start heading the start without a yaw, as gridcar plan takes it then
            std::string start = std::to_string(queries[k].first.x) + "," + std::to_string(queries[k].first.y);
            if (!freeStart) start += "," + std::to_string(queries[k].first.yaw * 180 / M_PI);
            std::fprintf(stderr, "[defaults]   %.2f s: %s --planner %s%s --start %s --goal %s\n", r.seconds, cli.c_str(),
                         c.first.c_str(), set.c_str(), start.c_str(), goal.c_str());
        }
        run.exact = r.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        run.drivable = run.exact && r.drivability.drivable;
        run.length = r.metrics.length;
        run.cusps = r.metrics.cusps;
        runs.push_back(run);
    }
    return runs;
}

/// Goal poses the vehicle fits at, seeded, that FootprintChecker::reachability() proves cut off
/// from @p start in a region of at most 50 000 cells; the defaults answer each (fast failure).
void unreachableGoals(const Options &o, GridSetup &setup, const Pose2 &start)
{
    const OccupancyGrid &g = *setup.grid;
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> ux(g.originX(), g.originX() + g.width() * g.resolution()),
        uy(g.originY(), g.originY() + g.height() * g.resolution()), uyaw(-M_PI, M_PI);
    std::vector<Pose2> goals;
    for (int attempt = 0; attempt < 200000 && int(goals.size()) < o.unreachable; ++attempt)
    {
        const Pose2 goal{ux(rng), uy(rng), uyaw(rng)};
        if (!setup.checker->isValid(goal.x, goal.y, goal.yaw)) continue;
        const FootprintChecker::Reach r = setup.checker->reachability(start, false, goal, false, 50000);
        if (r.verdict == FootprintChecker::Reach::Separated && r.shutEnd == 1) goals.push_back(goal);
    }
    if (goals.empty())
    {
        std::printf("\nNo goal pose cut off from the start found (200 000 seeded tries).\n");
        return;
    }
    std::printf("\n%zu seeded goal poses the vehicle fits at, cut off from the first query's start (the proof's own "
                "region of at most 50 000 cells):\n\n| planner | answered: median / max (ms) | status |\n|---|---|---|\n",
                goals.size());
    for (const auto &c : kDefaults)
    {
        auto planner = configurePlanner(setup.ss->getSpaceInformation(), {c.first, c.second, true, false});
        std::vector<double> ms;
        std::string statuses;
        for (const Pose2 &goal : goals)
        {
            const QueryResult r = runQuery(setup, planner, start, goal, o.limit, false);
            ms.push_back(1e3 * r.seconds);
            if (statuses.find(r.status.asString()) == std::string::npos)
                statuses += (statuses.empty() ? "" : ", ") + r.status.asString();
        }
        std::printf("| %s | %.1f / %.1f | %s |\n", configurationLabel(c).c_str(), quantile(ms, 0.5), quantile(ms, 1.0),
                    statuses.c_str());
    }
}

void runArea(const Options &o, const Area &area)
{
    const std::shared_ptr<const OccupancyGrid> grid = loadAreaMap(o.shared, area);
    if (!grid) return;
    const auto t0 = std::chrono::steady_clock::now();
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset(area.vehicle));
    const double mapSetup = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::vector<std::pair<Pose2, Pose2>> queries;
    for (const auto &[s, g] : randomPairs(*setup.checker, o.pairs, o.seed, area.lo, area.hi))
        queries.push_back({withFittingYaw(*setup.checker, s), withFittingYaw(*setup.checker, g)});
    std::fprintf(stderr, "[defaults] %s %s: %zu queries, map set-up %.2f s\n", area.name.c_str(), area.vehicle.c_str(),
                 queries.size(), mapSetup);
    const PlannerParams extra = parsePlannerParams(o.params);
    // a slow query is named on stderr as the command that plans it again
    std::string cli = "gridcar plan --map " + (area.map == "embedded" ? area.map : o.shared + "/" + area.map) +
                      " --vehicle " + area.vehicle;
    std::vector<std::vector<Run>> tested, refs;
    std::vector<NamedConfiguration> testedConfigs;
    std::vector<double> setups;
    for (const auto &c : kDefaults)
    {
        if (!o.planners.empty() && std::find(o.planners.begin(), o.planners.end(), c.first) == o.planners.end())
            continue;
        double s = 0;
        tested.push_back(runConfiguration(setup, c, extra, queries, o.limit, s, cli, !o.startYaw));
        testedConfigs.push_back(c);
        setups.push_back(s);
        std::fprintf(stderr, "[defaults]   %s done (planner set-up %.2f s)\n", configurationLabel(c).c_str(), s);
    }
    if (!o.noReferences)
        for (const auto &c : kReferences)
        {
            double s = 0;
            refs.push_back(runConfiguration(setup, c, {}, queries, o.limit, s, cli, !o.startYaw));
            std::fprintf(stderr, "[defaults]   reference %s done\n", configurationLabel(c).c_str());
        }
    // each query's shortest drivable path over every configuration run
    std::vector<double> best(queries.size(), std::numeric_limits<double>::infinity());
    for (const auto *set : {&tested, &refs})
        for (const auto &runs : *set)
            for (std::size_t k = 0; k < runs.size(); ++k)
                if (runs[k].drivable) best[k] = std::min(best[k], runs[k].length);
    std::printf("\n### %s, %s (%zu seeded queries %.0f-%.0f m apart, half to a goal pose; limit %.0f s; map set-up %.2f s)\n\n",
                area.name.c_str(), area.vehicle.c_str(), queries.size(), area.lo, area.hi, o.limit, mapSetup);
    std::printf("| planner | exact | drivable | solve() median / p95 / max (ms) | planner set-up (s) | length / shortest found: "
                "median / max | cusps |\n|---|---|---|---|---|---|---|\n");
    const auto row = [&](const std::string &label, const std::vector<Run> &runs, const std::string &setupCell) {
        int exact = 0, drivable = 0, cusps = 0;
        std::vector<double> ms, ratio;
        for (std::size_t k = 0; k < queries.size(); ++k)
        {
            const Run &r = runs[k];
            exact += r.exact;
            drivable += r.drivable;
            cusps += r.cusps;
            ms.push_back(1e3 * r.seconds);
            if (r.drivable && std::isfinite(best[k])) ratio.push_back(r.length / best[k]);
        }
        std::printf("| %s | %d / %zu | %d | %.0f / %.0f / %.0f | %s | %.3f / %.3f | %d |\n", label.c_str(), exact, queries.size(),
                    drivable, quantile(ms, 0.5), quantile(ms, 0.95), quantile(ms, 1.0), setupCell.c_str(), quantile(ratio, 0.5),
                    quantile(ratio, 1.0), cusps);
    };
    for (std::size_t c = 0; c < tested.size(); ++c)
    {
        std::string label = "**" + configurationLabel(testedConfigs[c]);
        for (const auto &kv : extra) label += " " + kv.first + "=" + kv.second;
        char cell[32];
        std::snprintf(cell, sizeof cell, "%.2f", setups[c]);
        row(label + "**", tested[c], cell);
    }
    for (std::size_t c = 0; c < refs.size(); ++c) row("(reference) " + configurationLabel(kReferences[c]), refs[c], "");
    if (o.unreachable > 0 && !queries.empty()) unreachableGoals(o, setup, queries.front().first);
    std::fflush(stdout);
}
}  // namespace

int main(int argc, char **argv)
{
    Options o;
    CLI::App app{"Defaults suite: seeded queries on the real maps with their vehicles, corner-astar and improved-astar "
                 "with no parameters set; every exact path checked independently and compared with the shortest any "
                 "reference configuration finds (see docs/performance.md)"};
    app.add_option("--shared", o.shared, "the shared folder holding maps/ (areas whose map is absent are skipped)")->capture_default_str();
    app.add_option("--pairs", o.pairs, "seeded queries per area")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--seed", o.seed, "random seed of the queries")->capture_default_str();
    app.add_option("--time-limit", o.limit, "solve() limit per query, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--only", o.only, "areas to run (willow-garage, mit-stata, ut-gdc-2, ut-gdc-3ne, intel-lab, nav2-depot, "
                                     "tsudanuma, campus; default: all)");
    app.add_option("--param", o.params, "NAME=VALUE set on the planners under test (repeatable; not on the references)");
    app.add_option("--planners", o.planners, "planners under test (corner-astar, improved-astar; default: both)")
        ->check(CLI::IsMember({"corner-astar", "improved-astar"}));
    app.add_option("--unreachable", o.unreachable,
                   "goal poses per area proven cut off from the start, answered by the defaults (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0, 100));
    app.add_flag("--start-yaw", o.startYaw,
                 "start at the yaw the vehicle fits at there, as an OMPL application's start state (default: a free start "
                 "heading, as gridcar plan --start X,Y)");
    app.add_flag("--no-references", o.noReferences, "skip the reference configurations (the ratio is then to the defaults' shortest)");
    CLI11_PARSE(app, argc, argv);
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG::setSeed(o.seed);
    std::printf("Defaults suite: %d seeded queries per area (seed %u), no parameters set%s; reference configurations:", o.pairs,
                o.seed, o.params.empty() ? "" : " but --param");
    for (const auto &c : kReferences) std::printf(" %s;", configurationLabel(c).c_str());
    std::printf("\n");
    try
    {
        for (const Area &a : kAreas)
            if (o.only.empty() || std::find(o.only.begin(), o.only.end(), a.name) != o.only.end()) runArea(o, a);
    }
    catch (const std::exception &e)  // a --param a planner does not have, a map that does not load
    {
        std::fprintf(stderr, "bench_defaults: %s\n", e.what());
        return 2;
    }
    return 0;
}
