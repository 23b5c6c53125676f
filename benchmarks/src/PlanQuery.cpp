#include "gridcar/bench/PlanQuery.h"

#include "gridcar/core/Cusps.h"

#include "gridcar/core/Errors.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/CurveSpaces.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>

namespace gridcar
{
PlannerParams parsePlannerParams(const std::vector<std::string> &settings)
{
    PlannerParams out;
    for (const auto &kv : settings)
    {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0) throw InputError("--param '" + kv + "': expected NAME=VALUE");
        out.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    }
    return out;
}

namespace
{
void applyParam(ompl::base::Planner &planner, const std::string &name, const std::string &value)
{
    if (!planner.params().hasParam(name))
    {
        std::vector<std::string> names;
        planner.params().getParamNames(names);
        std::string list;
        for (const auto &n : names) list += (list.empty() ? "" : ", ") + n;
        throw InputError("planner " + planner.getName() + " has no parameter '" + name + "' (its parameters: " + list + ")");
    }
    // the setters throw std::invalid_argument, which OMPL's setParam() turns into false
    if (!planner.params().setParam(name, value))
        throw InputError("planner " + planner.getName() + ": parameter " + name + "=" + value +
                         " not accepted (see the planner's documentation for the values it takes)");
}

bool smoothsItself(const ompl::base::Planner &planner)
{
    if (!dynamic_cast<const SmoothingReport *>(&planner)) return false;
    return !planner.params().hasParam("smooth") || planner.params().getParam("smooth")->getValue() == "1";
}
}  // namespace

ompl::base::PlannerPtr configurePlanner(const ompl::base::SpaceInformationPtr &si, const PlannerConfig &config)
{
    ompl::base::PlannerPtr planner = makePlanner(si, config.name);
    if (config.freeStartHeading && planner->params().hasParam("free_start_heading"))
        planner->params().setParam("free_start_heading", "1");
    for (const auto &kv : config.params) applyParam(*planner, kv.first, kv.second);
    if (config.smooth && !smoothsItself(*planner)) planner = std::make_shared<SmoothedPlanner>(planner);
    return planner;
}

std::vector<NamedConfiguration> everyConfiguration()
{
    std::vector<NamedConfiguration> out;
    for (const auto &n : plannerNames()) out.push_back({n, {}});
    out.push_back({"improved-astar-grid", {{"mode", "integral"}}});
    for (const char *n : {"astar-octile+smooth", "rrtconnect+smooth", "rrtconnect+simplify"}) out.push_back({n, {}});
    return out;
}

std::string configurationLabel(const NamedConfiguration &c)
{
    std::string s = c.first;
    for (const auto &kv : c.second) s += " " + kv.first + "=" + kv.second;
    return s;
}

double progressValue(const ompl::base::Planner &planner, const std::string &property)
{
    const auto &props = planner.getPlannerProgressProperties();
    const auto it = props.find(property);
    return it == props.end() ? 0.0 : std::strtod(it->second().c_str(), nullptr);
}


std::vector<Pose2> solutionPoses(const GridSetup &setup, const ompl::base::Planner &planner)
{
    ompl::geometric::PathGeometric path = setup.ss->getSolutionPath();
    // on Dubins / Reeds-Shepp, an OMPL planner's consecutive states are joined by the space's
    // curves: the poses along them, at most the validity resolution apart (grid planners'
    // paths are their own poses: dense car-lattice curves, or the papers' grid polylines)
    const auto *wrapper = dynamic_cast<const SmoothedPlanner *>(&planner);
    const bool ours = dynamic_cast<const GridPlanner *>(&planner) ||
                      (wrapper && wrapper->method() == SmoothedPlanner::Method::PaperI);
    if (setup.kind == SpaceKind::SE2 || ours) return toPoses(path);
    const auto &space = setup.ss->getStateSpace();
    if (carSpaceTurningRadius(*space) > 0) return carSpacePoses(*space, path, space->getLongestValidSegmentLength());
    path.interpolate();
    return toPoses(path);
}

QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit, bool freeGoalHeading)
{
    using Clock = std::chrono::steady_clock;
    QueryResult q;
    setup.ss->clear();
    setup.setStartAndGoal(start, goal, freeGoalHeading);
    setup.ss->setPlanner(planner);
    const auto t0 = Clock::now();
    q.status = setup.ss->solve(timeLimit);
    q.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (setup.ss->haveSolutionPath()) q.path = solutionPoses(setup, *planner);
    q.rawPath = q.path;
    q.expanded = std::uint64_t(progressValue(*planner, "expanded nodes INTEGER"));
    // a path may reverse on a Reeds-Shepp space, or on any space where the car lattice reverses
    const bool reversing = setup.reversing() || drivesBackwards(q.path);
    q.metrics = computePathMetrics(q.path, setup.checker.get(), TurnParams(), reversing);
    q.maxTurnDeg = q.metrics.maxTurnDeg;
    const auto *report = dynamic_cast<const SmoothingReport *>(planner.get());
    if (report && !report->lastSmoothing().path.empty())
    {
        const SmoothingResult &sm = report->lastSmoothing();
        q.rawPath = report->lastRawPath();
        q.smoothed = true;
        q.smoothingSeconds = sm.seconds;
        q.adjustFailures = sm.adjustFailures;
        q.bezierFallbacks = sm.bezierFallbacks;
        q.maxTurnDeg = 0.0;
        for (const CornerReport &c : sm.corners) q.maxTurnDeg = std::max(q.maxTurnDeg, c.turnDeg);
    }
    const bool searchCost = planner->getPlannerProgressProperties().count("search cost REAL") > 0;
    q.cost = searchCost ? progressValue(*planner, "search cost REAL") : q.metrics.length;
    const GridPlanner *grid = dynamic_cast<const GridPlanner *>(planner.get());
    if (const auto *w = dynamic_cast<const SmoothedPlanner *>(planner.get()))
        grid = dynamic_cast<const GridPlanner *>(w->inner().get());
    if (grid) q.notExactBecause = grid->lastStopReason();
    if (report && !report->lastSmoothing().notDrivable.empty())
        q.notExactBecause = "the smoothed path is not drivable: " + report->lastSmoothing().notDrivable;
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

}  // namespace gridcar
