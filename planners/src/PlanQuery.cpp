#include "gridcar/planners/PlanQuery.h"

#include "gridcar/core/Errors.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"
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

double progressValue(const ompl::base::Planner &planner, const std::string &property)
{
    const auto &props = planner.getPlannerProgressProperties();
    const auto it = props.find(property);
    return it == props.end() ? 0.0 : std::strtod(it->second().c_str(), nullptr);
}

QueryResult runQuery(GridSetup &setup, const ompl::base::PlannerPtr &planner, const Pose2 &start, const Pose2 &goal,
                     double timeLimit)
{
    using Clock = std::chrono::steady_clock;
    QueryResult q;
    setup.ss->clear();
    setup.setStartAndGoal(start, goal);
    setup.ss->setPlanner(planner);
    const auto t0 = Clock::now();
    q.status = setup.ss->solve(timeLimit);
    q.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (setup.ss->haveSolutionPath()) q.path = toPoses(setup.ss->getSolutionPath());
    q.rawPath = q.path;
    q.expanded = std::uint64_t(progressValue(*planner, "expanded nodes INTEGER"));
    q.metrics = computePathMetrics(q.path, setup.checker.get());
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
    if (!q.path.empty()) q.drivability = checkDrivable(q.path, *setup.checker);
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
