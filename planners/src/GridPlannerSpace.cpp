/// @file GridPlannerSpace.cpp
/// @brief GridPlanner on an SE(2) space that is not gridcar's (plain SE2, OMPL's Dubins or
/// Reeds-Shepp): the lattice geometry from the space's bounds and the planner's parameters,
/// the turning radius from the space, and the default car's dynamics.
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/spaces/CurveSpaces.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace gridcar
{
double GridPlanner::turningRadius() const
{
    // never tighter than gridcar's vehicle can drive
    if (checker_) return std::max(params_.turningRadius, checker_->vehicle().minTurningRadius());
    if (params_.turningRadius > 0) return params_.turningRadius;
    const double r = carSpaceTurningRadius(*si_->getStateSpace());
    return r > 0 ? r : VehicleParams{}.minTurningRadius();
}

VehicleParams GridPlanner::genericVehicle() const
{
    VehicleParams v;  // the default car, steering to the turning radius in use
    v.name = "default car (" + getName() + " without gridcar's checker)";
    const double r = turningRadius();
    v.maxSteerDeg = std::atan(v.wheelbase / r) * 180.0 / M_PI;
    return v;
}

std::shared_ptr<GridSE2StateSpace> GridPlanner::ownGridSpace()
{
    if (checker_)
    {
        // gridcar's checker on OMPL's Dubins / Reeds-Shepp space: the map's own cells
        const OccupancyGrid &g = checker_->grid();
        if (!ownSpace_ || ownSpace_->width() != g.width() || ownSpace_->height() != g.height() ||
            ownSpace_->cellSize() != g.resolution() || ownSpace_->originX() != g.originX() ||
            ownSpace_->originY() != g.originY())
            ownSpace_ = std::make_shared<GridSE2StateSpace>(g, 8);
        return ownSpace_;
    }
    const auto &b = si_->getStateSpace()->as<ompl::base::SE2StateSpace>()->getBounds();
    const double sx = b.high[0] - b.low[0], sy = b.high[1] - b.low[1];
    if (!(sx > 0 && sy > 0) || !std::isfinite(sx) || !std::isfinite(sy))
        throw ompl::Exception(getName(), "the SE(2) space needs finite, non-empty x and y bounds");
    double cell = params_.latticeCell > 0 ? params_.latticeCell : turningRadius() / 4;
    constexpr double kMaxCells = double(1 << 24);
    if (usesCarLattice())
        cell = std::max(cell, std::sqrt(sx * sy / kMaxCells));  // geometry only: the car lattice has its own nodes
    const double w = std::ceil(sx / cell - 1e-9), h = std::ceil(sy / cell - 1e-9);
    if (w * h > kMaxCells)
        throw ompl::Exception(getName(), "lattice_cell " + std::to_string(cell) + " m over the space's bounds gives " +
                                             std::to_string(long(w)) + " x " + std::to_string(long(h)) +
                                             " cells, more than 2^24: raise lattice_cell");
    if (ownSpace_ && ownSpace_->width() == int(w) && ownSpace_->height() == int(h) && ownSpace_->cellSize() == cell &&
        ownSpace_->originX() == b.low[0] && ownSpace_->originY() == b.low[1])
        return ownSpace_;
    OccupancyGrid g(int(w), int(h), cell);
    g.setOrigin(b.low[0], b.low[1]);
    ownSpace_ = std::make_shared<GridSE2StateSpace>(g, 8);
    return ownSpace_;
}

}  // namespace gridcar
