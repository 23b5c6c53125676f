#pragma once
/// @file Figure.h
/// @brief The pictures of `gridcar plan --png` and `gridcar drive --png`: the map around the
/// paths (or the whole map, for `gridcar demo`) with axes in metres, a scale bar, a legend, the vehicle's outline along each path and
/// in reverse segments their own colour, in `gridcar bench`'s colours (start black, goal
/// magenta). gridcar draws the map crop; scripts/plot_figure.py (matplotlib) draws the rest.

#include "gridcar/map/OccupancyGrid.h"
#include "gridcar/render/Render.h"
#include "gridcar/vehicle/VehicleParams.h"

#include <string>
#include <utility>
#include <vector>

namespace gridcar::bench
{
/// A path in a figure, with matplotlib's colour name.
struct FigurePath
{
    std::string label, colour;
    std::vector<Pose2> points;
    bool outline{true};  ///< the vehicle's outline along it
    double width{1.6};
};

/// Points drawn as markers (or a line with linestyle "-").
struct FigureMarkers
{
    std::string label, colour, marker{"o"}, linestyle{"none"};
    std::vector<std::pair<double, double>> points;
};

/// What a picture shows.
struct Figure
{
    std::string title;
    VehicleParams vehicle;
    Pose2 start, goal;
    bool endpoints{true};  ///< false: no start and goal drawn (a map picture)
    bool goalYaw{true};  ///< false: the goal's heading was free (no goal outline)
    std::vector<FigurePath> paths;
    std::vector<FigureMarkers> markers;
    std::vector<Cell> tinted;  ///< map cells to tint (e.g. what a planner explored)
    std::string tintLabel{"explored by the planner"};
    Rgb tintColour{170, 200, 255};
    double margin{10.0};  ///< metres of map around everything drawn
};

/// Draws @p fig over @p grid into @p png (progress on stderr, prefixed "[@p command]"): the
/// map around what is drawn (the whole map when nothing is), its cost layer where it has one.
/// std::runtime_error naming the script when the picture cannot be drawn.
void drawFigure(const OccupancyGrid &grid, const Figure &fig, const std::string &png, const std::string &command);

/// The figure script: the installed copy next to an installed gridcar
/// (BINDIR/../share/gridcar/plot_figure.py) if there is one, else the source tree's.
std::string defaultFigureScript();

}  // namespace gridcar::bench
