// gridcar: command-line front end. Exit status: 0 ok, 2 bad input, 1 internal error.
#include "Commands.h"

#include "gridcar/planners/PlannerFactory.h"

#include "gridcar/io/Image.h"

#include <cstdio>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#include <ompl/util/Exception.h>

int main(int argc, char **argv)
{
    using namespace gridcar::cli;
    CLI::App app{"gridcar: vehicle-aware grid planners for OMPL (grid A* baselines, corner-weighted A*, improved A*) "
                 "and a benchmark harness against OMPL's sampling planners.\n"
                 "Maps: ROS map_server .yaml (+ PGM/PNG), Moving AI .map, plain .ppm/.pgm/.png (dark = occupied)."};
    app.require_subcommand(1);

    InfoOptions info;
    auto *cInfo = app.add_subcommand("info", "Print a map's size, origin, cell counts and max clearance");
    cInfo->add_option("--map", info.map, "Map file (.yaml, .map, .ppm, .pgm, .png)")->required();
    cInfo->add_flag("--json", info.json,
                    "Print one JSON object: width, height, resolution, origin, free, occupied, unknown "
                    "(counts as read), max_clearance (m)");
    cInfo->add_flag("--unknown-free", info.unknownFree, "Treat unknown cells as free for the clearance");

    GenmapOptions gen;
    auto *cGen = app.add_subcommand("genmap", "Generate the embedded campus-like map (deterministic from --seed)");
    cGen->add_option("--out", gen.out, "Output YAML path; the image is written next to it")->capture_default_str();
    cGen->add_option("--format", gen.format, "Image format: pgm or png")->capture_default_str();
    cGen->add_option("--png", gen.png, "Also write a preview picture (PNG) to this path");
    cGen->add_option("--seed", gen.seed, "Random seed")->capture_default_str();
    cGen->add_option("--width", gen.width, "Width in cells")->capture_default_str();
    cGen->add_option("--height", gen.height, "Height in cells")->capture_default_str();
    cGen->add_option("--resolution", gen.resolution, "Metres per cell")->capture_default_str();

    DemoOptions demo;
    auto *cDemo = app.add_subcommand(
        "demo", "Load the map (default: embedded campus), build distance field, Voronoi diagram and "
                "footprint checker, print a summary and write pictures");
    cDemo->add_option("--map", demo.map, "Map file (default: the embedded campus map)");
    cDemo->add_option("--out", demo.outDir, "Output folder")->capture_default_str();
    cDemo->add_option("--vehicle", demo.vehicle, "Vehicle preset (paper-i, paper-c-car, paper-c-robot, point) or YAML file")
        ->capture_default_str();

    VehicleOptions veh;
    auto *cVeh = app.add_subcommand(
        "vehicle", "Print a vehicle's parameters, its K_max, R_min and corner speeds, and the corner-astar weights "
                   "(paper defaults and weights=physics) it implies");
    cVeh->add_option("--vehicle", veh.vehicle, "Vehicle preset (paper-i, paper-c-car, paper-c-robot, point) or YAML file")
        ->capture_default_str();
    cVeh->add_option("--scale", veh.scale,
                     "Scale the vehicle by K with the same timing: lengths, speeds and accelerations x K (paper C's "
                     "robot is its car at K = 0.6 / 30 = 0.02)")
        ->capture_default_str();
    cVeh->add_flag("--json", veh.json,
                   "Print one JSON object: the fields, max_curvature, min_turning_radius, corner_speeds, "
                   "physics_weights and paper_weights ([45, 90, 135 deg])");

    PlanOptions plan;
    auto *cPlan = app.add_subcommand("plan", "Plan one path on a map with a grid planner or an OMPL planner");
    cPlan->add_option("--map", plan.map, "Map file")->required();
    std::string plannerList;
    for (const auto &n : gridcar::plannerNames()) plannerList += (plannerList.empty() ? "" : ", ") + n;
    cPlan->add_option("--planner", plan.planner, plannerList)->required();
    cPlan->add_option("--start", plan.start, "Start X,Y[,YAW_DEG] in the world frame (m; yaw 0 = +x, CCW); no yaw: free start heading for the grid "
                                             "planners (OMPL planners start at yaw 0)");
    cPlan->add_option("--start-cell", plan.startCell, "Start COL,ROW[,HEADING_DEG] (row 0 = top image row)");
    cPlan->add_option("--goal", plan.goal, "Goal X,Y[,YAW_DEG] (the goal heading counts only with "
                                           "--param match_goal_heading=1)");
    cPlan->add_option("--goal-cell", plan.goalCell, "Goal COL,ROW[,HEADING_DEG]");
    cPlan->add_option("--vehicle", plan.vehicle, "paper-i, paper-c-car, paper-c-robot, point, or a YAML file")
        ->capture_default_str();
    cPlan->add_option("--param", plan.params, "NAME=VALUE: set a declared planner parameter (repeatable)");
    cPlan->add_option("--time-limit", plan.timeLimit, "Seconds")->capture_default_str();
    cPlan->add_flag("--json", plan.json,
                    "Print one JSON object: status, planner, cost, length, expanded, turns, max_turn_deg, max_curvature, "
                    "min_path_distance, smoothing_time, "
                    "min_clearance, time, path [[x, y, yaw_rad], ...]");
    cPlan->add_flag("--unknown-free", plan.unknownFree, "Treat unknown cells as free");
    cPlan->add_option("--out", plan.outCsv, "Write the path as CSV (x,y,yaw)");
    cPlan->add_option("--png", plan.png, "Write a picture of the map, the path (before smoothing in orange) and the "
                                         "expanded cells");
    cPlan->add_flag("--smooth", plan.smooth,
                    "Post-process any planner's path as paper I does (line of sight, turning-point adjustment under "
                    "K_max, Bezier); improved-astar does this itself unless --param smooth=0");
    cPlan->footer("Exit status: 0 exact solution, 3 no exact solution (timeout / approximate), 2 bad input "
                  "(including a start or goal off the map or in collision), 1 internal error.");

    ScenOptions scen;
    DriveOptions drive;
    auto *cDrive = app.add_subcommand(
        "drive", "Plan a path (or read one) and drive it with paper C's potential-field follower in the kinematic "
                 "bicycle simulation, with optional moving obstacles");
    cDrive->add_option("--map", drive.plan.map, "Map file")->required();
    cDrive->add_option("--planner", drive.plan.planner, plannerList + " (or NAME+smooth)");
    cDrive->add_option("--path", drive.pathCsv, "Drive this path instead of planning: CSV x,y[,yaw] (as plan --out writes)");
    cDrive->add_option("--start", drive.plan.start, "Start X,Y[,YAW_DEG] (world frame, m)");
    cDrive->add_option("--start-cell", drive.plan.startCell, "Start COL,ROW[,HEADING_DEG]");
    cDrive->add_option("--goal", drive.plan.goal, "Goal X,Y[,YAW_DEG]");
    cDrive->add_option("--goal-cell", drive.plan.goalCell, "Goal COL,ROW[,HEADING_DEG]");
    cDrive->add_option("--vehicle", drive.plan.vehicle, "paper-i, paper-c-car, paper-c-robot, point, or a YAML file")
        ->capture_default_str();
    cDrive->add_option("--param", drive.plan.params, "NAME=VALUE: a declared planner parameter (repeatable)");
    cDrive->add_option("--time-limit", drive.plan.timeLimit, "Planning time limit, s")->capture_default_str();
    cDrive->add_flag("--smooth", drive.plan.smooth, "Post-process the planned path as paper I does before driving it");
    cDrive->add_flag("--unknown-free", drive.plan.unknownFree, "Treat unknown cells as free");
    cDrive->add_option("--scenario", drive.scenario, "Moving obstacles (YAML: obstacles: [{shape, radius | size, waypoints, speed, start_time, loop}])");
    cDrive->add_option("--dt", drive.dt, "Simulation step, s")->capture_default_str();
    cDrive->add_option("--xi", drive.xi, "Attractive gain of the potential field")->capture_default_str();
    cDrive->add_option("--eta", drive.eta, "Repulsive gain of the potential field")->capture_default_str();
    cDrive->add_option("--rho0", drive.rho0, "Influence distance of obstacles, m (beyond the body's half width)")
        ->capture_default_str();
    cDrive->add_flag("--json", drive.json,
                     "Print one JSON object: outcome (reached | collided | stuck | timeout), reason, driving_time, path_length, "
                     "distance_driven, cross_track_mean, cross_track_max, min_clearance, recoveries, plan {...}");
    cDrive->add_option("--png", drive.png, "Picture of the path (blue), the trajectory (red) and the moving obstacles (orange)");
    cDrive->add_option("--out", drive.trajectoryCsv, "Trajectory CSV: t,x,y,yaw,v,steer");

    PaperCOptions paperC;
    auto *cPaperC = app.add_subcommand(
        "paper-c", "Reproduce paper C's driving-time comparison: A* Euclidean against corner A* (paper and physics "
                   "weights) on random road pairs, driven in the simulation by paper C's robot and car, on the embedded "
                   "campus and the Tsudanuma map; plus a corner-weight sweep. Writes paper_c_tables.md and paper_c.json");
    cPaperC->add_option("--out", paperC.outDir, "Output folder")->capture_default_str();
    cPaperC->add_option("--shared", paperC.sharedDir, "Folder holding maps/ros/tsudanuma_campus")->capture_default_str();
    cPaperC->add_option("--pairs", paperC.pairs, "Start / goal pairs per map and vehicle")->capture_default_str();
    cPaperC->add_option("--seed", paperC.seed, "Seed of the pairs")->capture_default_str();
    cPaperC->add_option("--time-limit", paperC.timeLimit, "Planning time limit per query, s")->capture_default_str();

    BenchOptions bench;
    auto *cBench = app.add_subcommand(
        "bench", "Benchmark the planners of a problem file with ompl::tools::Benchmark: writes the OMPL .log files, "
                 "the SQLite database (ompl_benchmark_statistics), report.md and plots");
    cBench->add_option("problem", bench.problem, "Problem file (YAML; see benchmarks/problems/)")->required();
    cBench->add_option("--out", bench.outDir, "Output folder")->capture_default_str();
    cBench->add_option("--shared", bench.sharedDir, "Folder substituted for ${shared} in the problem's map path")
        ->capture_default_str();
    cBench->add_option("--shard", bench.shard,
                       "K/N: run only every N-th (query, planner) unit starting at the K-th and write only .log files; "
                       "merge the shards' logs with ompl_benchmark_statistics");
    cBench->add_option("--time-limit", bench.timeLimit, "Seconds per run (overrides the problem file)");
    cBench->add_option("--runs", bench.runs, "Runs per planner (overrides the problem file)");
    cBench->add_flag("--no-database", bench.noDatabase, "Write only the .log files (no database, no report)");
    cBench->add_option("--report-script", bench.reportScript,
                       "The report script (default: " + defaultReportScript() +
                           ", the installed copy next to an installed gridcar, else the source tree's)");

    PaperIOptions paper;
    auto *cPaper = app.add_subcommand(
        "paper-i", "Reproduce paper I's tables: Dijkstra, A* Manhattan / Euclidean, improved A* (paper and integral "
                   "modes) and corner A* in three areas of the embedded campus and of the Tsudanuma map (native and "
                   "resampled to 0.298 m/cell); writes paper_i_tables.md, paper_i.json and one picture per area");
    cPaper->add_option("--out", paper.outDir, "Output folder")->capture_default_str();
    cPaper->add_option("--shared", paper.sharedDir, "Folder holding maps/ros/tsudanuma_campus (skipped if absent)")
        ->capture_default_str();
    cPaper->add_option("--time-limit", paper.timeLimit, "Seconds per query")->capture_default_str();
    cPaper->add_option("--maps", paper.maps, "Only these of campus, tsudanuma-0.298, tsudanuma, comma-separated (default: all found)")
        ->delimiter(',');
    cPaper->add_flag("--skip-native", paper.skipNative, "Do not run the native 0.05 m/cell Tsudanuma map (the slow part)");

    auto *cScen = app.add_subcommand("scen", "Run a Moving AI scenario file and compare with the published optimal lengths");
    cScen->add_option("--map", scen.map, "Moving AI .map file")->required();
    cScen->add_option("--scen", scen.scen, "Moving AI .scen file")->required();
    cScen->add_option("--planner", scen.planner, "Planner name")->capture_default_str();
    cScen->add_option("--vehicle", scen.vehicle, "Vehicle preset or YAML file")->capture_default_str();
    cScen->add_option("--limit", scen.limit, "Only the first N scenarios (0: all)")->capture_default_str();
    cScen->add_flag("--json", scen.json, "Print one JSON object with the counts and speeds");
    cScen->footer("Lengths match when within max(1e-3, 1e-5 x length). Exit status: 0 all matched, 3 some did not, "
                  "2 bad input.");

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
    catch (const CLI::ParseError &e)
    {
        app.exit(e);
        return 2;
    }

    try
    {
        if (*cInfo) return runInfo(info);
        if (*cGen) return runGenmap(gen);
        if (*cDemo) return runDemo(demo);
        if (*cVeh) return runVehicle(veh);
        if (*cPlan) return runPlan(plan);
        if (*cScen) return runScen(scen);
        if (*cPaper) return runPaperI(paper);
        if (*cBench) return runBench(bench);
        if (*cDrive) return runDrive(drive);
        if (*cPaperC) return runPaperC(paperC);
    }
    catch (const gridcar::MapLoadError &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        return 2;
    }
    catch (const InputError &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        return 2;
    }
    catch (const std::invalid_argument &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        return 2;
    }
    catch (const ompl::Exception &e)
    {
        std::fprintf(stderr, "gridcar: error: %s\n", e.what());
        return 2;
    }
    catch (const std::bad_alloc &)
    {
        std::fprintf(stderr, "gridcar: internal error: out of memory\n");
        return 1;
    }
    catch (const std::exception &e)
    {
        std::fprintf(stderr, "gridcar: internal error: %s\n", e.what());
        return 1;
    }
    return 1;
}
