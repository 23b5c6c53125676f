#include "gridcar/spaces/GridSE2StateSpace.h"

#include "gridcar/spaces/Lattice.h"

#include <cmath>
#include <stdexcept>

namespace gridcar
{
GridSE2StateSpace::GridSE2StateSpace(const OccupancyGrid &grid, int headingBins)
  : width_(grid.width())
  , height_(grid.height())
  , bins_(headingBins)
  , resolution_(grid.resolution())
  , originX_(grid.originX())
  , originY_(grid.originY())
{
    if (headingBins != 8 && headingBins != 16 && headingBins != 32 && headingBins != 72)
        throw std::invalid_argument("heading bins must be 8, 16, 32 or 72, got " + std::to_string(headingBins));
    if (width_ <= 0 || height_ <= 0) throw std::invalid_argument("GridSE2StateSpace needs a non-empty grid");
    setName("GridSE2" + getName());
    ompl::base::RealVectorBounds b(2);
    b.setLow(0, originX_);
    b.setHigh(0, originX_ + width_ * resolution_);
    b.setLow(1, originY_);
    b.setHigh(1, originY_ + height_ * resolution_);
    setBounds(b);
}

int GridSE2StateSpace::headingBin(double yaw) const { return gridcar::headingBin(yaw, bins_); }

LatticeState GridSE2StateSpace::toLattice(double x, double y, double yaw) const
{
    LatticeState l;
    const double u = std::floor((x - originX_) / resolution_);
    const double v = std::floor((y - originY_) / resolution_);
    l.col = std::isfinite(u) ? int(std::max(-1.0, std::min(double(width_), u))) : -1;
    const int vi = std::isfinite(v) ? int(std::max(-1.0, std::min(double(height_), v))) : -1;
    l.row = height_ - 1 - vi;
    l.heading = headingBin(yaw);
    return l;
}

LatticeState GridSE2StateSpace::toLattice(const ompl::base::State *state) const
{
    const auto *s = state->as<StateType>();
    return toLattice(s->getX(), s->getY(), s->getYaw());
}

double GridSE2StateSpace::binYaw(int bin) const
{
    // bins at pi (up to rounding) map to -pi: OMPL's SO2 range is [-pi, pi)
    const double yaw = wrapYaw(bin * headingStep());
    return yaw >= M_PI - 1e-12 ? yaw - 2.0 * M_PI : yaw;
}

void GridSE2StateSpace::fromLattice(const LatticeState &l, ompl::base::State *state) const
{
    auto *s = state->as<StateType>();
    s->setXY(cellCenterX(l.col), cellCenterY(l.row));
    s->setYaw(binYaw(l.heading));
}

}  // namespace gridcar
