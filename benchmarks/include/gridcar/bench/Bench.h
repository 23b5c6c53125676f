#pragma once
/// @file Bench.h
/// @brief `gridcar bench`: ompl::tools::Benchmark of the planners of a problem file, then the
/// SQLite database (ompl_benchmark_statistics), report.md and plots (scripts/bench_report.py).

#include <string>

namespace gridcar::bench
{
struct BenchOptions
{
    std::string problem;
    std::string outDir{"bench-out"};
    std::string sharedDir{"../shared"};
    std::string shard;          ///< "K/N" or empty
    double timeLimit{0.0};      ///< > 0 overrides the problem file's
    unsigned runs{0};           ///< > 0 overrides the problem file's
    bool noDatabase{false};     ///< only the .log files
    std::string reportScript;   ///< empty: defaultReportScript()
    std::string reportNote;     ///< a paragraph under the report's title
    /// --params-file: its vehicle, space and time limit replace the problem's (--time-limit
    /// still wins); its params go to the problem's planners named like its planner (all of them
    /// when it names none).
    std::string paramsFile;
};

/// Benchmark of one problem file (progress on stderr); 0 also when the problem's shared map is
/// absent (skipped with a message). InputError for a bad problem file or option.
int runBench(const BenchOptions &o);

/// The report script `bench` runs unless told otherwise: the installed copy next to an
/// installed gridcar (BINDIR/../share/gridcar/bench_report.py) if there is one, else the
/// source tree's scripts/bench_report.py.
std::string defaultReportScript();

}  // namespace gridcar::bench
