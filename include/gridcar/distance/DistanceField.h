#pragma once
/// @file DistanceField.h
/// @brief Exact Euclidean distance transform, generalized Voronoi diagram and Voronoi field.

#include "gridcar/map/OccupancyGrid.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace gridcar
{
/// Parameters of Dolgov et al.'s Voronoi field.
struct VoronoiFieldParams
{
    double alpha{2.0};      ///< falloff rate, metres
    double dOMax{5.0};      ///< obstacle influence distance d_O^max, metres
};

/// A rectangle of cells, inclusive (columns col0..col1, rows row0..row1, row 0 at the top as in
/// OccupancyGrid); empty when col0 > col1 or row0 > row1.
struct CellWindow
{
    int col0{0}, row0{0}, col1{-1}, row1{-1};
    bool empty() const { return col0 > col1 || row0 > row1; }
};

/**
 * @brief Obstacle distance d_O and Voronoi distance d_V of every cell of a grid.
 *
 * d_O is the exact Euclidean distance, in metres, from a cell's CENTRE to the CENTRE of the
 * nearest blocked cell (OccupancyGrid::isBlocked(): occupied, or unknown unless unknown is
 * free). The map border counts as an obstacle: a ring of blocked cells just outside the map.
 * Blocked cells have d_O = 0. The transform is Felzenszwalb & Huttenlocher's lower envelope of
 * parabolas ("Distance Transforms of Sampled Functions", 2012), linear in the number of cells,
 * after a linear column pass, the columns and then the rows shared among up to 4 threads on a
 * large map (1 M cells and more).
 *
 * The generalized Voronoi diagram (GVD) is the set of free cells where the nearest obstacle
 * changes between 4-neighbours in a way that is not a step along one wall: either the two
 * nearest obstacle cells belong to different obstacles (8-connected components of blocked
 * cells; the border and everything touching it is one obstacle), or they are more than
 * voronoiSeparationCells apart (medial axis inside one U-shaped obstacle, e.g. a corridor whose
 * walls join). Of each such pair the cell farther from its obstacle (ties: lower index) is
 * marked, giving a one-cell-thin diagram. d_V is the exact distance from a cell centre to the
 * nearest GVD cell centre (+infinity when the map has no GVD cell).
 *
 * Values between cell centres are bilinear (distance(), gradient()); points outside the map
 * have distance 0.
 *
 * @par External documentation
 * P. Felzenszwalb, D. Huttenlocher, Distance Transforms of Sampled Functions, Theory of
 * Computing 8, 2012. D. Dolgov, S. Thrun, M. Montemerlo, J. Diebel, Path Planning for
 * Autonomous Vehicles in Unknown Semi-structured Environments, IJRR 29(5), 2010 (Voronoi field).
 * Paper I (Yao et al. 2020), eq. 8: o(n) = delta / d_min from a Voronoi / distance map.
 */
class DistanceField
{
public:
    /// Cells whose nearest obstacles are farther apart than this (in cells) mark the GVD.
    static constexpr double voronoiSeparationCells = 3.0;

    /// Computes d_O for @p grid (the grid is copied by reference into metadata only); the GVD
    /// and d_V on first use.
    explicit DistanceField(const OccupancyGrid &grid);

    int width() const { return width_; }
    int height() const { return height_; }
    double resolution() const { return resolution_; }

    /// d_O at cell centre, metres (0 for blocked cells; 0 off the map).
    double cellDistance(int col, int row) const
    {
        return (col < 0 || row < 0 || col >= width_ || row >= height_) ? 0.0 : double(dist_[idx(col, row)]);
    }
    /// d_V at cell centre, metres (+inf if there is no GVD; +inf off the map).
    double cellVoronoiDistance(int col, int row) const
    {
        if (col < 0 || row < 0 || col >= width_ || row >= height_) return std::numeric_limits<double>::infinity();
        voronoiReady();
        return double(vdist_[idx(col, row)]);
    }
    bool isVoronoi(int col, int row) const
    {
        voronoiReady();
        return voronoi_[idx(col, row)] != 0;
    }
    std::size_t voronoiCellCount() const
    {
        voronoiReady();
        return voronoiCount_;
    }
    /**
     * @brief Brings d_O up to date after cells of the grid changed (became blocked or free)
     * within @p changed, and returns the window of cells whose d_O changed (empty if none).
     *
     * @p grid has this field's size; cells outside @p changed must be as they were when the
     * field was last computed or updated. The result equals a full recomputation: the
     * transform's column pass is redone for the changed columns only, and its row pass for
     * the rows where a changed column's distances moved (the rest of the field keeps its
     * values). That needs every column's pass kept (prepareUpdates()); without it, the first
     * update keeps it and redoes every row. The GVD and d_V are built again on next use. Not
     * to be called while other threads read the field.
     * @throws std::invalid_argument if @p grid's size differs or @p changed leaves the map.
     */
    CellWindow update(const OccupancyGrid &grid, const CellWindow &changed);
    /// Keeps the transform's column pass of every cell for update() (16 bits a cell, 32 on maps
    /// of 65 535 rows or more): call it with the grid the field was computed from, before cells
    /// change. 0.1-0.2 s and 48 MB on a 24 M-cell map.
    void prepareUpdates(const OccupancyGrid &grid);

    /// Largest d_O over the map, metres.
    double maxDistance() const { return maxDist_; }

    /// Bilinear d_O at world point (x, y), metres.
    double distance(double x, double y) const;
    /// Gradient of the bilinear d_O at (x, y) (metres per metre); 0 off the map.
    void gradient(double x, double y, double &gx, double &gy) const;
    /// d_V at the cell containing (x, y).
    double voronoiDistance(double x, double y) const;

    /**
     * @brief Dolgov's Voronoi field at (x, y), in [0, 1]:
     * rho_V = (alpha / (alpha + d_O)) (d_V / (d_O + d_V)) ((d_O - d_O^max)^2 / (d_O^max)^2) for
     * d_O <= d_O^max, else 0; with d_V = inf the middle factor is 1. 1 inside obstacles.
     */
    double voronoiField(double x, double y, const VoronoiFieldParams &p = VoronoiFieldParams()) const;

private:
    /// d_O at the four cell centres around (x, y) and the fractions between them; false off the map.
    bool bilinearCorners(double x, double y, double corner[4], double &fu, double &fv) const;
    std::size_t idx(int col, int row) const { return std::size_t(row) * std::size_t(width_) + std::size_t(col); }

    int width_{0}, height_{0};
    double resolution_{1.0};
    double originX_{0}, originY_{0};
    double maxDist_{0};
    std::vector<float> dist_;            ///< d_O per cell, metres
    /// The GVD and d_V are built on first use (voronoiReady(): once, whichever thread asks
    /// first): only paper I's Voronoi cost and the map picture read them, and on a 24 M-cell
    /// map they cost more than d_O itself.
    void voronoiReady() const;
    void buildVoronoi() const;
    /// Column pass of every cell (distance in cells to the nearest blocked cell of its column,
    /// the map border included) and the largest d_O per row: made by the first update().
    struct Columns;
    std::shared_ptr<Columns> columns_;
    mutable std::unique_ptr<std::once_flag> voronoiOnce_{std::make_unique<std::once_flag>()};
    mutable std::size_t voronoiCount_{0};
    mutable std::vector<float> vdist_;           ///< d_V per cell, metres
    mutable std::vector<std::uint8_t> voronoi_;  ///< 1 on GVD cells
};

}  // namespace gridcar
