// gridcar: command-line front end. Exit status: 0 ok, 2 bad input, 1 internal error; commands
// that plan or drive use 3 for "ran, but no exact solution / did not reach the goal".
#include "Cli.h"

#include "gridcar/query/PlainLog.h"
#include "gridcar/version.h"

#include <nlohmann/json.hpp>
#include <ompl/config.h>
#include <ompl/util/Exception.h>

#include <cstdio>
#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>

namespace
{
/// "gridcar 0.1.0 (OMPL 1.5.2)": OMPL's version from its headers' numbers (Debian's OMPL 1.5.2
/// sets OMPL_VERSION to "").
std::string versionText()
{
    return std::string("gridcar ") + GRIDCAR_VERSION + " (OMPL " + std::to_string(OMPL_MAJOR_VERSION) + "." +
           std::to_string(OMPL_MINOR_VERSION) + "." + std::to_string(OMPL_PATCH_VERSION) + ")";
}

/// True if --json is among the arguments: errors are then a JSON object on stdout as well.
bool jsonAsked(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (std::string_view(argv[i]) == "--json") return true;
    return false;
}

/// With @p json: {"status": "Invalid input" | "Internal error", "error": message} on stdout,
/// unless the command printed its JSON object already.
void errorJson(bool json, bool bad, const std::string &message)
{
    if (json && !gridcar::cli::jsonPrinted())
        gridcar::cli::printJson(nlohmann::json{{"status", bad ? "Invalid input" : "Internal error"}, {"error", message}}.dump());
}

/// Runs @p run and turns every error into one stderr line and an exit status (2 for a bad
/// input, 1 for an internal error), and with @p json into one JSON object on stdout too.
int guarded(const std::function<int()> &run, bool json)
{
    try
    {
        return run();
    }
    // a bad file, a bad argument or value, a bad name, size or number given to the library,
    // a problem OMPL refused
    catch (const gridcar::MapLoadError &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        errorJson(json, true, e.what());
    }
    catch (const gridcar::InputError &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        errorJson(json, true, e.what());
    }
    catch (const std::invalid_argument &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        errorJson(json, true, e.what());
    }
    catch (const ompl::Exception &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        errorJson(json, true, e.what());
    }
    catch (const std::bad_alloc &)
    {
        std::fprintf(stderr, "gridcar: internal error: out of memory\n");
        errorJson(json, false, "out of memory");
        return 1;
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "gridcar: internal error: %s\n", e.what());
        errorJson(json, false, e.what());
        return 1;
    }
    return 2;
}
}  // namespace

int main(int argc, char **argv)
{
    using namespace gridcar::cli;
    gridcar::usePlainLog();  // OMPL's log lines without their source file and line
    CLI::App app{"gridcar: vehicle-aware grid planners for OMPL (grid A* baselines, corner-weighted A*, improved A*) "
                 "and a benchmark harness against OMPL's sampling planners.\n"
                 "Maps: ROS map_server .yaml (+ PGM/PNG), Moving AI .map, plain .ppm/.pgm/.png (dark = occupied)."};
    app.require_subcommand(1);
    app.set_version_flag("--version", versionText(), "Print gridcar's version and the OMPL it is built on, and exit");
    const std::vector<Command> commands = {addInfoCommand(app),    addGenmapCommand(app), addDemoCommand(app),
                                           addVehicleCommand(app), addPlanCommand(app),   addPlannersCommand(app),   addScenCommand(app),
                                           addDriveCommand(app),   addNavigateCommand(app), addBenchCommand(app),  addPaperICommand(app),
                                           addPaperCCommand(app)};
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::CallForHelp &e)
    {
        return app.exit(e);
    }
    catch (const CLI::CallForAllHelp &e)
    {
        return app.exit(e);
    }
    catch (const CLI::CallForVersion &e)
    {
        return app.exit(e);
    }
    catch (const CLI::ParseError &e)
    {
        app.exit(e);
        errorJson(jsonAsked(argc, argv), true, e.what());
        return 2;
    }
    for (const Command &c : commands)
        if (*c.app) return guarded(c.run, jsonAsked(argc, argv));
    return 1;
}
