#include "Commands.h"

#include "CliUtil.h"

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/io/Render.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/planners/GridPlanner.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

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
    return loadMap(map);
}

void ensureDir(const std::string &dir)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError("cannot create output folder '" + dir + "': " + ec.message());
}
}  // namespace

int runInfo(const InfoOptions &o)
{
    OccupancyGrid grid = loadMap(o.map);
    const OccupancyGrid::Counts counts = grid.counts();
    grid.setUnknownIsFree(o.unknownFree);
    const DistanceField field(grid);
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
        j["max_clearance"] = field.maxDistance();
        std::cout << j.dump() << "\n";
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
    std::printf("clearance  max %.2f m (unknown counted as %s)\n", field.maxDistance(),
                o.unknownFree ? "free" : "occupied");
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

    VehicleParams vehicle;
    try
    {
        vehicle = VehicleParams::fromNameOrFile(o.vehicle);
    }
    catch (const std::invalid_argument &e)
    {
        throw InputError(e.what());
    }
    t0 = Clock::now();
    FootprintChecker checker(grid, field, vehicle);
    std::fprintf(stderr, "[3/4] footprint checker (%zu FCL obstacle boxes): %.2f s\n", checker.obstacleBoxCount(),
                 secondsSince(t0));
    // fraction of free cells where the vehicle fits at some of 8 headings
    std::size_t fits = 0, freeCells = 0;
    for (int r = 0; r < grid->height(); r += 4)
        for (int c = 0; c < grid->width(); c += 4)
        {
            if (grid->isBlocked(c, r)) continue;
            ++freeCells;
            for (int k = 0; k < 8; ++k)
                if (checker.isValid(grid->cellCenterX(c), grid->cellCenterY(r), k * M_PI / 4))
                {
                    ++fits;
                    break;
                }
        }
    std::printf("vehicle %s (%.2f m x %.2f m, R_min %.2f m): fits at %.1f %% of free cells (sampled every 4th)\n",
                vehicle.name.c_str(), vehicle.length, vehicle.width, vehicle.minTurningRadius(),
                freeCells ? 100.0 * fits / freeCells : 0.0);

    t0 = Clock::now();
    MapCanvas canvas(*grid);
    canvas.save(o.outDir + "/map.png");
    // Voronoi diagram overlay
    MapCanvas vor(*grid);
    std::vector<Cell> vcells;
    for (int r = 0; r < grid->height(); ++r)
        for (int c = 0; c < grid->width(); ++c)
            if (field->isVoronoi(c, r)) vcells.push_back({c, r});
    vor.tintCells(vcells, {220, 40, 40});
    vor.save(o.outDir + "/voronoi.png");
    std::fprintf(stderr, "[4/4] pictures written (%.2f s)\n", secondsSince(t0));
    std::printf("wrote %s/map.png and %s/voronoi.png%s\n", o.outDir.c_str(), o.outDir.c_str(),
                o.map.empty() ? (" and " + o.outDir + "/campus.yaml").c_str() : "");
    return 0;
}

}  // namespace gridcar::cli

namespace gridcar::cli
{
int runVehicle(const VehicleOptions &o)
{
    VehicleParams v = loadVehicle(o.vehicle);
    if (o.scale != 1.0)
    {
        try
        {
            v = v.scaled(o.scale);
            v.validate();
        }
        catch (const std::invalid_argument &e)
        {
            throw InputError(std::string("--scale: ") + e.what());
        }
    }
    const CornerSpeeds vc = CornerAStar::cornerSpeeds(v);
    const CornerWeights physics = CornerAStar::physicsWeights(v);
    const CornerWeights paper;
    if (o.json)
    {
        nlohmann::json j;
        j["name"] = v.name;
        j["length"] = v.length;
        j["width"] = v.width;
        j["wheelbase"] = v.wheelbase;
        j["rear_overhang"] = v.rearOverhang;
        j["max_steer_deg"] = v.maxSteerDeg;
        j["max_speed"] = v.maxSpeed;
        j["acceleration"] = v.acceleration;
        j["deceleration"] = v.deceleration;
        j["max_lateral_accel"] = v.maxLateralAccel;
        j["friction"] = v.friction;
        j["max_curvature"] = v.isPoint() ? nlohmann::json(nullptr) : nlohmann::json(v.maxCurvature());
        j["min_turning_radius"] = v.minTurningRadius();
        j["corner_speeds"] = {vc.v45, vc.v90, vc.v135};
        j["physics_weights"] = {physics.w45, physics.w90, physics.w135};
        j["paper_weights"] = {paper.w45, paper.w90, paper.w135};
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("vehicle %s\n", v.name.c_str());
    if (v.isPoint())
        std::printf("  body: a point (plain grid semantics)\n");
    else
        std::printf("  body: %.3g m x %.3g m, wheelbase %.3g m, rear overhang %.3g m\n", v.length, v.width, v.wheelbase,
                    v.rearOverhang);
    std::printf("  steering: max %.3g deg -> K_max %.4g 1/m, R_min %.4g m\n", v.maxSteerDeg, v.maxCurvature(),
                v.minTurningRadius());
    std::printf("  speed: max %.4g m/s, acceleration %.4g m/s^2, deceleration %.4g m/s^2, lateral %.4g m/s^2, "
                "friction %.3g\n",
                v.maxSpeed, v.acceleration, v.deceleration, v.maxLateralAccel, v.friction);
    std::printf("  corner speeds: %.4g / %.4g / %.4g m/s (45 / 90 / 135 deg)\n", vc.v45, vc.v90, vc.v135);
    std::printf("corner-astar weights (m)       45 deg    90 deg   135 deg\n");
    std::printf("  weights=paper (defaults)  %9.2f %9.2f %9.2f\n", paper.w45, paper.w90, paper.w135);
    std::printf("  weights=physics           %9.2f %9.2f %9.2f\n", physics.w45, physics.w90, physics.w135);
    std::printf("physics weight = (v_max - v_c)^2 / 2 x (1/a + 1/d): v_max x the time lost braking for the corner and "
                "accelerating again\n");
    return 0;
}
}  // namespace gridcar::cli
