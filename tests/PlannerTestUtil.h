#pragma once
// Maps and set-ups the planner tests share.
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/Setup.h"

#include <memory>
#include <string>

namespace gridcar::test
{
/// A map where the left and right halves are joined by one corridor; a separate closed room
/// holds the unreachable goal.
inline std::shared_ptr<const OccupancyGrid> testMap()
{
    auto g = std::make_shared<OccupancyGrid>(60, 40, 0.5);
    g->setUnknownIsFree(true);
    for (int r = 0; r < 40; ++r)
        if (r < 18 || r > 22) g->set(30, r, CellState::Occupied);  // wall with a gap
    for (int c = 45; c < 56; ++c)                                  // closed room, rows 2..10
    {
        g->set(c, 2, CellState::Occupied);
        g->set(c, 10, CellState::Occupied);
    }
    for (int r = 2; r <= 10; ++r)
    {
        g->set(45, r, CellState::Occupied);
        g->set(55, r, CellState::Occupied);
    }
    return g;
}

inline GridSetup testSetup(const std::string &vehicle = "point")
{
    return makeGridSetup(testMap(), VehicleParams::preset(vehicle));
}

/// 60 m x 40 m at 0.2 m, free but for a wall at x = 30 m from y = 0 to y = 28 m (the car
/// spaces' tests go round it).
inline std::shared_ptr<OccupancyGrid> wallMap()
{
    auto g = std::make_shared<OccupancyGrid>(300, 200, 0.2, CellState::Free);
    for (int r = 60; r < 200; ++r)
        for (int c = 150; c < 153; ++c) g->set(c, r, CellState::Occupied);
    return g;
}

/// wallMap() with paper I's car on a space of the given kind.
inline GridSetup carSetup(SpaceKind kind)
{
    SetupOptions o;
    o.space = kind;
    return makeGridSetup(wallMap(), VehicleParams::preset("paper-i"), o);
}

inline Pose2 cellPose(const OccupancyGrid &g, int c, int r, double yaw = 0.0) { return {g.cellCenterX(c), g.cellCenterY(r), yaw}; }

inline bool isGrid(const std::string &name)
{
    for (const auto &n : gridPlannerNames())
        if (n == name) return true;
    return false;
}

}  // namespace gridcar::test
