// ompl::tools::Benchmark whose logs read well in Planner Arena.
#include "ArenaBenchmark.h"

#include <ompl/config.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

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
    // a progress property is kept only where some sample of some run has a finite value (an
    // anytime planner's best cost stays infinite until its first solution), and a planner's
    // progress only if something besides the time is left: no column, no plot, without data
    const auto filled = [](const std::string &v) {
        char *end = nullptr;
        const double d = std::strtod(v.c_str(), &end);
        return end != v.c_str() && std::isfinite(d);
    };
    for (auto &pe : exp_.planners)
    {
        std::vector<std::string> keep;
        for (const std::string &name : pe.progressPropertyNames)
        {
            bool any = false;
            for (const auto &run : pe.runsProgressData)
                for (const auto &sample : run)
                {
                    const auto it = sample.find(name);
                    any = any || (it != sample.end() && filled(it->second));
                }
            if (any || name == "time REAL") keep.push_back(name);
            else
                for (auto &run : pe.runsProgressData)
                    for (auto &sample : run) sample.erase(name);
        }
        pe.progressPropertyNames = keep;
        bool sampled = false;
        for (const auto &r : pe.runsProgressData) sampled = sampled || !r.empty();
        if (!sampled || keep.size() <= 1) pe.runsProgressData.clear();  // no progress rows, no empty plot
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
