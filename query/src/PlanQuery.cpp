#include "gridcar/query/PlanQuery.h"

#include "gridcar/core/Cusps.h"

#include "gridcar/core/Errors.h"
#include "gridcar/planners/ParameterHelp.h"
#include "gridcar/planners/PlannerReport.h"
#include "gridcar/planners/Settings.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/CurveSpaces.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/PlannerData.h>
#include <ompl/util/Console.h>
#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <mutex>

namespace gridcar
{
PlannerParams parsePlannerParams(const std::vector<std::string> &settings)
{
    PlannerParams out;
    for (const auto &kv : settings)
    {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0) throw InputError("--param '" + kv + "': expected NAME=VALUE (`gridcar planners --planner NAME` lists a planner's parameters with their defaults and what they take)");
        out.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    }
    return out;
}

namespace
{
/// The last warning OMPL logged on this thread while a parameter was being set.
std::string &lastParamWarning()
{
    thread_local std::string text;
    return text;
}

/// OMPL's log while a parameter is set: the last warning kept (the reason a value was refused),
/// nothing printed. One object for the process (OMPL keeps the handler it replaces as its
/// "previous" one: it must never dangle), installed under a lock.
struct ParamWarnings : ompl::msg::OutputHandler
{
    void log(const std::string &text, ompl::msg::LogLevel level, const char *, int) override
    {
        if (level >= ompl::msg::LOG_WARN) lastParamWarning() = text;
    }
};
ParamWarnings paramWarnings;
std::mutex paramWarningsLock;

/// OMPL's own planners take whatever their setters are given (a goal bias of 7, a negative
/// rewire factor, "maybe" for a flag): a value is checked first against the kind of its range
/// suggestion: a flag (0,1) is 0, 1, true or false; a number (lo:step:hi or lo:hi) is one, whole
/// where the range is, not negative where the range is not, and at most hi where hi <= 1 (a
/// probability or a fraction).
void checkOmplValue(const ompl::base::Planner &planner, const std::string &name, const std::string &value)
{
    const std::string range = planner.params().getParam(name)->getRangeSuggestion();
    const std::string refused = "planner " + planner.getName() + ": parameter " + name + "=" + value + " not accepted: ";
    const std::string type = parameterType(range);
    if (type == "flag")
    {
        for (const char *ok : {"0", "1", "true", "false"})
            if (value == ok) return;
        throw InputError(refused + "a flag takes 0, 1, true or false");
    }
    if (type != "number" && type != "whole number") return;
    const std::size_t c1 = range.find(':'), c2 = range.rfind(':');  // (lo:hi or lo:step:hi)
    const double lo = std::strtod(range.substr(0, c1).c_str(), nullptr), hi = std::strtod(range.substr(c2 + 1).c_str(), nullptr);
    const bool whole = type == "whole number";
    char *end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(v) || (whole && v != std::floor(v)))
        throw InputError(refused + (whole ? "not a whole number" : "not a number") + " (OMPL's suggested range: " + range + ")");
    // (a suggestion's lower end is not a limit: a count or a factor below it still works)
    if ((lo >= 0 && v < 0) || (lo >= 0 && hi <= 1.0 && v > hi))
        throw InputError(refused + (hi <= 1.0 ? "outside [0, " + settings::print(hi) + "]" : "negative") +
                         " (OMPL's suggested range: " + range + ")");
}

void applyParam(ompl::base::Planner &planner, const std::string &name, const std::string &value, bool omplPlanner)
{
    if (!planner.params().hasParam(name))
    {
        std::vector<std::string> names;
        planner.params().getParamNames(names);
        std::string list;
        for (const auto &n : names) list += (list.empty() ? "" : ", ") + n;
        throw InputError("planner " + planner.getName() + " has no parameter '" + name + "' (its parameters: " + list + ")");
    }
    if (omplPlanner) checkOmplValue(planner, name, value);
    // the setters throw std::invalid_argument, which OMPL's setParam() turns into false after
    // logging the reason as a warning: the warning is caught here and becomes the message
    bool accepted = false;
    {
        const std::lock_guard<std::mutex> lock(paramWarningsLock);
        lastParamWarning().clear();
        ompl::msg::OutputHandler *previous = ompl::msg::getOutputHandler();
        const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
        ompl::msg::useOutputHandler(&paramWarnings);
        ompl::msg::setLogLevel(std::min(level, ompl::msg::LOG_WARN));
        try
        {
            accepted = planner.params().setParam(name, value);
        }
        catch (const std::exception &e)  // OMPL's own conversions throw past setParam() (a number that is not one)
        {
            lastParamWarning() = e.what();
        }
        ompl::msg::setLogLevel(level);
        ompl::msg::useOutputHandler(previous);
    }
    if (accepted) return;
    std::string why = lastParamWarning();
    const std::string prefix = "Invalid value format specified for parameter '" + name + "': ";
    if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
    // our planners' reasons name the planner, the setting and what it takes; OMPL's say little,
    // so its range suggestion (lo:step:hi, or the choices) goes with them
    const bool ours = why.rfind(planner.getName() + ":", 0) == 0;
    const std::string range = ours ? "" : planner.params().getParam(name)->getRangeSuggestion();
    throw InputError("planner " + planner.getName() + ": parameter " + name + "=" + value + " not accepted" +
                     (why.empty() ? "" : ": " + why) + (range.empty() ? "" : " (OMPL's suggested range: " + range + ")"));
}

}  // namespace

ompl::base::PlannerPtr configurePlanner(const ompl::base::SpaceInformationPtr &si, const PlannerConfig &config)
{
    PlannerParams params = config.params;
    std::string name;
    try
    {
        name = resolvePlannerAlias(config.name, params);  // the old `lattice=grid` / `mode=paper` command lines
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(e.what());
    }
    ompl::base::PlannerPtr planner = makePlanner(si, name);
    if (config.freeStartHeading && planner->params().hasParam("free_start_heading"))
        planner->params().setParam("free_start_heading", "1");
    // OMPL's planners (any case of their names, with or without a post-processing suffix) get
    // their values checked first
    std::string base = name;
    for (const std::string suffix : {"+smooth", "+simplify"})
        if (base.size() > suffix.size() && base.compare(base.size() - suffix.size(), suffix.size(), suffix) == 0)
            base.erase(base.size() - suffix.size());
    const PlannerEntry *entry = findPlanner(base);
    const bool omplPlanner = entry && !entry->ours;
    for (const auto &kv : params) applyParam(*planner, kv.first, kv.second, omplPlanner);
    if (config.smooth && !reportOf(*planner).smoothsItself) planner = std::make_shared<SmoothedPlanner>(planner);
    return planner;
}

std::vector<NamedConfiguration> everyConfiguration()
{
    std::vector<NamedConfiguration> out;
    for (const auto &n : plannerNames()) out.push_back({n, {}});
    out.push_back({"improved-astar-grid", {{"mode", "integral"}}});
    out.push_back({"improved-astar", {{"mode", "paper"}}});
    for (const char *n : {"astar-octile+smooth", "rrtconnect+smooth", "rrtconnect+simplify"}) out.push_back({n, {}});
    return out;
}

std::string configurationLabel(const NamedConfiguration &c)
{
    std::string s = c.first;
    for (const auto &kv : c.second) s += " " + kv.first + "=" + kv.second;
    return s;
}

std::vector<Pose2> solutionPoses(const GridSetup &setup, const ompl::base::Planner &planner)
{
    ompl::geometric::PathGeometric path = setup.ss->getSolutionPath();
    // on Dubins / Reeds-Shepp, an OMPL planner's consecutive states are joined by the space's
    // curves: the poses along them, at most the validity resolution apart (grid planners'
    // paths are their own poses: dense car-lattice curves, or the papers' grid polylines)
    if (setup.kind == SpaceKind::SE2 || reportOf(planner).ownPoses) return toPoses(path);
    const auto &space = setup.ss->getStateSpace();
    if (carSpaceTurningRadius(*space) > 0) return carSpacePoses(*space, path, space->getLongestValidSegmentLength());
    path.interpolate();
    return toPoses(path);
}

QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit, bool freeGoalHeading, const GoalTolerance &tolerance)
{
    using Clock = std::chrono::steady_clock;
    QueryResult q;
    setup.ss->clear();
    setup.setStartAndGoal(start, goal, freeGoalHeading, tolerance);
    setup.ss->setPlanner(planner);
    const auto t0 = Clock::now();
    q.status = setup.ss->solve(timeLimit);
    q.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (setup.ss->haveSolutionPath()) q.path = solutionPoses(setup, *planner);
    q.rawPath = q.path;
    const PlannerReport report = reportOf(*planner);
    q.expanded = report.expanded.value_or(0);
    // a path may reverse on a Reeds-Shepp space, or on any space where the car lattice reverses
    const bool reversing = setup.reversing() || drivesBackwards(q.path);
    q.metrics = computePathMetrics(q.path, setup.checker.get(), TurnParams(), reversing);
    q.maxTurnDeg = q.metrics.maxTurnDeg;
    const SmoothingResult *sm = report.smoothing;
    if (sm && !sm->path.empty())
    {
        q.rawPath = report.rawPath;
        q.smoothed = true;
        q.smoothingSeconds = sm->seconds;
        q.adjustFailures = sm->adjustFailures;
        q.bezierFallbacks = sm->bezierFallbacks;
        q.maxTurnDeg = 0.0;
        for (const CornerReport &c : sm->corners) q.maxTurnDeg = std::max(q.maxTurnDeg, c.turnDeg);
    }
    q.cost = report.searchCost.value_or(q.metrics.length);
    q.notExactBecause = report.stopReason;
    if (sm && !sm->notDrivable.empty()) q.notExactBecause = "the smoothed path is not drivable: " + sm->notDrivable;
    DrivabilityOptions drive;
    drive.reversing = reversing;
    if (!q.path.empty()) q.drivability = checkDrivable(q.path, *setup.checker, drive);
    return q;
}

std::vector<Cell> exploredCells(const ompl::base::Planner &planner, const OccupancyGrid &grid)
{
    ompl::base::PlannerData data(planner.getSpaceInformation());
    planner.getPlannerData(data);
    std::vector<Cell> out;
    out.reserve(data.numVertices());
    for (unsigned i = 0; i < data.numVertices(); ++i)
    {
        const Pose2 p = toPose(data.getVertex(i).getState());
        out.push_back(grid.worldToCell(p.x, p.y));
    }
    return out;
}

std::string whyPoseInvalid(const FootprintChecker &fc, const OccupancyGrid &g, const Pose2 &p, bool anyHeading)
{
    if (anyHeading ? fc.fitsAtSomeHeading(p.x, p.y, 72) : fc.isValid(p)) return "";
    const Cell c = g.worldToCell(p.x, p.y);
    char buf[200];
    if (!g.inBounds(c.col, c.row))
    {
        std::snprintf(buf, sizeof buf, "outside the map, which spans x %.3f..%.3f m, y %.3f..%.3f m", g.originX(),
                      g.originX() + g.sizeX(), g.originY(), g.originY() + g.sizeY());
        return buf;
    }
    std::string why = "in collision for vehicle " + fc.vehicle().name + (anyHeading ? " at every heading (5-degree steps)" : "");
    // unknown cells under or near the body: say so, and how to count them free
    if (!g.unknownIsFree())
    {
        const int reach = int(std::ceil((fc.vehicle().circumscribedRadius() + fc.reach()) / g.resolution())) + 1;
        int unknown = 0, occupied = 0;
        for (int r = c.row - reach; r <= c.row + reach; ++r)
            for (int k = c.col - reach; k <= c.col + reach; ++k)
            {
                if (!g.inBounds(k, r)) continue;
                unknown += g.at(k, r) == CellState::Unknown;
                occupied += g.at(k, r) == CellState::Occupied;
            }
        if (g.at(c.col, c.row) == CellState::Unknown)
            why += " (the map's cell there is unknown, which counts as blocked unless the map is read with unknown cells "
                   "free: gridcar's --unknown-free; unknown_free=True of Map.load() or Map.from_array() in Python)";
        else if (unknown > 0 && occupied == 0)
            why += " (only unknown cells are near it, which count as blocked unless the map is read with unknown cells "
                   "free: gridcar's --unknown-free; unknown_free=True of Map.load() or Map.from_array() in Python)";
    }
    return why;
}

}  // namespace gridcar
