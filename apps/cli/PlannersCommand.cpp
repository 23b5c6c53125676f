// gridcar planners: every planner and every parameter it declares, with its default, what it
// accepts and what it does.
#include "Cli.h"

#include "gridcar/planners/ParameterHelp.h"
#include "gridcar/planners/PlannerFactory.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <map>

namespace gridcar::cli
{
namespace
{
struct PlannersOptions
{
    std::string planner;
    bool json{false};
};

int runPlanners(const PlannersOptions &o)
{
    // (reading some of OMPL's parameters warns that they no longer act: the list says what they are)
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    std::vector<std::string> names = plannerNames();
    if (!o.planner.empty())
    {
        if (!isPlannerName(o.planner))
        {
            const std::string near = suggestPlanner(o.planner);
            throw InputError("--planner '" + o.planner + "': unknown planner" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                             "; gridcar planners lists them all");
        }
        names = {o.planner};
    }
    // a planner's parameters and defaults do not depend on the map: a small open one
    auto grid = std::make_shared<OccupancyGrid>(40, 40, 0.5, CellState::Free);
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset("paper-i"));
    nlohmann::json all = nlohmann::json::object();
    for (const std::string &name : names)
    {
        const ompl::base::PlannerPtr p = makePlanner(setup.ss->getSpaceInformation(), name);
        std::map<std::string, std::string> values;
        p->params().getParams(values);
        nlohmann::json list = nlohmann::json::array();
        if (!o.json) std::printf("%s%s\n", name.c_str(), values.empty() ? " (no parameters)" : "");
        for (const auto &[param, value] : values)
        {
            const std::string range = p->params().getParam(param)->getRangeSuggestion();
            const std::string help = parameterHelp(param);
            const std::string type = parameterType(range);
            list.push_back({{"name", param}, {"default", value}, {"type", type}, {"sweep_range", range}, {"help", help}});
            if (!o.json)
                std::printf("  %-26s default %-10s %-12s %s%s%s\n", param.c_str(), value.empty() ? "(unset)" : value.c_str(),
                            type.c_str(), help.c_str(), range.empty() ? "" : type == "choice" ? "; one of " : "; Benchmark sweeps ",
                            range.c_str());
        }
        all[name] = list;
    }
    if (o.json) printJson(all.dump());
    return 0;
}
}  // namespace

Command addPlannersCommand(CLI::App &app)
{
    auto o = std::make_shared<PlannersOptions>();
    auto *c = app.add_subcommand("planners", "List every planner and every parameter it declares: default, type, what it does (with its unit) and the range OMPL's Benchmark would sweep");
    c->add_option("--planner", o->planner, "Only this planner");
    c->add_flag("--json", o->json, "Print one JSON object: {planner: [{name, default, type (flag, choice, number, whole number, text), sweep_range, help}, ...]}");
    c->footer("Set a parameter with plan --param NAME=VALUE (or params: in --params-file); an OMPL application "
              "sets it with planner->params().setParam(NAME, VALUE). The sweep ranges are OMPL's range suggestions "
              "(LOW:STEP:HIGH for numbers, the words a switch or a choice takes): what a benchmark would try, not "
              "limits; a value the planner refuses is an error (exit 2) that says what it takes.");
    return {c, [o] { return runPlanners(*o); }};
}

}  // namespace gridcar::cli
