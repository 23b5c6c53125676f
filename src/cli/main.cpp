// gridcar: command-line front end. Exit status: 0 ok, 2 bad input, 1 internal error.
#include "Commands.h"

#include "gridcar/io/Image.h"

#include <cstdio>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

int main(int argc, char **argv)
{
    using namespace gridcar::cli;
    CLI::App app{"gridcar: vehicle-aware grid planners for OMPL (corner-weighted A*, improved A*).\n"
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
        "demo", "Main job: load the map (default: embedded campus), build distance field, Voronoi diagram and "
                "footprint checker, print a summary and write pictures");
    cDemo->add_option("--map", demo.map, "Map file (default: the embedded campus map)");
    cDemo->add_option("--out", demo.outDir, "Output folder")->capture_default_str();
    cDemo->add_option("--vehicle", demo.vehicle, "Vehicle preset (paper-i, paper-c-car, paper-c-robot, point) or YAML file")
        ->capture_default_str();

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
