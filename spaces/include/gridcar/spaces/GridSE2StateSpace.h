#pragma once
/// @file GridSE2StateSpace.h
/// @brief SE(2) state space that also knows the map's lattice (cells x heading bins).

#include "gridcar/core/Angles.h"
#include "gridcar/map/OccupancyGrid.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <cmath>

namespace gridcar
{
/// A lattice state: map cell (col, row; row 0 is the top image row) and heading bin.
struct LatticeState
{
    int col{0};
    int row{0};
    int heading{0};
    bool operator==(const LatticeState &o) const { return col == o.col && row == o.row && heading == o.heading; }
};

/**
 * @brief An ompl::base::SE2StateSpace whose bounds are the map's extent and which converts
 * states to and from the grid lattice (cell, heading bin).
 *
 * Any OMPL planner samples it as plain SE(2). The grid planners use the lattice:
 * - position: the cell that CONTAINS (x, y) (floor of the map-frame coordinate; a point on a
 *   cell edge belongs to the cell to its right / above);
 * - heading: the nearest of headingBins() equally spaced headings, bin k at yaw
 *   k * 2 pi / bins (0 = +x, counter-clockwise); a yaw exactly half-way rounds up to the
 *   higher bin;
 * - fromLattice() places the state at the cell centre with the bin's yaw in [-pi, pi) (OMPL's SO2 range).
 */
class GridSE2StateSpace : public ompl::base::SE2StateSpace
{
public:
    /// @param headingBins 8 (default), 16, 32 or 72; anything else throws std::invalid_argument.
    explicit GridSE2StateSpace(const OccupancyGrid &grid, int headingBins = 8);

    int width() const { return width_; }
    int height() const { return height_; }
    double cellSize() const { return resolution_; }
    double originX() const { return originX_; }
    double originY() const { return originY_; }
    int headingBins() const { return bins_; }
    double headingStep() const { return 2.0 * M_PI / bins_; }

    LatticeState toLattice(const ompl::base::State *state) const;
    LatticeState toLattice(double x, double y, double yaw) const;
    int headingBin(double yaw) const;
    void fromLattice(const LatticeState &l, ompl::base::State *state) const;
    double cellCenterX(int col) const { return originX_ + (col + 0.5) * resolution_; }
    double cellCenterY(int row) const { return originY_ + (height_ - row - 0.5) * resolution_; }
    double binYaw(int bin) const;
    bool inBounds(const LatticeState &l) const
    {
        return l.col >= 0 && l.row >= 0 && l.col < width_ && l.row < height_ && l.heading >= 0 && l.heading < bins_;
    }

private:
    int width_, height_, bins_;
    double resolution_, originX_, originY_;
};

}  // namespace gridcar
