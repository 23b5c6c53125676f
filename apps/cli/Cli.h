#pragma once
// The gridcar program's commands: each add*Command() registers one subcommand with its options
// and returns how to run it. Shared option groups (map, vehicle, time limit, a planning query)
// are declared once, here.
#include "gridcar/core/Errors.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/spaces/Setup.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gridcar::cli
{
/// A registered subcommand and what runs it (returns the exit status).
struct Command
{
    CLI::App *app;
    std::function<int()> run;
};

Command addInfoCommand(CLI::App &app);
Command addGenmapCommand(CLI::App &app);
Command addDemoCommand(CLI::App &app);
Command addVehicleCommand(CLI::App &app);
Command addPlanCommand(CLI::App &app);
Command addPlannersCommand(CLI::App &app);
Command addScenCommand(CLI::App &app);
Command addDriveCommand(CLI::App &app);
Command addNavigateCommand(CLI::App &app);
Command addBenchCommand(CLI::App &app);
Command addPaperICommand(CLI::App &app);
Command addPaperCCommand(CLI::App &app);

// ------------------------------------------------------------------ shared option groups
/// `--map FILE` (required) in any of the formats the readers take.
void addMapOption(CLI::App *cmd, std::string &map);
/// The map of a --map argument: 'embedded' (when no file has that name) is the embedded campus;
/// a plain image whose ROS .yaml sits beside it is read as the image, with a warning naming the
/// .yaml (the image alone has no resolution, origin or thresholds).
OccupancyGrid loadMapArgument(const std::string &map);
/// `--vehicle NAME|FILE` (default paper-i).
void addVehicleOption(CLI::App *cmd, std::string &vehicle);
/// `--time-limit S`.
void addTimeLimitOption(CLI::App *cmd, double &seconds, const std::string &what);

/// A planning query as `plan` and `drive` take it.
struct QueryArgs
{
    std::string map;
    bool unknownFree{false};
    std::string planner;
    std::string start, startCell, goal, goalCell;
    std::string goalTolerance;    ///< --goal-tolerance XY[,YAW]
    std::string vehicle{"paper-i"};
    std::vector<std::string> params;
    double timeLimit{10.0};
    bool smooth{false};
    std::string space{"se2"};
    std::string rowOrder{"top"};  ///< --row-order: top (image rows) or bottom (ROS's data order)
    std::string paramsFile;       ///< --params-file: planner, params, vehicle, space, time limit
    const CLI::App *cmd{nullptr};  ///< the command, to tell options given from defaults
};
/// --map, --unknown-free, --planner (required or not), --start / --start-cell, --goal /
/// --goal-cell, --vehicle, --param, --time-limit, --smooth, --space.
void addQueryOptions(CLI::App *cmd, QueryArgs &q, bool plannerRequired);
/// Merges --params-file into @p q: the file's planner, vehicle, space and time limit where the
/// command line gave none, its params unless --param sets the same name.
/// Then, with @p plannerRequired, InputError when neither named a planner.
void applyParamsFile(QueryArgs &q, bool plannerRequired);

/// A query made concrete: the map, the vehicle, the setup and the poses.
struct Query
{
    std::shared_ptr<OccupancyGrid> grid;
    VehicleParams vehicle;
    GridSetup setup;
    Pose2 start, goal;
    bool startYaw{false};  ///< the start's yaw was given (else: free start heading)
    bool goalYaw{false};   ///< the goal's yaw was given
    GoalTolerance goalTolerance;  ///< --goal-tolerance (default exact)
};
/// Loads the map and the vehicle, reads start and goal (with @p withPoses; InputError on
/// malformed ones) and builds the setup. A start or goal without a yaw gets the first yaw (5
/// degrees apart from 0) at which the vehicle fits there, so that the OMPL state is valid; the
/// grid planners then choose the heading themselves.
Query loadQuery(const QueryArgs &q, bool withPoses);
/// "" if the vehicle fits at @p p (at any heading with @p anyHeading), else why not ("outside
/// the map", "in collision for vehicle X", "... at every heading").
std::string whyInvalid(const Query &query, const Pose2 &p, bool anyHeading = false);
/// The planner of the query: configurePlanner() with the free start heading when no start yaw
/// was given, the --param settings and --smooth.
ompl::base::PlannerPtr queryPlanner(const QueryArgs &q, const Query &query);

// ------------------------------------------------------------------ parsing helpers
/// "A,B[,C]" -> numbers; throws InputError naming the option.
std::vector<double> parseNumbers(const std::string &text, const std::string &option, std::size_t minN, std::size_t maxN);
/// --goal-tolerance XY[,YAW] (YAW in degrees or with its unit: deg, rad); InputError when malformed or out of range.
GoalTolerance parseGoalTolerance(const std::string &text);
/// A pose from --X (world X,Y[,YAW]) or --X-cell (COL,ROW[,HEADING]); exactly one must be given. The
/// yaw is in degrees unless it ends in its unit (90deg, 1.5708rad).
/// @p rowsFromBottom: ROW counts from the map origin's row (ROS's order), else from the image's top.
Pose2 parsePose(const std::string &world, const std::string &cell, const std::string &which, const OccupancyGrid &g,
                bool &hasYaw, bool rowsFromBottom = false);
/// The scenario file of --scenario ("": none); MapLoadError naming the file and the obstacle
/// when a waypoint lies outside @p g.
Scenario loadScenarioOnMap(const std::string &file, const OccupancyGrid &g);
/// The trajectory CSV of --out: t (s), x, y (m), yaw_rad, v (m/s), steer_rad; InputError when
/// the file cannot be written.
void writeTrajectoryCsv(const std::string &file, const std::vector<TrajectorySample> &trajectory);
/// "(x, y, yaw deg)".
std::string describe(const Pose2 &p);
/// Writes @p text (one JSON object) and a newline to stdout and notes it: with --json, main()
/// prints an error as a JSON object of its own only when the command has printed none.
void printJson(const std::string &text);
/// True once printJson() has run.
bool jsonPrinted();
/// Creates a folder (and its parents); InputError saying why not.
void ensureDir(const std::string &dir);

}  // namespace gridcar::cli
