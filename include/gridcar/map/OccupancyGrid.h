#pragma once
/// @file OccupancyGrid.h
/// @brief Occupancy grid in the ROS map_server convention.

#include "gridcar/core/Limits.h"
#include "gridcar/core/Pose2.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <algorithm>
#include <cmath>
#include <vector>

namespace gridcar
{
/// State of one grid cell as read from a map file.
enum class CellState : std::uint8_t
{
    Free = 0,
    Occupied = 1,
    Unknown = 2
};

/// Cell sizes a map may have, metres: from a tenth of a millimetre to a kilometre.
constexpr double kMinResolution = 1e-4, kMaxResolution = 1e3;
/// Largest distance of a map's origin from 0 and largest side of a map, metres (10 000 km):
/// beyond it world coordinates lose the precision of a cell, and FCL's boxes overflow.
constexpr double kMaxMapExtent = 1e7;

/**
 * @brief A 2D occupancy grid: width x height cells of `resolution` metres.
 *
 * Conventions (ROS map_server): cell (col, row) with row 0 at the TOP of the image;
 * the world frame has x to the right and y up, and `origin` is the world pose of the
 * lower-left corner of the lower-left cell (col 0, row height-1). The origin yaw is stored
 * and reported but, like ROS costmap_2d, ignored by the conversions (yaw != 0 maps are
 * treated as axis-aligned). Cell centres are at half-integer multiples of the resolution.
 *
 * Cells keep the state they were read with (free / occupied / unknown). For planning,
 * isBlocked() treats unknown as occupied unless setUnknownIsFree(true).
 */
class OccupancyGrid
{
public:
    OccupancyGrid() = default;
    /// Creates a width x height grid filled with @p fill. Throws std::invalid_argument for
    /// non-positive or absurd sizes or a non-positive / non-finite resolution.
    OccupancyGrid(int width, int height, double resolution, CellState fill = CellState::Free);

    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t size() const { return cells_.size(); }
    double resolution() const { return resolution_; }
    double originX() const { return originX_; }
    double originY() const { return originY_; }
    double originYaw() const { return originYaw_; }
    /// Sets the world pose of the lower-left corner (yaw stored, not applied).
    void setOrigin(double x, double y, double yaw = 0.0);

    bool inBounds(int col, int row) const { return col >= 0 && row >= 0 && col < width_ && row < height_; }
    /// True if @p o has this grid's size, resolution and origin (position and yaw): a cell of
    /// one is the same piece of the world as the same cell of the other.
    bool sameFrame(const OccupancyGrid &o) const
    {
        return width_ == o.width_ && height_ == o.height_ && resolution() == o.resolution() && originX_ == o.originX_ &&
               originY_ == o.originY_ && originYaw_ == o.originYaw_;
    }
    std::size_t index(int col, int row) const { return std::size_t(row) * std::size_t(width_) + std::size_t(col); }

    CellState at(int col, int row) const { return cells_[index(col, row)]; }
    void set(int col, int row, CellState s) { cells_[index(col, row)] = s; }
    const std::vector<CellState> &cells() const { return cells_; }
    std::vector<CellState> &cells() { return cells_; }

    /// Blocked for planning: occupied, unknown (unless unknown counts as free), or off the map.
    bool isBlocked(int col, int row) const
    {
        if (!inBounds(col, row)) return true;
        const CellState s = cells_[index(col, row)];
        return s == CellState::Occupied || (s == CellState::Unknown && !unknownIsFree_);
    }
    bool unknownIsFree() const { return unknownIsFree_; }
    void setUnknownIsFree(bool v) { unknownIsFree_ = v; }

    /// World x of the centre of column @p col.
    double cellCenterX(int col) const { return originX_ + (col + 0.5) * resolution_; }
    /// World y of the centre of row @p row (row 0 is the top).
    double cellCenterY(int row) const { return originY_ + (height_ - row - 0.5) * resolution_; }
    /// The cell that contains world point (x, y) (may be out of bounds; check inBounds()).
    Cell worldToCell(double x, double y) const
    {
        const double u = std::floor(worldToMapU(x));
        const double v = std::floor(worldToMapV(y));
        // clamp into int range before the cast; out-of-range values stay out of bounds
        const double lim = 2.0e9;
        const int col = int(std::max(-lim, std::min(lim, std::isfinite(u) ? u : -1.0)));
        const int vi = int(std::max(-lim, std::min(lim, std::isfinite(v) ? v : -1.0)));
        return Cell{col, height_ - 1 - vi};
    }
    /// Continuous "map frame" coordinates: u = (x - ox) / res, v = (y - oy) / res (cells, y up).
    double worldToMapU(double x) const { return (x - originX_) / resolution_; }
    double worldToMapV(double y) const { return (y - originY_) / resolution_; }

    /// World extent.
    double sizeX() const { return width_ * resolution_; }
    double sizeY() const { return height_ * resolution_; }

    struct Counts
    {
        std::size_t free{0}, occupied{0}, unknown{0};
    };
    /// Cell counts by state as stored (unknown is not merged into occupied).
    Counts counts() const;

    /**
     * @brief The cost layer: a traversal cost 0..252 per cell (Nav2 costmap_2d's scale: 0 free
     * space, 252 just short of the inscribed / lethal values 253-254, which are obstacles here).
     * Read from a map_server map in `scale` mode or `raw` mode (see loadRosMap()); empty for
     * every other map. Planners use it only when asked (`cost_layer_weight`).
     */
    bool hasCosts() const { return !costs_.empty(); }
    /// The cost of a cell (0 without a cost layer or off the map).
    std::uint8_t cost(int col, int row) const { return costs_.empty() || !inBounds(col, row) ? 0 : costs_[index(col, row)]; }
    /// Sets a cell's cost (0..252), creating the layer (all 0) at the first call.
    void setCost(int col, int row, std::uint8_t c);
    const std::vector<std::uint8_t> &costs() const { return costs_; }

    /// A copy resampled to @p newResolution (metres/cell): a new cell is blocked if any source
    /// cell it overlaps is occupied, unknown if any is unknown and none occupied, else free
    /// (conservative for planning).
    OccupancyGrid resampled(double newResolution) const;
    /// The cells [col0, col0 + w) x [row0, row0 + h) (clipped to the map) as a new grid with the
    /// same world coordinates (origin moved), e.g. to draw a detail. Throws std::invalid_argument
    /// if the window misses the map.
    OccupancyGrid cropped(int col0, int row0, int w, int h) const;

private:
    int width_{0};
    int height_{0};
    double resolution_{1.0};
    double originX_{0.0}, originY_{0.0}, originYaw_{0.0};
    bool unknownIsFree_{false};
    std::vector<CellState> cells_;
    std::vector<std::uint8_t> costs_;  ///< empty: no cost layer
};

}  // namespace gridcar
