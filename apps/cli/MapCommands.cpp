// gridcar info / genmap / demo: maps, their distance field and pictures.
#include "Cli.h"

#include "gridcar/bench/Figure.h"
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/render/Render.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace gridcar::cli
{
namespace
{
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

OccupancyGrid loadOrGenerate(const std::string &map, std::string &label)
{
    if (map.empty())
    {
        label = "embedded campus map (gridcar genmap, seed 1)";
        return generateCampus();
    }
    label = map;
    return loadMapArgument(map);
}

struct InfoOptions
{
    std::string map;
    bool json{false};
    bool unknownFree{false};
};

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

struct DemoOptions
{
    std::string map;  ///< empty: the embedded campus map
    std::string outDir{"gridcar-out"};
    std::string vehicle{"paper-i"};
};

/// What a planning set-up on a map of @p cells cells holds per map, in MB (the structures
/// are sized by the map, not by a query): the grid, the distance field (d_O, d_V, GVD: 9 bytes
/// a cell), the grid planners' move cache (8 bytes a cell), their dense search records (16
/// bytes a state, committed as touched: dijkstra / astar-*: a state a cell; corner-astar
/// mode=paper: 8), and the car lattice's 2D heuristic nodes (24 bytes a node of about 0.45 m).
nlohmann::json memoryEstimate(const OccupancyGrid &g)
{
    const double mb = 1.0 / (1024.0 * 1024.0), cells = double(g.size());
    const double nodes = (g.sizeX() / 0.45 + 3) * (g.sizeY() / 0.45 + 3);
    return {{"map", cells * mb},
            {"distance_field", 9 * cells * mb},
            {"move_cache", 8 * cells * mb},
            {"dense_search", 16 * cells * mb},
            {"corner_paper_search", 16 * 8 * cells * mb},
            {"car_lattice_heuristic", 24 * nodes * mb}};
}

/// Above this many cells `info` does not build the distance field (2^26 cells: 576 MB of field).
constexpr std::size_t kInfoFieldCells = std::size_t(1) << 26;

int runInfo(const InfoOptions &o)
{
    OccupancyGrid grid = loadMapArgument(o.map);
    const OccupancyGrid::Counts counts = grid.counts();
    std::size_t costCells = 0;  // free cells of the cost layer with a cost above 0
    for (std::uint8_t c : grid.costs()) costCells += c > 0 ? 1 : 0;
    grid.setUnknownIsFree(o.unknownFree);
    std::unique_ptr<DistanceField> field;
    if (grid.size() <= kInfoFieldCells) field = std::make_unique<DistanceField>(grid);
    const nlohmann::json memory = memoryEstimate(grid);
    if (o.json)
    {
        nlohmann::json j;
        j["width"] = grid.width();
        j["height"] = grid.height();
        j["resolution"] = grid.resolution();
        j["origin"] = {grid.originX(), grid.originY(), grid.originYaw()};
        j["free"] = counts.free;
        j["occupied"] = counts.occupied;
        j["unknown"] = counts.unknown;
        if (grid.hasCosts()) j["cost_cells"] = costCells;
        j["max_clearance"] = field ? nlohmann::json(field->maxDistance()) : nlohmann::json(nullptr);
        j["memory_mb"] = memory;
        printJson(j.dump());
        return 0;
    }
    std::printf("map        %s\n", o.map.c_str());
    std::printf("size       %d x %d cells, %.3f m/cell (%.1f m x %.1f m)\n", grid.width(), grid.height(),
                grid.resolution(), grid.sizeX(), grid.sizeY());
    std::printf("origin     x %.3f  y %.3f  yaw %.3f rad%s\n", grid.originX(), grid.originY(), grid.originYaw(),
                grid.originYaw() != 0.0 ? "  (yaw ignored, as by ROS costmap_2d)" : "");
    const double n = double(grid.size());
    std::printf("cells      free %zu (%.1f %%), occupied %zu (%.1f %%), unknown %zu (%.1f %%)\n", counts.free,
                100.0 * counts.free / n, counts.occupied, 100.0 * counts.occupied / n, counts.unknown,
                100.0 * counts.unknown / n);
    if (grid.hasCosts())
        std::printf("cost layer %zu cells with a cost above 0 (map_server scale / raw values; used by the car-lattice "
                    "planners with --param cost_layer_weight=W)\n",
                    costCells);
    if (field)
        std::printf("clearance  max %.2f m (unknown counted as %s)\n", field->maxDistance(),
                    o.unknownFree ? "free" : "occupied");
    else
        std::printf("clearance  not computed: %zu cells (> 2^26); the distance field alone needs %.0f MB\n", grid.size(),
                    memory["distance_field"].get<double>());
    std::printf("memory     per-map structures of a planning set-up, MB: map %.0f, distance field %.0f; grid planners: "
                "move cache %.0f, dense search up to %.0f (corner-astar mode=paper %.0f); car lattice 2D heuristic %.0f\n",
                memory["map"].get<double>(), memory["distance_field"].get<double>(), memory["move_cache"].get<double>(),
                memory["dense_search"].get<double>(), memory["corner_paper_search"].get<double>(),
                memory["car_lattice_heuristic"].get<double>());
    return 0;
}

int runGenmap(const GenmapOptions &o)
{
    if (o.format != "pgm" && o.format != "png") throw InputError("--format must be pgm or png");
    CampusParams p;
    p.width = o.width;
    p.height = o.height;
    p.resolution = o.resolution;
    p.seed = o.seed;
    const auto t0 = Clock::now();
    OccupancyGrid grid;
    try
    {
        grid = generateCampus(p);
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(e.what());
    }
    std::string stem = o.out;
    if (stem.size() > 5 && (stem.substr(stem.size() - 5) == ".yaml")) stem = stem.substr(0, stem.size() - 5);
    const std::string yaml = stem + ".yaml";
    const std::string imageName = std::filesystem::path(stem).filename().string() + "." + o.format;
    if (auto parent = std::filesystem::path(yaml).parent_path(); !parent.empty()) ensureDir(parent.string());
    saveRosMap(grid, yaml, imageName);
    std::fprintf(stderr, "[genmap] %d x %d cells at %.3f m/cell, seed %llu, %.2f s -> %s\n", grid.width(),
                 grid.height(), grid.resolution(), o.seed, secondsSince(t0), yaml.c_str());
    if (!o.png.empty()) MapCanvas(grid).save(o.png);
    return 0;
}

int runDemo(const DemoOptions &o)
{
    ensureDir(o.outDir);
    auto t0 = Clock::now();
    std::string label;
    auto grid = std::make_shared<OccupancyGrid>(loadOrGenerate(o.map, label));
    const auto counts = grid->counts();
    std::fprintf(stderr, "[1/4] map loaded: %s (%.2f s)\n", label.c_str(), secondsSince(t0));
    std::printf("map: %s\n  %d x %d cells at %.3f m/cell = %.0f m x %.0f m; free %.1f %%, occupied %.1f %%, unknown %.1f %%\n",
                label.c_str(), grid->width(), grid->height(), grid->resolution(), grid->sizeX(), grid->sizeY(),
                100.0 * counts.free / grid->size(), 100.0 * counts.occupied / grid->size(),
                100.0 * counts.unknown / grid->size());
    if (o.map.empty()) saveRosMap(*grid, o.outDir + "/campus.yaml", "campus.pgm");

    t0 = Clock::now();
    auto field = std::make_shared<const DistanceField>(*grid);
    std::fprintf(stderr, "[2/4] distance field + Voronoi: %.2f s\n", secondsSince(t0));
    std::printf("distance field: max clearance %.2f m, %zu Voronoi cells\n", field->maxDistance(),
                field->voronoiCellCount());

    const VehicleParams vehicle = VehicleParams::fromNameOrFile(o.vehicle);
    t0 = Clock::now();
    FootprintChecker checker(grid, field, vehicle);
    const double checkerSeconds = secondsSince(t0);  // (the box count below scans the map: not part of it)
    std::fprintf(stderr, "[3/4] footprint checker: %.2f s (%zu FCL obstacle boxes for the exact check, made per tile on first use)\n",
                 checkerSeconds, checker.obstacleBoxCount());
    // fraction of free cells where the vehicle fits at some of 8 headings
    std::size_t fits = 0, freeCells = 0;
    for (int r = 0; r < grid->height(); r += 4)
        for (int c = 0; c < grid->width(); c += 4)
        {
            if (grid->isBlocked(c, r)) continue;
            ++freeCells;
            if (checker.fitsAtSomeHeading(grid->cellCenterX(c), grid->cellCenterY(r), 8)) ++fits;
        }
    std::printf("vehicle %s (%.2f m x %.2f m, R_min %.2f m): fits at %.1f %% of free cells (sampled every 4th)\n",
                vehicle.name.c_str(), vehicle.length, vehicle.width, vehicle.minTurningRadius(),
                freeCells ? 100.0 * fits / freeCells : 0.0);

    t0 = Clock::now();
    // the pictures through the figure script: axes in metres, a scale bar, a legend, the cost
    // layer shaded where the map has one
    bench::Figure fig;
    fig.endpoints = false;
    char title[200];
    std::snprintf(title, sizeof title, "%s: %.0f m x %.0f m at %.3f m/cell", std::filesystem::path(label).filename().c_str(), grid->sizeX(), grid->sizeY(),
                  grid->resolution());
    fig.title = title;
    bench::drawFigure(*grid, fig, o.outDir + "/map.png", "demo");
    for (int r = 0; r < grid->height(); ++r)
        for (int c = 0; c < grid->width(); ++c)
            if (field->isVoronoi(c, r)) fig.tinted.push_back({c, r});
    fig.tintColour = {220, 40, 40};
    fig.tintLabel = "Voronoi diagram";
    fig.title = std::string(title) + ", Voronoi diagram";
    bench::drawFigure(*grid, fig, o.outDir + "/voronoi.png", "demo");
    std::fprintf(stderr, "[4/4] pictures written (%.2f s)\n", secondsSince(t0));
    std::printf("wrote %s/map.png and %s/voronoi.png%s\n", o.outDir.c_str(), o.outDir.c_str(),
                o.map.empty() ? (" and " + o.outDir + "/campus.yaml").c_str() : "");
    return 0;
}

}  // namespace

Command addInfoCommand(CLI::App &app)
{
    auto o = std::make_shared<InfoOptions>();
    auto *c = app.add_subcommand("info", "Print a map's size, origin, cell counts, max clearance and the memory a planning set-up on it takes");
    addMapOption(c, o->map);
    c->add_flag("--json", o->json,
                "Print one JSON object: width, height, resolution, origin, free, occupied, unknown (counts as read), "
                "max_clearance (m)");
    c->add_flag("--unknown-free", o->unknownFree, "Treat unknown cells as free for the clearance");
    return {c, [o] { return runInfo(*o); }};
}

Command addGenmapCommand(CLI::App &app)
{
    auto o = std::make_shared<GenmapOptions>();
    auto *c = app.add_subcommand("genmap", "Generate the embedded campus-like map (deterministic from --seed)");
    c->add_option("--out", o->out, "Output YAML path; the image is written next to it")->capture_default_str();
    c->add_option("--format", o->format, "Image format: pgm or png")->capture_default_str();
    c->add_option("--png", o->png, "Also write a preview picture (PNG) to this path");
    c->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    c->add_option("--width", o->width, "Width in cells")->capture_default_str();
    c->add_option("--height", o->height, "Height in cells")->capture_default_str();
    c->add_option("--resolution", o->resolution, "Metres per cell")->capture_default_str();
    return {c, [o] { return runGenmap(*o); }};
}

Command addDemoCommand(CLI::App &app)
{
    auto o = std::make_shared<DemoOptions>();
    auto *c = app.add_subcommand("demo", "Load the map (default: embedded campus), build distance field, Voronoi diagram "
                                         "and footprint checker, print a summary and write pictures");
    c->add_option("--map", o->map, "Map file (default: the embedded campus map)");
    c->add_option("--out", o->outDir, "Output folder")->capture_default_str();
    addVehicleOption(c, o->vehicle);
    return {c, [o] { return runDemo(*o); }};
}

}  // namespace gridcar::cli
