// gridcar paper-i: paper I's section 4 (three query areas, the baselines and improved A*) on the
// embedded campus and on the real Tsudanuma campus map (native and at paper I's 0.298 m/cell).
#include "gridcar/bench/PaperI.h"

#include "gridcar/bench/Format.h"
#include "gridcar/core/Errors.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/render/Render.h"

#include <ompl/util/Console.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gridcar::bench
{
namespace
{
namespace fs = std::filesystem;

struct Area
{
    std::string name;
    double sx, sy, gx, gy;  ///< world coordinates before snapping to a free cell
};

struct MapCase
{
    std::string key, title;
    std::shared_ptr<const OccupancyGrid> grid;
    std::vector<Area> areas;
};

/// Planner configurations of the tables: name shown, factory name, parameters.
struct PlannerRow
{
    std::string label, name;
    PlannerParams params;
    Rgb colour;
};

std::vector<PlannerRow> plannerRows()
{
    return {{"Dijkstra", "dijkstra", {}, {120, 120, 120}},
            {"A* Manhattan", "astar-manhattan", {}, {230, 140, 20}},
            {"A* Euclidean", "astar-euclidean", {}, {220, 30, 30}},
            {"improved A* (paper)", "improved-astar", {{"mode", "paper"}, {"lattice", "grid"}}, {20, 60, 220}},
            {"improved A* (integral)", "improved-astar", {{"mode", "integral"}, {"lattice", "grid"}}, {20, 170, 200}},
            {"corner A*", "corner-astar", {{"mode", "paper"}}, {30, 160, 40}},
            // the car lattice (drivable as searched), beside the papers' grids
            {"improved A* (car lattice, integral)", "improved-astar", {{"mode", "integral"}}, {250, 140, 0}},
            {"corner A* (car lattice)", "corner-astar", {}, {150, 0, 150}}};
}

const char *kTableHeader = "| area | planner | status | time s | length m | expanded | path distance m | footprint clearance m | "
                           "max turn deg | smoothing s | turns | max curvature 1/m |\n"
                           "|---|---|---|---|---|---|---|---|---|---|---|---|\n";

/// A start / goal near (x, y) in the middle of the road: of the cells within 4 m where the
/// vehicle fits at some multiple of 45 degrees, the one farthest from obstacles (so that the
/// query's end points do not decide every planner's clearance); failing that, the nearest such
/// cell within 15 m. Throws InputError if there is none.
Pose2 snap(const GridSetup &s, double x, double y, const std::string &what)
{
    const OccupancyGrid &g = *s.grid;
    const Cell c0 = g.worldToCell(x, y);
    auto fits = [&](int c, int r, double &yaw) {
        return g.inBounds(c, r) && !g.isBlocked(c, r) && s.checker->fitsAtSomeHeading(g.cellCenterX(c), g.cellCenterY(r), 8, &yaw);
    };
    const int near = int(std::ceil(4.0 / g.resolution()));
    double bestD = -1.0;
    Pose2 best{};
    for (int dr = -near; dr <= near; ++dr)
        for (int dc = -near; dc <= near; ++dc)
        {
            if (std::hypot(dc, dr) > near) continue;
            const int c = c0.col + dc, r = c0.row + dr;
            double yaw;
            if (!g.inBounds(c, r) || s.field->cellDistance(c, r) <= bestD || !fits(c, r, yaw)) continue;
            bestD = s.field->cellDistance(c, r);
            best = {g.cellCenterX(c), g.cellCenterY(r), yaw};
        }
    if (bestD >= 0) return best;
    const int maxR = int(std::ceil(15.0 / g.resolution()));
    for (int rad = near; rad <= maxR; ++rad)
        for (int dr = -rad; dr <= rad; ++dr)
            for (int dc = -rad; dc <= rad; ++dc)
            {
                if (std::max(std::abs(dr), std::abs(dc)) != rad) continue;
                double yaw;
                if (fits(c0.col + dc, c0.row + dr, yaw))
                    return {g.cellCenterX(c0.col + dc), g.cellCenterY(c0.row + dr), yaw};
            }
    throw InputError(what + ": no free pose for the vehicle within 15 m of (" + std::to_string(x) + ", " +
                     std::to_string(y) + ")");
}

/// The maps of the tables: the embedded campus, and the Tsudanuma map when it is there.
std::vector<MapCase> mapCases(const PaperIOptions &o)
{
    std::vector<MapCase> cases;
    auto campus = std::make_shared<const OccupancyGrid>(generateCampus());
    auto area = [&](const std::string &n, int sc, int sr, int gc, int gr) {
        return Area{n, campus->cellCenterX(sc), campus->cellCenterY(sr), campus->cellCenterX(gc), campus->cellCenterY(gr)};
    };
    cases.push_back({"campus", "embedded campus (4846 x 2816, 0.298 m/cell)", campus,
                     {area("1", 2680, 1680, 2470, 1440), area("2", 3047, 1450, 3250, 1668), area("3", 1700, 1537, 1960, 1650)}});
    const fs::path tsu = fs::path(o.sharedDir) / "maps/ros/tsudanuma_campus/tsudanuma_all.yaml";
    std::error_code tsuError;  // a --shared path the file system refuses: no Tsudanuma map
    if (fs::exists(tsu, tsuError))
    {
        auto native = std::make_shared<const OccupancyGrid>(loadMap(tsu.string()));
        auto coarse = std::make_shared<const OccupancyGrid>(native->resampled(0.298));
        const std::vector<Area> areas = {{"1", 0, -110, 75, -45}, {"2", -5, -98, 75, -45}, {"3", -5, -98, 72, -80}};
        cases.push_back({"tsudanuma-0.298", "Tsudanuma campus resampled to 0.298 m/cell (" +
                                                std::to_string(coarse->width()) + " x " + std::to_string(coarse->height()) + ")",
                         coarse, areas});
        if (!o.skipNative) cases.push_back({"tsudanuma", "Tsudanuma campus, native 0.05 m/cell (5500 x 4416)", native, areas});
    }
    else
        std::fprintf(stderr, "[paper-i] %s not found: only the embedded campus map is run\n", tsu.string().c_str());
    if (o.maps.empty()) return cases;
    std::vector<MapCase> chosen;
    for (const MapCase &mc : cases)
        if (std::find(o.maps.begin(), o.maps.end(), mc.key) != o.maps.end()) chosen.push_back(mc);
    if (chosen.empty()) throw InputError("--maps: none of the given maps is available (campus, tsudanuma-0.298, tsudanuma)");
    return chosen;
}

/// One table row (Markdown) and its JSON record.
void addRow(std::ostringstream &md, nlohmann::json &all, const MapCase &mc, const Area &a, const PlannerRow &pr,
            const QueryResult &q, const Pose2 &start, const Pose2 &goal)
{
    const bool exact = q.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
    md << "| " << a.name << " | " << pr.label << " | " << (exact ? "exact" : q.status.asString()) << " | "
       << fixed(q.seconds, 3) << " | " << fixed(q.metrics.length, 1) << " | " << q.expanded << " | "
       << fixed(q.metrics.minPathDistance, 2) << " | " << fixed(q.metrics.minClearance, 2) << " | " << fixed(q.maxTurnDeg, 1)
       << " | " << (q.smoothed ? fixed(q.smoothingSeconds, 4) : std::string("-")) << " | " << q.metrics.turns << " | "
       << fixed(q.metrics.maxCurvature, 2) << " |\n";
    all.push_back({{"map", mc.key}, {"area", a.name}, {"planner", pr.label}, {"status", q.status.asString()},
                   {"time", q.seconds}, {"length", q.metrics.length}, {"expanded", q.expanded},
                   {"min_path_distance", q.metrics.minPathDistance}, {"min_clearance", q.metrics.minClearance},
                   {"max_turn_deg", q.maxTurnDeg}, {"smoothing_time", q.smoothingSeconds}, {"turns", q.metrics.turns},
                   {"max_curvature", q.metrics.maxCurvature}, {"adjust_failures", q.adjustFailures},
                   {"bezier_fallbacks", q.bezierFallbacks}, {"drivable", q.drivability.drivable}, {"not_drivable_because", q.drivability.reason},
                   {"start", {start.x, start.y}}, {"goal", {goal.x, goal.y}}});
}

/// Every planner of the tables on one area: rows, JSON and a picture with every path.
void runArea(const PaperIOptions &o, GridSetup &setup, const MapCase &mc, const Area &a, std::ostringstream &md,
             nlohmann::json &all, std::chrono::steady_clock::time_point t0)
{
    const Pose2 start = snap(setup, a.sx, a.sy, mc.key + " area " + a.name + " start");
    const Pose2 goal = snap(setup, a.gx, a.gy, mc.key + " area " + a.name + " goal");
    WorldBox box;
    box.add(start.x, start.y);
    box.add(goal.x, goal.y);
    std::vector<std::pair<Rgb, std::vector<Pose2>>> paths;
    for (const PlannerRow &pr : plannerRows())
    {
        std::fprintf(stderr, "[paper-i] %s area %s: %-24s ", mc.key.c_str(), a.name.c_str(), pr.label.c_str());
        const auto planner = configurePlanner(setup.ss->getSpaceInformation(), {pr.name, pr.params, true, false});
        const QueryResult q = runQuery(setup, planner, start, goal, o.timeLimit);
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::fprintf(stderr, "%s, %.3f s, %.1f m, %llu expanded (elapsed %.0f s)\n", q.status.asString().c_str(), q.seconds,
                     q.metrics.length, (unsigned long long)q.expanded, elapsed);
        addRow(md, all, mc, a, pr, q, start, goal);
        box.add(q.path);
        paths.push_back({pr.colour, q.path});
    }
    const OccupancyGrid crop = cropAround(*mc.grid, box, 12.0);
    MapCanvas canvas(crop, 1000);
    for (const auto &p : paths) canvas.polyline(p.second, p.first, 2);
    canvas.disc(start.x, start.y, 6, {0, 0, 0});
    canvas.disc(goal.x, goal.y, 6, {200, 0, 200});
    const std::string png = "paper_i_" + mc.key + "_area" + a.name + ".png";
    canvas.save((fs::path(o.outDir) / png).string());
    md << "\n![" << mc.key << " area " << a.name << "](" << png << ")\n\n";
}
}  // namespace

int runPaperI(const PaperIOptions &o)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    checkTimeLimit(o.timeLimit);
    fs::create_directories(o.outDir);
    const VehicleParams vehicle = VehicleParams::preset("paper-i");
    const std::vector<MapCase> cases = mapCases(o);
    std::ostringstream md;
    nlohmann::json all = nlohmann::json::array();
    const auto t0 = std::chrono::steady_clock::now();
    for (const MapCase &mc : cases)
    {
        std::fprintf(stderr, "[paper-i] %s: distance field and footprint checker...\n", mc.key.c_str());
        GridSetup setup = makeGridSetup(mc.grid, vehicle);
        md << "### " << mc.title << "\n\n";
        for (const Area &a : mc.areas)
        {
            md << kTableHeader;
            runArea(o, setup, mc, a, md, all, t0);
        }
    }
    md << "Colours: Dijkstra grey, A* Manhattan orange, A* Euclidean red, improved A* (paper) blue, improved A* "
          "(integral) cyan, corner A* green, improved A* (car lattice, integral) orange-brown, corner A* (car lattice) "
          "purple; start black, goal magenta.\n";
    std::ofstream(fs::path(o.outDir) / "paper_i_tables.md") << md.str();
    std::ofstream(fs::path(o.outDir) / "paper_i.json") << all.dump(1) << "\n";
    std::fprintf(stderr, "[paper-i] wrote %s/paper_i_tables.md, paper_i.json and the pictures\n", o.outDir.c_str());
    return 0;
}

}  // namespace gridcar::bench
