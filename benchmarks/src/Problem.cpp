#include "gridcar/bench/Problem.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Files.h"

#include <cmath>
#include <filesystem>
#include <set>

namespace gridcar::bench
{
namespace fs = std::filesystem;

void bad(const Problem &p, const std::string &why) { throw InputError(p.file + ": " + why); }

namespace
{
/// The `planners` list: names, or {name, label?, params?} with unique labels.
void readPlanners(Problem &p, const YAML::Node &list)
{
    std::set<std::string> labels;
    for (const auto &n : list)
    {
        PlannerSpec s;
        if (n.IsScalar())
            s.name = n.as<std::string>();
        else
        {
            if (!n["name"]) bad(p, "a planner entry has no 'name'");
            s.name = n["name"].as<std::string>();
            if (n["params"])
                for (const auto &kv : n["params"]) s.params.push_back({kv.first.as<std::string>(), kv.second.as<std::string>()});
            if (n["label"]) s.label = n["label"].as<std::string>();
        }
        if (s.label.empty()) s.label = s.name;
        if (!labels.insert(s.label).second) bad(p, "two planners are labelled '" + s.label + "': give one a 'label'");
        p.planners.push_back(s);
    }
}
}  // namespace

Problem readProblem(const std::string &file, const std::string &sharedDir, bool &skip, std::string &skipWhy)
{
    Problem p;
    p.file = file;
    YAML::Node y;
    try
    {
        requireReadableFile(file, "problem file");
    }
    catch (const MapLoadError &e)
    {
        throw InputError(e.what());
    }
    try
    {
        y = YAML::LoadFile(file);
    }
    catch (const YAML::BadFile &)
    {
        throw InputError(file + ": cannot open the problem file");
    }
    catch (const YAML::Exception &e)
    {
        throw InputError(file + ": not valid YAML (" + std::string(e.what()) + ")");
    }
    if (!y.IsMap()) bad(p, "expected a mapping with map, queries and planners");
    try
    {
        p.name = y["name"] ? y["name"].as<std::string>() : fs::path(file).stem().string();
        if (!y["map"]) bad(p, "no 'map' (a map file, or 'embedded' for the generated campus)");
        p.map = y["map"].as<std::string>();
        const std::string tag = "${shared}";
        bool shared = false;
        if (auto pos = p.map.find(tag); pos != std::string::npos)
        {
            // --shared is relative to the working directory, not to the problem file
            p.map.replace(pos, tag.size(), fs::absolute(sharedDir).lexically_normal().string());
            shared = true;
        }
        if (p.map != "embedded")
        {
            if (fs::path(p.map).is_relative()) p.map = (fs::path(file).parent_path() / p.map).string();
            std::error_code ec;  // a name the file system refuses (too long, ...) is a map that is not there
            if (!fs::exists(p.map, ec))
            {
                if (shared)
                {
                    skip = true;
                    skipWhy = p.map + " not found (the shared data folder is " + sharedDir + ")";
                    return p;
                }
                bad(p, "map file " + p.map + (ec ? " cannot be looked up (" + ec.message() + ")" : " does not exist"));
            }
        }
        if (y["vehicle"]) p.vehicle = y["vehicle"].as<std::string>();
        if (y["objective"]) p.objective = y["objective"].as<std::string>();
        if (y["delta"]) p.delta = y["delta"].as<double>();
        if (y["unknown_free"]) p.unknownFree = y["unknown_free"].as<bool>();
        if (y["resample"]) p.resample = y["resample"].as<double>();
        if (y["time_limit"] && y["time_limits"]) bad(p, "give either 'time_limit' or 'time_limits', not both");
        if (y["time_limit"]) p.timeLimit = y["time_limit"].as<double>();
        if (y["time_limits"])
        {
            if (!y["time_limits"].IsSequence() || y["time_limits"].size() == 0)
                bad(p, "'time_limits' must be a non-empty list of seconds, e.g. [1, 5, 10]");
            for (const auto &t : y["time_limits"]) p.timeLimits.push_back(t.as<double>());
            p.timeLimit = p.timeLimits.front();
        }
        if (y["space"])
        {
            try
            {
                p.space = parseSpaceKind(y["space"].as<std::string>());
            }
            catch (const std::invalid_argument &e)
            {
                bad(p, e.what());
            }
        }
        if (y["memory_limit_mb"]) p.memoryMb = y["memory_limit_mb"].as<double>();
        if (y["runs"]) p.runs = y["runs"].as<unsigned>();
        if (y["row_order"])
        {
            const std::string ro = y["row_order"].as<std::string>();
            if (ro != "top" && ro != "bottom") bad(p, "row_order must be top or bottom, got '" + ro + "'");
            p.rowsFromBottom = ro == "bottom";
        }
        if (!y["queries"] || !y["queries"].IsSequence() || y["queries"].size() == 0)
            bad(p, "'queries' must be a non-empty list of {start | start_cell, goal | goal_cell}");
        for (const auto &q : y["queries"])
        {
            if (!q.IsMap())
                bad(p, "query " + std::to_string(p.queries.size() + 1) + ": must be a map {start | start_cell, goal | goal_cell}");
            p.queries.push_back(q);
        }
        if (!y["planners"] || !y["planners"].IsSequence() || y["planners"].size() == 0)
            bad(p, "'planners' must be a non-empty list of {name, label?, params?}");
        readPlanners(p, y["planners"]);
    }
    catch (const YAML::Exception &e)
    {
        bad(p, std::string("bad value (") + e.what() + ")");
    }
    if (!(p.timeLimit > 0) || !std::isfinite(p.timeLimit) || p.timeLimit > 86400) bad(p, "time_limit must be in (0, 86400] s");
    for (double t : p.timeLimits)
        if (!(t > 0) || !std::isfinite(t) || t > 86400) bad(p, "every time_limits entry must be in (0, 86400] s");
    if (p.runs == 0 || p.runs > 100000) bad(p, "runs must be in 1..100000");
    if (!(p.memoryMb > 0)) bad(p, "memory_limit_mb must be positive");
    if (p.resample < 0 || !std::isfinite(p.resample) || (p.resample > 0 && p.resample < 1e-3))
        bad(p, "resample must be a cell size in metres (>= 0.001)");
    return p;
}

Pose2 readPose(const Problem &p, const YAML::Node &q, const std::string &key, const OccupancyGrid &g, bool &hasYaw,
               std::size_t index)
{
    const std::string where = "query " + std::to_string(index + 1) + ": ";
    if (!q.IsMap()) bad(p, where + "must be a map {start | start_cell, goal | goal_cell}");
    const bool world = bool(q[key]), cell = bool(q[key + "_cell"]);
    if (world == cell) bad(p, where + "give exactly one of " + key + ": [x, y(, yaw_deg)] and " + key + "_cell: [col, row(, deg)]");
    const YAML::Node v = world ? q[key] : q[key + "_cell"];
    if (!v.IsSequence() || v.size() < 2 || v.size() > 3) bad(p, where + key + " must be a list of 2 or 3 numbers");
    double a, b, yaw = 0;
    try
    {
        a = v[0].as<double>();
        b = v[1].as<double>();
        if (v.size() == 3) yaw = v[2].as<double>() * M_PI / 180.0;
    }
    catch (const YAML::Exception &)
    {
        bad(p, where + key + " must hold numbers");
    }
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(yaw)) bad(p, where + key + " must be finite");
    hasYaw = v.size() == 3;
    if (cell)
    {
        // compared as doubles first: a cell index beyond int's range must not reach the cast
        if (a != std::floor(a) || b != std::floor(b) || a < 0 || b < 0 || a >= g.width() || b >= g.height())
            bad(p, where + key + "_cell [" + std::to_string(a) + ", " + std::to_string(b) + "] is not a cell of the " +
                       std::to_string(g.width()) + " x " + std::to_string(g.height()) + " map");
        const int row = p.rowsFromBottom ? g.height() - 1 - int(b) : int(b);
        return {g.cellCenterX(int(a)), g.cellCenterY(row), wrapYaw(yaw)};
    }
    return {a, b, wrapYaw(yaw)};
}

bool parseShard(const std::string &s, unsigned &k, unsigned &n)
{
    k = 1;
    n = 1;
    if (s.empty()) return true;
    const auto slash = s.find('/');
    if (slash == std::string::npos) return false;
    try
    {
        std::size_t u1 = 0, u2 = 0;
        k = unsigned(std::stoul(s.substr(0, slash), &u1));
        n = unsigned(std::stoul(s.substr(slash + 1), &u2));
        if (u1 != slash || u2 != s.size() - slash - 1) return false;
    }
    catch (const std::exception &)
    {
        return false;
    }
    return n >= 1 && k >= 1 && k <= n;
}

}  // namespace gridcar::bench
