// Replanning after the map changed (the issue "driving in a changing world", its incremental
// updates): on a real map, seeded start / goal pairs; each is planned, then an obstacle the map
// did not show (a box of 1-10 m a side) is put across the middle of the path, the distance
// field and the checker are brought up to date in place (DistanceField::update(),
// FootprintChecker::cellsChanged()) and the same planner plans again. Against it: a full
// set-up on the changed map (makeGridSetup(), a new planner), the way a planner met a changed
// map before. Every replanned path is checked by a checker made anew on the changed map
// (drivable: checkDrivable) and its cost compared with the fresh set-up's (the same search on
// the same cells: the same cost). Output: a Markdown table on stdout, progress on stderr.
// See docs/simulation.md.
#include "gridcar/bench/Quantile.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/bench/RandomPairs.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Options
{
    std::string shared{"../shared"}, map{"maps/ros/tsudanuma_campus/tsudanuma_all.yaml"}, planner{"corner-astar"};
    std::vector<std::string> vehicles{"paper-i", "paper-c-car"};
    int pairs{10};
    unsigned seed{1};
    double limit{10.0}, boxMax{10.0};
};

/// The cells of the box (sides @p a x @p b m, axis-aligned) centred at @p c, clipped to the map.
CellWindow boxCells(const OccupancyGrid &g, const Pose2 &c, double a, double b)
{
    const Cell lo = g.worldToCell(c.x - a / 2, c.y + b / 2), hi = g.worldToCell(c.x + a / 2, c.y - b / 2);
    return {std::max(0, lo.col), std::max(0, lo.row), std::min(g.width() - 1, hi.col), std::min(g.height() - 1, hi.row)};
}

bool inside(const OccupancyGrid &g, const CellWindow &w, const Pose2 &p, double reach)
{
    const double x0 = g.cellCenterX(w.col0) - reach, x1 = g.cellCenterX(w.col1) + reach;
    const double y0 = g.cellCenterY(w.row1) - reach, y1 = g.cellCenterY(w.row0) + reach;
    return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
}

void run(const Options &o, const std::string &vehicleName)
{
    const VehicleParams vehicle = VehicleParams::preset(vehicleName);
    auto grid = std::make_shared<OccupancyGrid>(loadMap(o.shared + "/" + o.map));
    auto t0 = std::chrono::steady_clock::now();
    auto field = std::make_shared<DistanceField>(*grid);
    const double fieldSeconds = since(t0);
    t0 = std::chrono::steady_clock::now();
    field->prepareUpdates(*grid);
    const double prepareSeconds = since(t0);
    GridSetup setup = makeGridSetup(grid, vehicle, SetupOptions(), field);
    auto planner = makePlanner(setup.ss->getSpaceInformation(), o.planner);
    const auto pairs = randomPairs(*setup.checker, o.pairs, o.seed, 30.0, 150.0);
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> side(1.0, o.boxMax);
    std::vector<double> update, replan, total, freshSetup, freshSolve;
    int planned = 0, replanned = 0, sameAsFresh = 0, drivable = 0, blockedBoth = 0, differ = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        const Pose2 s = withFittingYaw(*setup.checker, pairs[k].first), t = pairs[k].second;
        const QueryResult first = runQuery(setup, planner, s, t, o.limit, true);
        if (first.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
        ++planned;
        // the box across the path's middle, clear of both ends by the body's reach
        const Pose2 mid = first.path[first.path.size() / 2];
        CellWindow w = boxCells(*grid, mid, side(rng), side(rng));
        const double reach = setup.checker->reach() + 0.5;
        for (int shrink = 0; shrink < 20 && (inside(*grid, w, s, reach) || inside(*grid, w, t, reach)); ++shrink)
            w = boxCells(*grid, mid, 0.8 * (w.col1 - w.col0 + 1) * grid->resolution(), 0.8 * (w.row1 - w.row0 + 1) * grid->resolution());
        if (inside(*grid, w, s, reach) || inside(*grid, w, t, reach)) continue;
        std::vector<CellState> saved;
        for (int r = w.row0; r <= w.row1; ++r)
            for (int c = w.col0; c <= w.col1; ++c)
            {
                saved.push_back(grid->at(c, r));
                grid->set(c, r, CellState::Occupied);
            }
        t0 = std::chrono::steady_clock::now();
        setup.checker->cellsChanged(w, field->update(*grid, w));
        update.push_back(since(t0));
        const QueryResult again = runQuery(setup, planner, s, t, o.limit, true);
        replan.push_back(again.seconds);
        total.push_back(update.back() + again.seconds);
        // the same map made anew, the way a changed map was met before
        t0 = std::chrono::steady_clock::now();
        GridSetup fresh = makeGridSetup(std::make_shared<const OccupancyGrid>(*grid), vehicle);
        freshSetup.push_back(since(t0));
        const QueryResult anew = runQuery(fresh, makePlanner(fresh.ss->getSpaceInformation(), o.planner), s, t, o.limit, true);
        freshSolve.push_back(anew.seconds);
        const bool exact = again.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        const bool freshExact = anew.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        if (exact)
        {
            ++replanned;
            DrivabilityOptions d;
            d.reversing = true;
            drivable += checkDrivable(again.path, *fresh.checker, d).drivable ? 1 : 0;
        }
        if (!exact && !freshExact) ++blockedBoth;
        if (exact && freshExact && std::abs(again.cost - anew.cost) <= 1e-9 * std::max(1.0, anew.cost))
            ++sameAsFresh;
        else if (exact != freshExact || exact)
        {
            ++differ;
            std::printf("  pair %zu: replanned %s cost %.4f, fresh set-up %s cost %.4f\n", k, again.status.asString().c_str(),
                        again.cost, anew.status.asString().c_str(), anew.cost);
        }
        std::fprintf(stderr, "%s pair %zu: box %d x %d cells, update %.1f ms, replan %.1f ms (fresh set-up %.2f s + %.1f ms)\n",
                     vehicleName.c_str(), k, w.col1 - w.col0 + 1, w.row1 - w.row0 + 1, 1e3 * update.back(),
                     1e3 * again.seconds, freshSetup.back(), 1e3 * anew.seconds);
        // the box taken away again: an update too
        std::size_t i = 0;
        for (int r = w.row0; r <= w.row1; ++r)
            for (int c = w.col0; c <= w.col1; ++c) grid->set(c, r, saved[i++]);
        t0 = std::chrono::steady_clock::now();
        setup.checker->cellsChanged(w, field->update(*grid, w));
        update.push_back(since(t0));
    }
    std::printf("\n### %s, %s, %s: %d pairs planned, a box of 1-%.0f m a side put across each path\n\n", o.map.c_str(),
                vehicleName.c_str(), o.planner.c_str(), planned, o.boxMax);
    std::printf("distance field %.2f s; prepareUpdates() %.2f s, once\n\n", fieldSeconds, prepareSeconds);
    std::printf("| replanned exact | same cost as a fresh set-up | drivable (a new checker) | no path either way | update (box put, "
                "taken away) median / p95 / max (ms) | replan solve() median / p95 (ms) | update + replan median / p95 (ms) | "
                "fresh set-up median (s) + solve() median (ms) |\n|---|---|---|---|---|---|---|---|\n");
    std::printf("| %d/%zu | %d | %d | %d | %.1f / %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | %.2f + %.1f |\n", replanned, replan.size(),
                sameAsFresh, drivable, blockedBoth, 1e3 * quantile(update, 0.5), 1e3 * quantile(update, 0.95),
                1e3 * quantile(update, 1.0), 1e3 * quantile(replan, 0.5), 1e3 * quantile(replan, 0.95), 1e3 * quantile(total, 0.5),
                1e3 * quantile(total, 0.95), quantile(freshSetup, 0.5), 1e3 * quantile(freshSolve, 0.5));
    if (differ > 0) std::printf("\n%d replans differ from the fresh set-up's (listed above)\n", differ);
    std::fflush(stdout);
}
}  // namespace

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    Options o;
    CLI::App app{"Replanning after the map changed: in-place updates of the distance field and the checker against a "
                 "full set-up (see docs/simulation.md)"};
    app.add_option("--shared", o.shared, "the shared folder holding maps/")->capture_default_str();
    app.add_option("--map", o.map, "map under the shared folder")->capture_default_str();
    app.add_option("--vehicle", o.vehicles, "vehicle presets")->capture_default_str();
    app.add_option("--planner", o.planner, "planner name, its defaults")->capture_default_str();
    app.add_option("--pairs", o.pairs, "seeded start / goal pairs 30-150 m apart per vehicle")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--seed", o.seed, "random seed of the pairs and boxes")->capture_default_str();
    app.add_option("--time-limit", o.limit, "solve() limit per query, s")->check(CLI::PositiveNumber)->capture_default_str();
    app.add_option("--box-max", o.boxMax, "largest side of the box put across a path, m")
        ->check(CLI::Range(1.0, 100.0))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    try
    {
        for (const std::string &v : o.vehicles) run(o, v);
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "bench_replan: %s\n", e.what());
        return 2;
    }
    return 0;
}
