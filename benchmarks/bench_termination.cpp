// Termination benchmark of the issue "trustworthy under real use": how late every planner returns
// after its time limit or a cancel, on the 24 M-cell Tsudanuma map (0.05 m) with paper I's car,
// on a long query that runs to the limit (the farthest of 2000 seeded poses for 0.2 s, a walled-in goal for
// 1 s and 0.2 s), three ways: the time limit with set-up done before solve(), the time limit
// with set-up done inside SimpleSetup::solve() (a fresh planner), and a cancel flag set from
// another thread. Output: a Markdown table on stdout, progress on stderr. See
// docs/reliability.md.
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/PlannerFactory.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace gridcar;
using Clock = std::chrono::steady_clock;

namespace
{
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// Every configuration (PlanQuery.h), and the car lattice at the map's own 0.05 m: slow
/// enough to run into the limits.
std::vector<NamedConfiguration> configurations()
{
    std::vector<NamedConfiguration> out = everyConfiguration();
    out.push_back({"corner-astar", {{"lattice_cell", "0.05"}}});
    out.push_back({"improved-astar", {{"lattice_cell", "0.05"}}});
    return out;
}

bool isOurs(const std::string &name)
{
    const std::string base = name.substr(0, name.find('+'));
    for (const auto &n : gridPlannerNames())
        if (n == base) return true;
    return false;
}

/// Seeded poses where the car fits with half a body width of room on each side.
std::vector<Pose2> roomyPoses(const FootprintChecker &fc, std::mt19937 &rng, int n)
{
    const OccupancyGrid &g = fc.grid();
    std::uniform_int_distribution<int> col(0, g.width() - 1), row(0, g.height() - 1);
    std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
    std::vector<Pose2> out;
    for (long k = 0; k < 100000000L && int(out.size()) < n; ++k)
    {
        const int c = col(rng), r = row(rng);
        if (fc.field().cellDistance(c, r) < fc.vehicle().width) continue;
        const Pose2 p{g.cellCenterX(c), g.cellCenterY(r), yaw(rng)};
        if (fc.isValid(p)) out.push_back(p);
    }
    if (int(out.size()) < n) throw std::runtime_error("too few poses where the car fits with room on the map");
    return out;
}

enum class Mode
{
    Limit,         ///< ss.setup() first, then solve(limit)
    SetupInSolve,  ///< a fresh planner: SimpleSetup::solve(limit) sets it up
    Cancel         ///< a flag set from another thread after `limit` seconds
};

/// Seconds from the limit (or the cancel) to solve()'s return; NaN when it returned before it
/// (solved, or the search exhausted what it could reach).
double lateness(GridSetup &s, const NamedConfiguration &c, const Pose2 &a, const Pose2 &b,
                double limit, Mode mode)
{
    s.ss->clear();
    s.setStartAndGoal(a, b);
    s.ss->setPlanner(configurePlanner(s.ss->getSpaceInformation(), {c.first, c.second, false, false}));
    if (mode != Mode::SetupInSolve) s.ss->setup();
    ompl::base::PlannerStatus st;
    double late;
    const auto t0 = Clock::now();
    if (mode == Mode::Cancel)
    {
        std::atomic<bool> stop{false};
        std::atomic<double> setAt{0.0};
        std::thread canceller([&] {
            std::this_thread::sleep_for(std::chrono::duration<double>(limit));
            setAt = since(t0);
            stop = true;
        });
        st = s.ss->solve(ompl::base::PlannerTerminationCondition([&] { return stop.load(); }));
        const double back = since(t0);
        canceller.join();
        late = stop ? back - setAt : NAN;
    }
    else
    {
        st = s.ss->solve(limit);
        late = since(t0) - limit;
    }
    (void)st;
    return late < 0 || std::isnan(late) ? NAN : late;
}
}  // namespace

int main(int argc, char **argv)
{
    CLI::App app{"bench_termination: how late every planner returns after its time limit or a cancel"};
    std::string shared = "../shared";
    int runs = 2;
    unsigned seed = 7;
    app.add_option("--shared", shared, "folder holding maps/ros/tsudanuma_campus");
    app.add_option("--runs", runs, "runs per planner, mode and limit (the table shows the worst)")->check(CLI::Range(1, 20));
    app.add_option("--seed", seed, "seed of the query's poses");
    std::string only;
    app.add_option("--only", only, "run only the configurations whose label contains this text (e.g. 'lattice_cell')");
    CLI11_PARSE(app, argc, argv);
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(seed);

    const std::string mapPath = shared + "/maps/ros/tsudanuma_campus/tsudanuma_all.yaml";
    std::fprintf(stderr, "loading %s\n", mapPath.c_str());
    auto grid = std::make_shared<OccupancyGrid>(loadMap(mapPath));
    const VehicleParams car = VehicleParams::preset("paper-i");
    GridSetup probe = makeGridSetup(grid, car);
    std::mt19937 rng(seed);
    // the start, the farthest of 2000 seeded poses from it, and one at two thirds of that
    const std::vector<Pose2> poses = roomyPoses(*probe.checker, rng, 2000);
    const Pose2 start = poses[0];
    auto dist = [&](const Pose2 &p) { return std::hypot(p.x - start.x, p.y - start.y); };
    Pose2 far = start, yard = start;
    for (const Pose2 &p : poses)
        if (dist(p) > dist(far)) far = p;
    for (const Pose2 &p : poses)
        if (std::abs(dist(p) - 2 * dist(far) / 3) < std::abs(dist(yard) - 2 * dist(far) / 3)) yard = p;
    // wall the yard in: a closed square 10 m round it, so every search runs until it is stopped
    auto walled = std::make_shared<OccupancyGrid>(*grid);
    const Cell yc = walled->worldToCell(yard.x, yard.y);
    const int half = int(std::lround(10.0 / walled->resolution()));
    for (int d = -half; d <= half; ++d)
        for (int t : {-half, half})
            for (const auto &[c, r] : {std::pair{yc.col + d, yc.row + t}, std::pair{yc.col + t, yc.row + d}})
                if (walled->inBounds(c, r)) walled->set(c, r, CellState::Occupied);
    GridSetup open = std::move(probe), closed = makeGridSetup(walled, car);
    std::fprintf(stderr, "map %d x %d cells; start (%.1f, %.1f), far goal (%.1f, %.1f), walled goal (%.1f, %.1f)\n",
                 grid->width(), grid->height(), start.x, start.y, far.x, far.y, yard.x, yard.y);

    struct Case
    {
        const char *name;
        GridSetup *setup;
        Pose2 goal;
        double limit;
    };
    const Case cases[] = {{"far 0.2 s", &open, far, 0.2}, {"walled 0.2 s", &closed, yard, 0.2}, {"walled 1 s", &closed, yard, 1.0}};
    const Mode modes[] = {Mode::Limit, Mode::SetupInSolve, Mode::Cancel};
    const char *modeNames[] = {"limit", "setup in solve", "cancel"};
    std::printf("Lateness (ms) after the time limit or the cancel, worst of %d runs; - : returned before it (solved, or "
                "the search exhausted what it could reach).\n\n",
                runs);
    std::printf("| planner |");
    for (const Case &k : cases)
        for (const char *m : modeNames) std::printf(" %s, %s |", k.name, m);
    std::printf("\n|---|");
    for (std::size_t i = 0; i < std::size(cases) * std::size(modes); ++i) std::printf("---:|");
    std::printf("\n");
    double worstOurs = 0, worstAll = 0;
    for (const auto &c : configurations())
    {
        if (!only.empty() && configurationLabel(c).find(only) == std::string::npos) continue;
        std::printf("| %s |", configurationLabel(c).c_str());
        for (const Case &k : cases)
            for (std::size_t m = 0; m < std::size(modes); ++m)
            {
                double worst = NAN;
                for (int r = 0; r < runs; ++r)
                {
                    const double l = lateness(*k.setup, c, start, k.goal, k.limit, modes[m]);
                    if (!std::isnan(l)) worst = std::isnan(worst) ? l : std::max(worst, l);
                }
                std::fprintf(stderr, "%-36s %-13s %-15s %s\n", configurationLabel(c).c_str(), k.name, modeNames[m],
                             std::isnan(worst) ? "returned before" : (std::to_string(int(std::lround(worst * 1000))) + " ms").c_str());
                if (std::isnan(worst)) std::printf(" - |");
                else std::printf(" %.0f |", worst * 1000);
                if (!std::isnan(worst))
                {
                    worstAll = std::max(worstAll, worst);
                    if (isOurs(c.first)) worstOurs = std::max(worstOurs, worst);
                }
            }
        std::printf("\n");
        std::fflush(stdout);
    }
    std::printf("\nWorst lateness: gridcar's planners %.0f ms, all planners %.0f ms.\n", worstOurs * 1000, worstAll * 1000);
    return 0;
}
