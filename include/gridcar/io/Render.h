#pragma once
/// @file Render.h
/// @brief Pictures of maps with paths and markers, written as PNG.

#include "gridcar/io/Image.h"
#include "gridcar/map/OccupancyGrid.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace gridcar
{
using Rgb = std::array<std::uint8_t, 3>;

/**
 * @brief An RGB picture of a grid (free white, unknown grey, occupied black), scaled so the
 * longer side has at most @p maxSide pixels (or enlarged up to @p maxSide for small maps).
 * When scaled down, a pixel takes the darkest state of the cells it covers, so thin curbs stay
 * visible. Overlays are drawn in world coordinates.
 */
class MapCanvas
{
public:
    explicit MapCanvas(const OccupancyGrid &grid, int maxSide = 1600);

    /// Polyline through world points.
    void polyline(const std::vector<std::pair<double, double>> &pts, const Rgb &colour, int thickness = 2);
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
