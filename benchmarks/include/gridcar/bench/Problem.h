#pragma once
/// @file Problem.h
/// @brief Problem files of `gridcar bench` (see docs/benchmark.md): a map, a vehicle, an
/// objective, queries and the planners to race.

#include "gridcar/core/Errors.h"
#include "gridcar/core/Pose2.h"
#include "gridcar/map/OccupancyGrid.h"
#include "gridcar/spaces/CarSpaces.h"

#include <yaml-cpp/yaml.h>

#include <string>
#include <utility>
#include <vector>

namespace gridcar::bench
{
struct PlannerSpec
{
    std::string name, label;
    std::vector<std::pair<std::string, std::string>> params;
};

struct Problem
{
    std::string file, name, map, vehicle{"paper-i"}, objective{"length"};
    bool unknownFree{false};
    double delta{1.0};
    double resample{0.0};  ///< > 0: resample the map to this many metres per cell
    double timeLimit{5.0};
    /// `time_limits: [1, 5, 10]`: every query is benchmarked once per limit (one experiment
    /// per limit, all named NAME-qK, the limit their time_limit parameter; logs NAME-qK-tTs.log);
    /// empty: `time_limit` alone.
    std::vector<double> timeLimits;
    /// `space: se2 | dubins | reeds-shepp` (makeGridSetup's SetupOptions::space).
    SpaceKind space{SpaceKind::SE2};
    double memoryMb{4096.0};
    unsigned runs{3};
    /// `row_order: top | bottom`: which image row `start_cell` / `goal_cell` count from; top
    /// (default): row 0 is the image's first row; bottom: row 0 is the map origin's row, as ROS
    /// counts an OccupancyGrid's data.
    bool rowsFromBottom{false};
    std::vector<YAML::Node> queries;
    std::vector<PlannerSpec> planners;
};

/// Throws InputError "<problem file>: <why>".
[[noreturn]] void bad(const Problem &p, const std::string &why);

/// Reads and checks a problem file. A map under `${shared}` (replaced by @p sharedDir) that does
/// not exist sets @p skip and @p skipWhy instead of failing. InputError on anything else wrong.
Problem readProblem(const std::string &file, const std::string &sharedDir, bool &skip, std::string &skipWhy);

/// The pose @p key (`start` / `goal`: [x, y(, yaw_deg)]) or `<key>_cell` ([col, row(, deg)]) of
/// query @p index; @p hasYaw tells whether a yaw was given. InputError naming the query.
Pose2 readPose(const Problem &p, const YAML::Node &q, const std::string &key, const OccupancyGrid &g, bool &hasYaw,
               std::size_t index);

/// "K/N" (1 <= K <= N) or empty (1/1); false when malformed.
bool parseShard(const std::string &s, unsigned &k, unsigned &n);

}  // namespace gridcar::bench
