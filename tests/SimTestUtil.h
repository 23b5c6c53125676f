#pragma once
// Roads and straight paths the simulation's tests drive on.
#include "gridcar/spaces/Setup.h"

#include <memory>
#include <string>
#include <vector>

namespace gridcar::test
{
/// A straight road along x: width w metres, length len metres, 0.25 m cells, curbs top and bottom.
inline GridSetup road(double len, double w, const std::string &vehicle = "paper-c-robot")
{
    const double res = 0.25;
    const int W = int(len / res), H = int((w + 2.0) / res);
    auto g = std::make_shared<OccupancyGrid>(W, H, res);
    for (int c = 0; c < W; ++c)
    {
        g->set(c, 0, CellState::Occupied);
        g->set(c, H - 1, CellState::Occupied);
    }
    return makeGridSetup(g, VehicleParams::preset(vehicle));
}

inline std::vector<Pose2> straight(double x0, double x1, double y, double step = 0.25)
{
    std::vector<Pose2> p;
    for (double x = x0; x <= x1 + 1e-9; x += step) p.push_back({x, y, 0.0});
    return p;
}
}  // namespace gridcar::test
