#include "gridcar/map/OccupancyGrid.h"

#include "gridcar/core/Memory.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gridcar
{
OccupancyGrid::OccupancyGrid(int width, int height, double resolution, CellState fill)
{
    if (width <= 0 || height <= 0)
    {
        std::ostringstream os;
        os << "grid size must be positive, got " << width << " x " << height;
        throw std::invalid_argument(os.str());
    }
    if (std::size_t(width) * std::size_t(height) > kMaxMapCells)
    {
        std::ostringstream os;
        os << "grid size " << width << " x " << height << " exceeds the limit of " << kMaxMapCells << " cells";
        throw std::invalid_argument(os.str());
    }
    if (!std::isfinite(resolution) || resolution < kMinResolution || resolution > kMaxResolution)
    {
        std::ostringstream os;
        os << "resolution must be between " << kMinResolution << " and " << kMaxResolution << " metres per cell, got "
           << resolution;
        throw std::invalid_argument(os.str());
    }
    if (std::max(width, height) * resolution > kMaxMapExtent)
    {
        std::ostringstream os;
        os << "a " << width << " x " << height << " map at " << resolution << " m per cell is larger than "
           << kMaxMapExtent << " m";
        throw std::invalid_argument(os.str());
    }
    width_ = width;
    height_ = height;
    resolution_ = resolution;
    reserveHuge(cells_, std::size_t(width) * std::size_t(height));
    cells_.assign(std::size_t(width) * std::size_t(height), fill);
}

void OccupancyGrid::setOrigin(double x, double y, double yaw)
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
        throw std::invalid_argument("map origin must be finite");
    if (std::abs(x) > kMaxMapExtent || std::abs(y) > kMaxMapExtent)
    {
        std::ostringstream os;
        os << "map origin (" << x << ", " << y << ") is more than " << kMaxMapExtent << " m from 0";
        throw std::invalid_argument(os.str());
    }
    originX_ = x;
    originY_ = y;
    originYaw_ = yaw;
}


OccupancyGrid::Counts OccupancyGrid::counts() const
{
    Counts c;
    for (CellState s : cells_)
    {
        if (s == CellState::Free) ++c.free;
        else if (s == CellState::Occupied) ++c.occupied;
        else ++c.unknown;
    }
    return c;
}

OccupancyGrid OccupancyGrid::cropped(int col0, int row0, int w, int h) const
{
    const int c0 = std::max(0, col0), r0 = std::max(0, row0);
    const int c1 = std::min(width_, col0 + std::max(0, w)), r1 = std::min(height_, row0 + std::max(0, h));
    if (c1 <= c0 || r1 <= r0) throw std::invalid_argument("crop window misses the map");
    OccupancyGrid out(c1 - c0, r1 - r0, resolution_, CellState::Free);
    // lower-left corner of the window: column c0, the bottom row r1 - 1
    out.setOrigin(originX_ + c0 * resolution_, originY_ + (height_ - r1) * resolution_, originYaw_);
    out.setUnknownIsFree(unknownIsFree_);
    for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c)
        {
            out.set(c - c0, r - r0, at(c, r));
            if (!costs_.empty() && costs_[index(c, r)]) out.setCost(c - c0, r - r0, costs_[index(c, r)]);
        }
    return out;
}

void OccupancyGrid::setCost(int col, int row, std::uint8_t c)
{
    if (!inBounds(col, row)) throw std::invalid_argument("setCost: cell outside the map");
    if (c > 252) throw std::invalid_argument("setCost: costs are 0..252 (253-254 are obstacles, 255 unknown)");
    if (costs_.empty()) costs_.assign(cells_.size(), 0);
    costs_[index(col, row)] = c;
}

OccupancyGrid OccupancyGrid::resampled(double newResolution) const
{
    if (!std::isfinite(newResolution) || newResolution < kMinResolution || newResolution > kMaxResolution)
    {
        std::ostringstream os;
        os << "resample resolution must be between " << kMinResolution << " and " << kMaxResolution
           << " metres per cell, got " << newResolution;
        throw std::invalid_argument(os.str());
    }
    // sizes as doubles first: a tiny cell size must give an error, not an overflowing cast
    const double w = std::max(1.0, std::ceil(sizeX() / newResolution - 1e-9));
    const double h = std::max(1.0, std::ceil(sizeY() / newResolution - 1e-9));
    if (w * h > double(kMaxMapCells))
    {
        std::ostringstream os;
        os << "resampling to " << newResolution << " m per cell would give " << w << " x " << h << " cells (limit "
           << kMaxMapCells << ")";
        throw std::invalid_argument(os.str());
    }
    const int nw = int(w), nh = int(h);
    OccupancyGrid out(nw, nh, newResolution, CellState::Free);
    out.setOrigin(originX_, originY_, originYaw_);
    out.setUnknownIsFree(unknownIsFree_);
    const double ratio = newResolution / resolution_;
    for (int r = 0; r < nh; ++r)
    {
        // new row r covers map-frame v in [nh-1-r, nh-r) * newRes (from the bottom)
        const double v0 = (nh - 1 - r) * ratio, v1 = (nh - r) * ratio;
        const int srcV0 = std::max(0, int(std::floor(v0 + 1e-9)));
        const int srcV1 = std::min(height_ - 1, int(std::ceil(v1 - 1e-9)) - 1);
        for (int c = 0; c < nw; ++c)
        {
            const double u0 = c * ratio, u1 = (c + 1) * ratio;
            const int srcU0 = std::max(0, int(std::floor(u0 + 1e-9)));
            const int srcU1 = std::min(width_ - 1, int(std::ceil(u1 - 1e-9)) - 1);
            bool occ = false, unk = false;
            std::uint8_t worst = 0;  // the cost layer: the highest cost under the new cell
            for (int sv = srcV0; sv <= srcV1 && !occ; ++sv)
            {
                const int srow = height_ - 1 - sv;
                for (int su = srcU0; su <= srcU1; ++su)
                {
                    if (!costs_.empty()) worst = std::max(worst, costs_[index(su, srow)]);
                    const CellState s = at(su, srow);
                    if (s == CellState::Occupied) { occ = true; break; }
                    if (s == CellState::Unknown) unk = true;
                }
            }
            // cells past the source extent (partial last row/column) count as occupied
            if (srcU1 < srcU0 || srcV1 < srcV0) occ = true;
            out.set(c, r, occ ? CellState::Occupied : (unk ? CellState::Unknown : CellState::Free));
            if (worst) out.setCost(c, r, worst);
        }
    }
    return out;
}

}  // namespace gridcar
