// Random obstacle fields after Nav2's planner benchmark design (navigation2's
// tools/planner_benchmarking: 100 m x 100 m maps at 0.05 m, 10 / 15 / 20 % of the cells
// occupied, 100 seeded start / goal poses with random yaws at least 3 m apart and 5 m inside the
// border). Nav2's maps are its own files; these are generated here: boxes of 0.25-1.5 m placed
// at seeded random until the share of occupied cells is reached. corner-astar and improved-astar
// with their defaults plan each pair as a goal pose; every exact path is checked independently
// (checkDrivable). Pairs the fast-failure proof shows apart are counted, not planned.
// Output: a Markdown table on stdout, progress on stderr. See docs/performance.md.
#include "gridcar/query/PlanQuery.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

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
struct Options
{
    int pairs{100};
    unsigned seed{1};
    double limit{5.0};
    std::vector<int> densities{10, 15, 20};
    std::string vehicle{"paper-c-robot"};
};

/// 2000 x 2000 cells at 0.05 m, boxes of 0.25-1.5 m until @p percent of the cells are occupied.
std::shared_ptr<OccupancyGrid> randomField(int percent, unsigned seed)
{
    constexpr int N = 2000;
    auto g = std::make_shared<OccupancyGrid>(N, N, 0.05, CellState::Free);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> at(0, N - 1), side(5, 30);
    const std::size_t want = std::size_t(N) * N * std::size_t(percent) / 100;
    std::size_t occupied = 0;
    while (occupied < want)
    {
        const int c0 = at(rng), r0 = at(rng), w = side(rng), h = side(rng);
        for (int r = r0; r < std::min(N, r0 + h); ++r)
            for (int c = c0; c < std::min(N, c0 + w); ++c)
                if (g->at(c, r) == CellState::Free)
                {
                    g->set(c, r, CellState::Occupied);
                    ++occupied;
                }
    }
    return g;
}

double quantile(std::vector<double> v, double q)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

void runDensity(const Options &o, int percent)
{
    const auto grid = randomField(percent, o.seed + unsigned(percent));
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset(o.vehicle));
    // Nav2's: random cells 5 m inside the border, yaw at random, goals at least 3 m away; here
    // also where the body fits at that pose
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> xy(5.0, 95.0), yaw(-M_PI, M_PI);
    const auto pose = [&] {
        for (;;)
        {
            const Pose2 p{xy(rng), xy(rng), yaw(rng)};
            if (setup.checker->isValid(p.x, p.y, p.yaw)) return p;
        }
    };
    std::vector<std::pair<Pose2, Pose2>> pairs;
    int apart = 0;
    while (int(pairs.size()) < o.pairs)
    {
        const Pose2 s = pose();
        Pose2 g = pose();
        while (std::hypot(g.x - s.x, g.y - s.y) <= 3.0) g = pose();
        if (setup.checker->reachability(s, false, g, false, std::size_t(1) << 22).verdict == FootprintChecker::Reach::Separated)
        {
            ++apart;
            continue;
        }
        pairs.push_back({s, g});
    }
    std::fprintf(stderr, "[fields] %d %%: %zu pairs (%d more proven apart and skipped)\n", percent, pairs.size(), apart);
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        auto planner = configurePlanner(setup.ss->getSpaceInformation(), {name, {}, false, false});
        int exact = 0, drivable = 0;
        std::vector<double> ms, length;
        double sum = 0;
        for (const auto &[s, g] : pairs)
        {
            const QueryResult r = runQuery(setup, planner, s, g, o.limit, false);
            ms.push_back(1e3 * r.seconds);
            sum += 1e3 * r.seconds;
            if (r.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
            ++exact;
            drivable += r.drivability.drivable;
            length.push_back(r.metrics.length);
        }
        double meanLength = 0;
        for (double l : length) meanLength += l / double(length.size());
        std::printf("| %d %% | %s | %d / %zu | %d | %.0f / %.0f / %.0f / %.0f | %.1f |\n", percent, name, exact, pairs.size(), drivable,
                    sum / double(ms.size()), quantile(ms, 0.5), quantile(ms, 0.95), quantile(ms, 1.0), meanLength);
        std::fflush(stdout);
        std::fprintf(stderr, "[fields]   %s done\n", name);
    }
    std::printf("| %d %% | (pairs the proof shows apart, skipped) | %d | | | |\n", percent, apart);
}
}  // namespace

int main(int argc, char **argv)
{
    Options o;
    CLI::App app{"Random obstacle fields after Nav2's planner benchmark: 100 m x 100 m at 0.05 m, 10 / 15 / 20 % occupied, "
                 "seeded goal poses, corner-astar and improved-astar with their defaults (see docs/performance.md)"};
    app.add_option("--pairs", o.pairs, "start / goal poses per density")->capture_default_str()->check(CLI::Range(1, 10000));
    app.add_option("--seed", o.seed, "random seed of the fields and the poses")->capture_default_str();
    app.add_option("--time-limit", o.limit, "solve() limit per query, s")->capture_default_str()->check(CLI::PositiveNumber);
    app.add_option("--density", o.densities, "percent of the cells occupied (repeatable)")->capture_default_str()->check(CLI::Range(1, 60));
    app.add_option("--vehicle", o.vehicle, "vehicle preset")->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ompl::RNG::setSeed(o.seed);
    std::printf("Random fields, %d goal poses per density, vehicle %s, limit %.0f s\n\n", o.pairs, o.vehicle.c_str(), o.limit);
    std::printf("| occupied | planner | exact | drivable | solve() mean / median / p95 / max (ms) | mean length (m) |\n"
                "|---|---|---|---|---|---|\n");
    for (int d : o.densities) runDensity(o, d);
    return 0;
}
