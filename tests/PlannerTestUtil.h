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

inline Pose2 cellPose(const OccupancyGrid &g, int c, int r, double yaw = 0.0) { return {g.cellCenterX(c), g.cellCenterY(r), yaw}; }

inline bool isGrid(const std::string &name)
{
    for (const auto &n : gridPlannerNames())
        if (n == name) return true;
    return false;
}

}  // namespace gridcar::test
