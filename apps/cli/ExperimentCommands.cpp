// gridcar bench / paper-i / paper-c: the options of the benchmark harness and the papers'
// experiments, which live in benchmarks/ (the gridcar_experiments library).
#include "Cli.h"

#include "gridcar/bench/Bench.h"
#include "gridcar/bench/PaperC.h"
#include "gridcar/bench/PaperI.h"

namespace gridcar::cli
{
namespace
{
/// --out and --shared of the experiments (the Tsudanuma map is run when found under --shared).
void addOutputAndSharedOptions(CLI::App *c, std::string &out, std::string &shared)
{
    c->add_option("--out", out, "Output folder")->capture_default_str();
    c->add_option("--shared", shared, "Folder holding maps/ros/tsudanuma_campus (that map is skipped if absent)")
        ->capture_default_str();
}
}  // namespace

Command addBenchCommand(CLI::App &app)
{
    auto o = std::make_shared<bench::BenchOptions>();
    auto *c = app.add_subcommand("bench", "Benchmark the planners of a problem file with ompl::tools::Benchmark: writes the "
                                          "OMPL .log files, the SQLite database (ompl_benchmark_statistics), report.md and plots");
    c->add_option("problem", o->problem, "Problem file (YAML; see benchmarks/problems/)")->required();
    c->add_option("--out", o->outDir, "Output folder")->capture_default_str();
    c->add_option("--shared", o->sharedDir, "Folder substituted for ${shared} in the problem's map path")->capture_default_str();
    c->add_option("--shard", o->shard,
                  "K/N: run only every N-th (query, planner) unit starting at the K-th and write only .log files; merge the "
                  "shards' logs with ompl_benchmark_statistics");
    c->add_option("--time-limit", o->timeLimit, "Seconds per run (overrides the problem file)");
    c->add_option("--runs", o->runs, "Runs per planner (overrides the problem file)");
    c->add_flag("--no-database", o->noDatabase, "Write only the .log files (no database, no report)");
    c->add_option("--params-file", o->paramsFile,
                  "YAML file (planner, params, vehicle, space, time_limit): its vehicle, space and time limit replace the "
                  "problem's, its params go to the problem's planners named like its planner (all when it names none)");
    c->add_option("--report-note", o->reportNote, "A paragraph put under the report's title (e.g. a link to another report)");
    c->add_option("--report-script", o->reportScript,
                  "The report script (default: " + bench::defaultReportScript() +
                      ", the installed copy next to an installed gridcar, else the source tree's)");
    return {c, [o] { return bench::runBench(*o); }};
}

Command addPaperICommand(CLI::App &app)
{
    auto o = std::make_shared<bench::PaperIOptions>();
    auto *c = app.add_subcommand(
        "paper-i", "Reproduce paper I's tables: Dijkstra, A* Manhattan / Euclidean, improved A* (paper and integral modes) "
                   "and corner A* in three areas of the embedded campus and of the Tsudanuma map (native and resampled to "
                   "0.298 m/cell); writes paper_i_tables.md, paper_i.json and one picture per area");
    addOutputAndSharedOptions(c, o->outDir, o->sharedDir);
    addTimeLimitOption(c, o->timeLimit, "Seconds per query");
    c->add_option("--maps", o->maps, "Only these of campus, tsudanuma-0.298, tsudanuma, comma-separated (default: all found)")
        ->delimiter(',');
    c->add_flag("--skip-native", o->skipNative, "Do not run the native 0.05 m/cell Tsudanuma map (the slow part)");
    return {c, [o] { return bench::runPaperI(*o); }};
}

Command addPaperCCommand(CLI::App &app)
{
    auto o = std::make_shared<bench::PaperCOptions>();
    auto *c = app.add_subcommand(
        "paper-c", "Reproduce paper C's driving-time comparison: A* Euclidean against corner A* (paper and physics weights) "
                   "on random road pairs, driven in the simulation by paper C's robot and car, on the embedded campus and "
                   "the Tsudanuma map; plus a corner-weight sweep. Writes paper_c_tables.md and paper_c.json");
    addOutputAndSharedOptions(c, o->outDir, o->sharedDir);
    c->add_option("--pairs", o->pairs, "Start / goal pairs per map and vehicle")->capture_default_str();
    c->add_option("--seed", o->seed, "Seed of the pairs")->capture_default_str();
    addTimeLimitOption(c, o->timeLimit, "Planning time limit per query, s");
    c->add_option("--corner-mode", o->cornerMode,
                  "corner A*'s search: paper (paper C's 8-connected grid) or drivable (the car lattice; then the "
                  "driving-time planner, corner-astar cost=time, runs beside them)")
        ->check(CLI::IsMember({"paper", "drivable"}))
        ->capture_default_str();
    return {c, [o] { return bench::runPaperC(*o); }};
}

}  // namespace gridcar::cli
