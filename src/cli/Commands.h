#pragma once
// Subcommands of the gridcar program. Each returns the process exit status and throws
// gridcar::InputError (exit 2) for bad input.
#include <stdexcept>
#include <string>
#include <vector>

namespace gridcar::cli
{
/// Bad input from the user (file, argument): reported on one line, exit status 2.
class InputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

struct InfoOptions
{
    std::string map;
    bool json{false};
    bool unknownFree{false};
};
int runInfo(const InfoOptions &o);

struct GenmapOptions
{
    std::string out{"campus.yaml"};
    std::string format{"pgm"};
    std::string png;
    unsigned long long seed{1};
    int width{4846};
    int height{2816};
    double resolution{0.298};
};
int runGenmap(const GenmapOptions &o);

struct DemoOptions
{
    std::string map;  ///< empty: the embedded campus map
    std::string outDir{"gridcar-out"};
    std::string vehicle{"paper-i"};
};
int runDemo(const DemoOptions &o);

struct VehicleOptions
{
    std::string vehicle{"paper-i"};
    double scale{1.0};
    bool json{false};
};
/// Prints a vehicle's parameters, what follows from them (K_max, R_min, corner speeds) and the
/// corner A* weights (paper and physics).
int runVehicle(const VehicleOptions &o);

}  // namespace gridcar::cli

namespace gridcar::cli
{
struct PlanOptions
{
    std::string map;
    std::string planner;
    std::string start, startCell, goal, goalCell;
    std::string vehicle{"paper-i"};
    std::vector<std::string> params;
    double timeLimit{10.0};
    bool json{false};
    bool unknownFree{false};
    std::string outCsv;
    std::string png;
    bool smooth{false};
};
/// Exit status: 0 exact solution, 3 planned without an exact solution (timeout / approximate).
int runPlan(const PlanOptions &o);

struct ScenOptions
{
    std::string map, scen;
    std::string planner{"astar-octile"};
    std::string vehicle{"point"};
    std::size_t limit{0};  ///< 0: all
    bool json{false};
};
struct DriveOptions
{
    PlanOptions plan;          ///< map, planner, start / goal, vehicle, params, time limit, smooth
    std::string pathCsv;       ///< drive this path (x,y[,yaw] CSV) instead of planning
    std::string scenario;      ///< moving obstacles (YAML)
    double dt{0.05};
    double xi{1.0}, eta{0.6}, rho0{1.5};  ///< potential-field gains (FollowerParams)
    bool json{false};
    std::string png;
    std::string trajectoryCsv;
};
/// Exit status: 0 reached, 3 collided / stuck / timeout (or no plan), 2 bad input.
int runDrive(const DriveOptions &o);

struct PaperCOptions
{
    std::string outDir{"paper-c-out"};
    std::string sharedDir{"../shared"};
    int pairs{20};
    unsigned long long seed{1};
    double timeLimit{20.0};
};
/// Paper C's driving-time comparison: plain A* against corner-weighted A*, driven in the
/// simulation, on the embedded campus and the Tsudanuma map; and a corner-weight sweep.
int runPaperC(const PaperCOptions &o);

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
};
/// Benchmark of one problem file; exit 0 also when the problem's shared map is absent (skipped).
int runBench(const BenchOptions &o);
/// The report script `bench` runs unless told otherwise: the installed copy next to an
/// installed gridcar (BINDIR/../share/gridcar/bench_report.py) if there is one, else the
/// source tree's scripts/bench_report.py.
std::string defaultReportScript();

struct PaperIOptions
{
    std::string outDir{"paper-i-out"};
    std::string sharedDir{"../shared"};
    double timeLimit{60.0};
    bool skipNative{false};
    std::vector<std::string> maps;  ///< empty: all
};
/// Paper I's tables on the embedded campus and the Tsudanuma map (when found under sharedDir).
int runPaperI(const PaperIOptions &o);

/// Exit status: 0 every path matched the published optimal length, 3 otherwise.
int runScen(const ScenOptions &o);
}  // namespace gridcar::cli
