// Runs every scenario of every Moving AI map in ../shared/maps/movingai (or the folder given as
// the first argument) with astar-octile and dijkstra on the point vehicle, checks each length
// against the published optimum, and reports queries/s and expansions/s on one core.
// Output: one table (Markdown) on stdout; progress on stderr.
#include "gridcar/bench/MovingAi.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace gridcar;
namespace fs = std::filesystem;

int main(int argc, char **argv)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const std::string dir = argc > 1 ? argv[1] : std::string(GRIDCAR_SHARED_DIR) + "/maps/movingai";
    std::vector<std::string> planners = {"astar-octile", "dijkstra"};
    if (argc > 2) planners = {argv[2]};
    if (!fs::is_directory(dir))
    {
        std::fprintf(stderr, "bench_movingai: %s does not exist (the Moving AI maps live in ../shared/maps/movingai)\n",
                     dir.c_str());
        return 2;
    }
    std::vector<fs::path> maps;
    for (const auto &f : fs::directory_iterator(dir))
        if (f.path().extension() == ".map") maps.push_back(f.path());
    std::sort(maps.begin(), maps.end());
    std::printf("| map | planner | queries | matched | ms/query | search M expansions/s | solve() M expansions/s |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    int failures = 0;
    for (const auto &planner : planners)
    {
        std::uint64_t allExp = 0;
        double allSearch = 0, allSolve = 0;
        std::size_t allQ = 0, allM = 0;
        for (const auto &m : maps)
        {
            auto grid = std::make_shared<const OccupancyGrid>(loadMovingAiMap(m.string()));
            const auto scen = loadScenario(m.string() + ".scen");
            GridSetup setup = makeGridSetup(grid, VehicleParams::preset("point"));
            auto p = makePlanner(setup.ss->getSpaceInformation(), planner);
            const bench::ScenarioStats st = bench::runScenarios(setup, p, scen, m.string() + ".scen");
            const std::uint64_t exp = st.expanded;
            const double solveSec = st.solveSeconds, searchSec = st.searchSeconds;
            const std::size_t matched = st.matched;
            failures += int(scen.size() - matched);
            std::printf("| %s | %s | %zu | %zu | %.3f | %.2f | %.2f |\n", m.filename().c_str(), planner.c_str(),
                        scen.size(), matched, 1000.0 * solveSec / scen.size(), exp / searchSec / 1e6, exp / solveSec / 1e6);
            std::fflush(stdout);
            std::fprintf(stderr, "[bench_movingai] %s %s: %zu/%zu matched\n", planner.c_str(), m.filename().c_str(), matched,
                         scen.size());
            allExp += exp;
            allSearch += searchSec;
            allSolve += solveSec;
            allQ += scen.size();
            allM += matched;
        }
        std::printf("| **all %zu maps** | %s | %zu | %zu | %.3f | %.2f | %.2f |\n", maps.size(), planner.c_str(), allQ, allM,
                    1000.0 * allSolve / allQ, allExp / allSearch / 1e6, allExp / allSolve / 1e6);
    }
    return failures == 0 ? 0 : 1;
}
