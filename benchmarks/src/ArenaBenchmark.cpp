// ompl::tools::Benchmark whose logs read well in Planner Arena.
#include "ArenaBenchmark.h"

#include <ompl/config.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gridcar::bench
{
std::string omplVersion()
{
    return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
           std::to_string(OMPL_PATCH_VERSION);
}

void ArenaBenchmark::tidy(const ompl::geometric::SimpleSetup &ss)
{
    std::stringstream setup;
    ss.getSpaceInformation()->printSettings(setup);
    ss.getProblemDefinition()->print(setup);
    setup << "\nProperties of benchmarked planners:\n";
    for (const auto &pl : planners_) pl->printProperties(setup);
    exp_.setupInfo = setup.str();
    for (auto &pe : exp_.planners)
    {
        bool sampled = false;
        for (const auto &r : pe.runsProgressData) sampled = sampled || !r.empty();
        if (!sampled) pe.runsProgressData.clear();  // no progress table rows, no empty plot
    }
}

void ArenaBenchmark::save(const std::string &file) const
{
    std::stringstream text;
    if (!saveResultsToStream(text)) throw std::runtime_error("cannot format the benchmark log " + file);
    std::string all = text.str();
    const std::string head = "OMPL version ";
    if (all.compare(0, head.size(), head) == 0)
    {
        const std::size_t eol = all.find('\n');
        all = head + omplVersion() + (eol == std::string::npos ? std::string("\n") : all.substr(eol));
    }
    std::ofstream out(file);
    out << all;
    if (!out) throw std::runtime_error("cannot write " + file);
}

}  // namespace gridcar::bench
