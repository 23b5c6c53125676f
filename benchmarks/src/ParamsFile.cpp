// --params-file: a planner, its parameters, the vehicle, the space and the time limit in YAML.
#include "gridcar/bench/ParamsFile.h"

#include "gridcar/core/Errors.h"
#include "gridcar/core/Files.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/CarSpaces.h"
#include "gridcar/spaces/Setup.h"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

namespace gridcar::bench
{
namespace
{
std::string lowerCase(std::string s)
{
    for (char &c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

[[noreturn]] void badParams(const std::string &file, const std::string &why) { throw InputError(file + ": " + why); }

std::string scalar(const std::string &file, const YAML::Node &n, const std::string &key)
{
    if (!n.IsScalar()) badParams(file, "'" + key + "' must be a single value");
    return n.Scalar();
}
}  // namespace

ParamsFile readParamsFile(const std::string &file)
{
    try
    {
        requireReadableFile(file, "parameters file");
    }
    catch (const MapLoadError &e)
    {
        throw InputError(e.what());
    }
    YAML::Node y;
    try
    {
        y = YAML::LoadFile(file);
    }
    catch (const YAML::Exception &e)
    {
        badParams(file, std::string("not valid YAML (") + e.what() + ")");
    }
    ParamsFile pf;
    pf.file = file;
    if (y.IsNull()) return pf;  // an empty file sets nothing
    if (!y.IsMap()) badParams(file, "expected a mapping with planner, params, vehicle, space, time_limit");
    static const std::set<std::string> known{"planner", "params", "vehicle", "space", "time_limit"};
    for (const auto &kv : y)
    {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
        if (!known.count(key))
            badParams(file, "unknown key '" + printable(key) + "' (known: planner, params, vehicle, space, time_limit)");
    }
    if (y["planner"])
    {
        pf.planner = scalar(file, y["planner"], "planner");
        if (!isPlannerName(pf.planner))
        {
            const std::string guess = suggestPlanner(pf.planner);
            badParams(file, "unknown planner '" + printable(pf.planner) + "'" +
                                (guess.empty() ? std::string() : "; did you mean '" + guess + "'?"));
        }
    }
    if (const YAML::Node params = y["params"])
    {
        if (!params.IsMap()) badParams(file, "'params' must be a mapping NAME: VALUE");
        for (const auto &kv : params)
        {
            if (!kv.first.IsScalar() || !kv.second.IsScalar())
                badParams(file, "params: every entry must be NAME: VALUE (single values)");
            pf.params.emplace_back(kv.first.Scalar(), kv.second.Scalar());
        }
    }
    if (y["vehicle"])
    {
        pf.vehicle = scalar(file, y["vehicle"], "vehicle");
        // a file name is relative to the parameters file; a preset name stays as it is
        const std::filesystem::path rel = std::filesystem::path(file).parent_path() / pf.vehicle;
        std::error_code ec;
        if (pf.vehicle.find('.') != std::string::npos && std::filesystem::path(pf.vehicle).is_relative() &&
            std::filesystem::exists(rel, ec))
            pf.vehicle = std::filesystem::absolute(rel).lexically_normal().string();
    }
    if (y["space"])
    {
        pf.space = scalar(file, y["space"], "space");
        try
        {
            parseSpaceKind(pf.space);
        }
        catch (const std::invalid_argument &e)
        {
            badParams(file, e.what());
        }
    }
    if (y["time_limit"])
    {
        try
        {
            pf.timeLimit = y["time_limit"].as<double>();
        }
        catch (const YAML::Exception &)
        {
            badParams(file, "time_limit must be a number of seconds");
        }
        if (!(pf.timeLimit > 0) || !std::isfinite(pf.timeLimit) || pf.timeLimit > 86400)
            badParams(file, "time_limit must be in (0, 86400] s");
    }
    return pf;
}

/// --params-file on a problem: vehicle, space and time limit replaced, params set on the
/// planners named like the file's planner (every planner when it names none).
void applyParamsFile(Problem &p, const ParamsFile &pf)
{
    if (!pf.vehicle.empty()) p.vehicle = pf.vehicle;
    if (!pf.space.empty()) p.space = parseSpaceKind(pf.space);
    if (pf.timeLimit > 0)
    {
        p.timeLimit = pf.timeLimit;
        p.timeLimits.clear();
    }
    if (pf.params.empty()) return;
    bool matched = false;
    for (PlannerSpec &s : p.planners)
    {
        if (!pf.planner.empty() && lowerCase(s.name) != lowerCase(pf.planner)) continue;
        matched = true;
        for (const auto &[name, value] : pf.params)
        {
            bool replaced = false;
            for (auto &kv : s.params)
                if (kv.first == name)
                {
                    kv.second = value;
                    replaced = true;
                }
            if (!replaced) s.params.emplace_back(name, value);
        }
    }
    if (!matched)
        throw InputError(pf.file + ": the problem " + p.file + " has no planner '" + pf.planner + "' to give the params to");
}

}  // namespace gridcar::bench
