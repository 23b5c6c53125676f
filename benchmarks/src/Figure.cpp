// The pictures of plan and drive: the map crop from gridcar, axes, legend and outlines from
// scripts/plot_figure.py.
#include "gridcar/bench/Figure.h"

#include "gridcar/render/Render.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#ifndef GRIDCAR_FIGURE_SCRIPT
#define GRIDCAR_FIGURE_SCRIPT "scripts/plot_figure.py"
#endif
#ifndef GRIDCAR_INSTALLED_FIGURE_SCRIPT
#define GRIDCAR_INSTALLED_FIGURE_SCRIPT "../share/gridcar/plot_figure.py"  // relative to the executable
#endif

namespace gridcar::bench
{
namespace
{
namespace fs = std::filesystem;

std::string quoted(const std::string &text)
{
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

nlohmann::json poses(const std::vector<Pose2> &path)
{
    nlohmann::json a = nlohmann::json::array();
    for (const Pose2 &p : path) a.push_back({p.x, p.y, p.yaw});
    return a;
}
}  // namespace

std::string defaultFigureScript()
{
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec)
    {
        const fs::path installed = (exe.parent_path() / GRIDCAR_INSTALLED_FIGURE_SCRIPT).lexically_normal();
        if (fs::is_regular_file(installed, ec)) return installed.string();
    }
    return GRIDCAR_FIGURE_SCRIPT;
}

static std::string hexColour(const Rgb &c)
{
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c[0], c[1], c[2]);
    return buf;
}

void drawFigure(const OccupancyGrid &grid, const Figure &fig, const std::string &png, const std::string &command)
{
    const auto t0 = std::chrono::steady_clock::now();
    std::fprintf(stderr, "[%s] drawing %s ...\n", command.c_str(), png.c_str());
    WorldBox box;
    if (fig.endpoints)
    {
        box.add(fig.start.x, fig.start.y);
        box.add(fig.goal.x, fig.goal.y);
    }
    for (const FigurePath &p : fig.paths) box.add(p.points);
    for (const FigureMarkers &m : fig.markers)
        for (const auto &[x, y] : m.points) box.add(x, y);
    const bool wholeMap = !fig.endpoints && fig.paths.empty() && fig.markers.empty();
    const double vehicleReach = fig.vehicle.isPoint() ? 0.0 : fig.vehicle.length;
    const OccupancyGrid crop = wholeMap ? grid : cropAround(grid, box, fig.margin + vehicleReach);
    MapCanvas canvas(crop, 1600);
    if (!fig.tinted.empty())
    {
        std::vector<Cell> inCrop;
        for (const Cell &c : fig.tinted)
        {
            const Cell k = crop.worldToCell(grid.cellCenterX(c.col), grid.cellCenterY(c.row));
            if (crop.inBounds(k.col, k.row)) inCrop.push_back(k);
        }
        canvas.tintCells(inCrop, fig.tintColour);
    }
    // the map crop and the figure's description beside the picture, removed afterwards
    const std::string stem = (fs::temp_directory_path() / ("gridcar-figure-" + std::to_string(::getpid()))).string();
    const std::string mapPng = stem + "-map.png", specFile = stem + ".json";
    canvas.save(mapPng);
    nlohmann::json j;
    j["title"] = fig.title;
    j["image"] = mapPng;
    j["extent"] = {crop.originX(), crop.originX() + crop.sizeX(), crop.originY(), crop.originY() + crop.sizeY()};
    j["vehicle"] = fig.vehicle.isPoint() ? nlohmann::json(nullptr)
                                         : nlohmann::json{{"length", fig.vehicle.length},
                                                          {"width", fig.vehicle.width},
                                                          {"rear_overhang", fig.vehicle.rearOverhang},
                                                          {"footprint", fig.vehicle.footprint}};
    if (fig.endpoints)
    {
        j["start"] = {fig.start.x, fig.start.y, fig.start.yaw};
        j["goal"] = {fig.goal.x, fig.goal.y, fig.goalYaw ? nlohmann::json(fig.goal.yaw) : nlohmann::json(nullptr)};
    }
    j["paths"] = nlohmann::json::array();
    for (const FigurePath &p : fig.paths)
        j["paths"].push_back({{"label", p.label}, {"colour", p.colour}, {"points", poses(p.points)}, {"outline", p.outline},
                              {"width", p.width}});
    j["markers"] = nlohmann::json::array();
    for (const FigureMarkers &m : fig.markers)
    {
        nlohmann::json pts = nlohmann::json::array();
        for (const auto &[x, y] : m.points) pts.push_back({x, y});
        j["markers"].push_back(
            {{"label", m.label}, {"colour", m.colour}, {"marker", m.marker}, {"linestyle", m.linestyle}, {"points", pts}});
    }
    if (!fig.tinted.empty()) j["tint"] = {{"label", fig.tintLabel}, {"colour", hexColour(fig.tintColour)}};
    if (crop.hasCosts()) j["costs"] = {{"label", "cost layer (0-252: deeper, costlier)"}, {"colour", hexColour(kCostColour)}};
    std::ofstream(specFile) << j.dump() << "\n";
    const std::string script = defaultFigureScript();
    const std::string log = stem + ".log";
    const std::string cmd = "/usr/bin/python3 " + quoted(script) + " " + quoted(specFile) + " " + quoted(png) + " > " +
                            quoted(log) + " 2>&1";
    const int rc = std::system(cmd.c_str());
    std::string err;
    if (rc != 0)
    {
        std::ifstream f(log);
        err.assign(std::istreambuf_iterator<char>(f), {});
        if (err.size() > 600) err = "..." + err.substr(err.size() - 600);
    }
    std::error_code ec;
    for (const std::string &f : {mapPng, specFile, log}) fs::remove(f, ec);
    if (rc != 0)
        throw std::runtime_error("the picture script " + script + " failed (needs /usr/bin/python3 with matplotlib): " + err);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "[%s] wrote %s in %.1f s\n", command.c_str(), png.c_str(), s);
}

}  // namespace gridcar::bench
