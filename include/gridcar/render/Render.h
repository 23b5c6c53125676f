#pragma once
/// @file Render.h
/// @brief Pictures of maps with paths and markers, written as PNG.

#include "gridcar/image/Image.h"
#include "gridcar/map/OccupancyGrid.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
using Rgb = std::array<std::uint8_t, 3>;

/// Bounding box of world points.
struct WorldBox
{
    double x0{1e300}, x1{-1e300}, y0{1e300}, y1{-1e300};
    void add(double x, double y)
    {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    void add(const std::vector<Pose2> &path)
    {
        for (const Pose2 &p : path) add(p.x, p.y);
    }
};

/// The part of @p grid covering @p box plus @p margin metres on every side, clipped to the map
/// (for pictures of a query's surroundings).
OccupancyGrid cropAround(const OccupancyGrid &grid, const WorldBox &box, double margin);

/// The colour a free cell of the highest cost (252) is drawn in; lower costs between it and white.
inline constexpr Rgb kCostColour{230, 120, 20};

/**
 * @brief An RGB picture of a grid (free white, unknown grey, occupied black; free cells of a
 * cost layer shaded towards kCostColour as their cost rises), scaled so the
 * longer side has at most @p maxSide pixels (or enlarged up to @p maxSide for small maps).
 * When scaled down, a pixel takes the darkest state (and the highest cost) of the cells it covers, so thin curbs stay
 * visible. Overlays are drawn in world coordinates.
 */
class MapCanvas
{
public:
    explicit MapCanvas(const OccupancyGrid &grid, int maxSide = 1600);

    /// Polyline through world points.
    void polyline(const std::vector<std::pair<double, double>> &pts, const Rgb &colour, int thickness = 2);
    /// Polyline through the positions of a path.
    void polyline(const std::vector<Pose2> &path, const Rgb &colour, int thickness = 2);
    /// Filled disc of radius @p radiusPx pixels at a world point.
    void disc(double x, double y, int radiusPx, const Rgb &colour);
    /// Tints the given cells (e.g. the expanded set of a search).
    void tintCells(const std::vector<Cell> &cells, const Rgb &colour);
    /// Closed polygon outline through world points.
    void polygon(const std::vector<std::pair<double, double>> &pts, const Rgb &colour);

    const Image &image() const { return img_; }
    double scale() const { return scale_; }
    void save(const std::string &pngPath) const { writePng(pngPath, img_); }

private:
    void pixel(int px, int py, const Rgb &c);
    void line(double x0, double y0, double x1, double y1, const Rgb &c, int thickness);
    double toPx(double x) const;
    double toPy(double y) const;

    const OccupancyGrid &grid_;
    double scale_;  ///< pixels per cell
    Image img_;
};

}  // namespace gridcar
