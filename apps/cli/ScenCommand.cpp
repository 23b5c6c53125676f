// gridcar scen: a Moving AI scenario file against the published optimal lengths.
#include "Cli.h"

#include "gridcar/bench/MovingAi.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/planners/PlannerFactory.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace gridcar::cli
{
namespace
{
struct ScenOptions
{
    std::string map, scen;
    std::string planner{"astar-octile"};
    std::string vehicle{"point"};
    std::size_t limit{0};  ///< 0: all
    bool json{false};
};

int runScen(const ScenOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto grid = std::make_shared<const OccupancyGrid>(loadMovingAiMap(o.map));
    const auto scen = loadScenario(o.scen);
    GridSetup setup = makeGridSetup(grid, VehicleParams::fromNameOrFile(o.vehicle));
    const auto planner = makePlanner(setup.ss->getSpaceInformation(), o.planner);
    const bench::ScenarioStats st = bench::runScenarios(setup, planner, scen, o.scen, o.limit, [](std::size_t i, std::size_t n) {
        if (i % 500 == 0) std::fprintf(stderr, "[scen] %zu / %zu queries\n", i, n);
    });
    const double seconds = st.solveSeconds;
    if (o.json)
    {
        nlohmann::json j;
        j["map"] = o.map;
        j["planner"] = o.planner;
        j["queries"] = st.queries;
        j["solved"] = st.solved;
        j["matched"] = st.matched;
        j["seconds"] = seconds;
        j["queries_per_s"] = seconds > 0 ? st.queries / seconds : 0.0;
        j["expanded"] = st.expanded;
        j["expansions_per_s"] = seconds > 0 ? st.expanded / seconds : 0.0;
        printJson(j.dump());
    }
    else
        std::printf("%s with %s: %zu / %zu paths match the published optimal length (%zu solved); %.3f ms per query, "
                    "%.2f M expansions/s\n",
                    o.map.c_str(), o.planner.c_str(), st.matched, st.queries, st.solved,
                    st.queries ? 1000.0 * seconds / st.queries : 0.0, seconds > 0 ? st.expanded / seconds / 1e6 : 0.0);
    return st.matched == st.queries ? 0 : 3;
}
}  // namespace

Command addScenCommand(CLI::App &app)
{
    auto o = std::make_shared<ScenOptions>();
    auto *c = app.add_subcommand("scen", "Run a Moving AI scenario file and compare with the published optimal lengths");
    c->add_option("--map", o->map, "Moving AI .map file")->required();
    c->add_option("--scen", o->scen, "Moving AI .scen file")->required();
    c->add_option("--planner", o->planner, "Planner name")->capture_default_str();
    addVehicleOption(c, o->vehicle);
    c->add_option("--limit", o->limit, "Only the first N scenarios (0: all)")->capture_default_str();
    c->add_flag("--json", o->json, "Print one JSON object with the counts and speeds");
    c->footer("Lengths match when within max(1e-3, 1e-5 x length). Exit status: 0 all matched, 3 some did not, "
              "2 bad input.");
    return {c, [o] { return runScen(*o); }};
}

}  // namespace gridcar::cli
