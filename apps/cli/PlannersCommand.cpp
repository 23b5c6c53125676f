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
            list.push_back({{"name", param}, {"default", value}, {"accepts", range}, {"help", help}});
            if (!o.json)
                std::printf("  %-26s default %-10s %s%s%s\n", param.c_str(), value.empty() ? "(unset)" : value.c_str(), help.c_str(),
                            range.empty() ? "" : "; range ", range.c_str());
        }
        all[name] = list;
    }
    if (o.json) std::cout << all.dump() << "\n";
    return 0;
}
}  // namespace

Command addPlannersCommand(CLI::App &app)
{
    auto o = std::make_shared<PlannersOptions>();
    auto *c = app.add_subcommand("planners", "List every planner and every parameter it declares: default, range, what it does");
    c->add_option("--planner", o->planner, "Only this planner");
    c->add_flag("--json", o->json, "Print one JSON object: {planner: [{name, default, accepts, help}, ...]}");
    c->footer("Set a parameter with plan --param NAME=VALUE (or params: in --params-file); an OMPL application "
              "sets it with planner->params().setParam(NAME, VALUE). Ranges are OMPL's range suggestions: "
              "LOW:STEP:HIGH for numbers, the words a switch or a choice takes.");
    return {c, [o] { return runPlanners(*o); }};
}

}  // namespace gridcar::cli
