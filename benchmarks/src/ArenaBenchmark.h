#pragma once
// ompl::tools::Benchmark whose logs read well in Planner Arena (gridcar bench's private part).
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <string>

namespace gridcar::bench
{
/// OMPL's version from its headers' numbers ("1.5.2"): Debian's OMPL 1.5.2 reports an empty
/// OMPL_VERSION, which its Benchmark writes into every log ("OMPL version " and nothing), and
/// ompl_benchmark_statistics then stores the word "version" as the version.
std::string omplVersion();

/// ompl::tools::Benchmark whose log reads well in Planner Arena: the OMPL version filled in,
/// the set-up text without the default planner SimpleSetup allocates (and never runs), and
/// progress tables only for planners whose runs lasted long enough to be sampled.
class ArenaBenchmark : public ompl::tools::Benchmark
{
public:
    using ompl::tools::Benchmark::Benchmark;

    /// After benchmark(): the set-up text and the progress data as Planner Arena should see them.
    void tidy(const ompl::geometric::SimpleSetup &ss);

    /// Writes the log to @p file with "OMPL version" followed by the version; std::runtime_error
    /// when it cannot.
    void save(const std::string &file) const;
};

}  // namespace gridcar::bench
