#pragma once
// Maps and set-ups the planner tests share.
#include "gridcar/core/Angles.h"
#include "gridcar/map/ParkingScenes.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/search/CarLattice.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/spaces/Setup.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
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

/// The parking scene named @p scene for @p vehicle (map/ParkingScenes.h), its query @p name in
/// @p query, and a set-up on it.
inline GridSetup parkingSetup(const std::string &vehicle, const std::string &scene, ParkingQuery &query, const std::string &name)
{
    const VehicleParams v = VehicleParams::preset(vehicle);
    for (const ParkingScene &s : parkingScenes(v))
        if (s.name == scene)
            for (const ParkingQuery &q : s.queries)
                if (q.name == name)
                {
                    query = q;
                    return makeGridSetup(std::make_shared<const OccupancyGrid>(s.grid), v);
                }
    throw std::logic_error("no parking query " + name);
}

/// How far pose @p a is from @p b: the largest of |dx|, |dy| (m) and the wrapped yaw difference
/// (rad), for "the path ends at the goal pose" checks.
inline double poseError(const Pose2 &a, const Pose2 &b)
{
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(wrapAngle(a.yaw - b.yaw))});
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

/// W x H m at 0.25 m, free but for two walls: one from the top at a third of the width, down
/// to a quarter of the height, one from the bottom at two thirds, up to three quarters:
/// corners to take, different paths for different planners.
inline std::shared_ptr<const OccupancyGrid> twoWallsMap(int widthCells, int heightCells)
{
    auto g = std::make_shared<OccupancyGrid>(widthCells, heightCells, 0.25, CellState::Free);
    const int c1 = widthCells * 5 / 16, c2 = widthCells * 21 / 32;
    for (int r = heightCells / 4; r < heightCells; ++r)
        for (int c = c1; c < c1 + 3; ++c) g->set(c, r, CellState::Occupied);
    for (int r = 0; r < heightCells * 3 / 4; ++r)
        for (int c = c2; c < c2 + 3; ++c) g->set(c, r, CellState::Occupied);
    return g;
}

/// A plain OMPL SE(2) space over [0, size]^2 (an application's own, not gridcar's), with a
/// SimpleSetup from @p start to @p goal (yaw 0) on it and the given validity function.
inline std::shared_ptr<ompl::base::SE2StateSpace> plainSpace(double size)
{
    auto space = std::make_shared<ompl::base::SE2StateSpace>();
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(0.0);
    bounds.setHigh(size);
    space->setBounds(bounds);
    return space;
}
inline void setPlainQuery(ompl::geometric::SimpleSetup &ss, double x0, double y0, double x1, double y1)
{
    ompl::base::ScopedState<ompl::base::SE2StateSpace> a(ss.getStateSpace()), b(ss.getStateSpace());
    a->setXY(x0, y0);
    a->setYaw(0);
    b->setXY(x1, y1);
    b->setYaw(0);
    ss.setStartAndGoalStates(a, b);
}

inline Pose2 cellPose(const OccupancyGrid &g, int c, int r, double yaw = 0.0) { return {g.cellCenterX(c), g.cellCenterY(r), yaw}; }

inline bool isGrid(const std::string &name)
{
    for (const auto &n : gridPlannerNames())
        if (n == name) return true;
    return false;
}

/// A free @p cols x @p rows map at @p res with @p blocks seeded random blocks of 1 to @p side
/// cells a side (some cut by the border).
inline std::shared_ptr<OccupancyGrid> randomBlocks(unsigned seed, int cols, int rows, double res, int blocks, int side)
{
    auto g = std::make_shared<OccupancyGrid>(cols, rows, res, CellState::Free);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> uc(0, cols - 1), ur(0, rows - 1), sz(1, side);
    for (int k = 0; k < blocks; ++k)
    {
        const int c = uc(rng), r = ur(rng), w = sz(rng), h = sz(rng);
        for (int rr = r; rr < std::min(rows, r + h); ++rr)
            for (int cc = c; cc < std::min(cols, c + w); ++cc) g->set(cc, rr, CellState::Occupied);
    }
    return g;
}

/// A 9 m x 7 m map at 0.1 m with 30 seeded random blocks (the car-lattice search tests).
inline std::shared_ptr<OccupancyGrid> randomBlocks(unsigned seed) { return randomBlocks(seed, 90, 70, 0.1, 30, 9); }

/// The car lattice of the random-block tests: 0.1 m cells, 16 headings, turns of 1.01 R_min,
/// 5 cm between samples, reversing or not.
inline CarLatticeConfig randomBlocksLattice(const FootprintChecker &fc, bool reverse = false)
{
    CarLatticeConfig cfg{0.1, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()};
    cfg.reverse = reverse;
    return cfg;
}

/// A random cell centre where the vehicle fits at one of 16 headings, with that heading.
inline Pose2 randomFree(const FootprintChecker &fc, std::mt19937 &rng)
{
    const OccupancyGrid &g = fc.grid();
    std::uniform_int_distribution<int> uc(0, g.width() - 1), ur(0, g.height() - 1);
    for (;;)
    {
        const int c = uc(rng), r = ur(rng);
        double yaw = 0;
        if (fc.fitsAtSomeHeading(g.cellCenterX(c), g.cellCenterY(r), 16, &yaw)) return {g.cellCenterX(c), g.cellCenterY(r), yaw};
    }
}

/// 20 m x 8 m at 0.05 m, free, with a block of cells [c0, c1] x [r0, r1] occupied (the margin
/// tests' room: a pillar, or a wall across it).
inline std::shared_ptr<OccupancyGrid> roomWithBlock(int c0, int r0, int c1, int r1)
{
    auto g = std::make_shared<OccupancyGrid>(400, 160, 0.05, CellState::Free);
    for (int r = r0; r <= r1; ++r)
        for (int c = c0; c <= c1; ++c) g->set(c, r, CellState::Occupied);
    return g;
}

/// One query by @p planner with @p params on @p setup, the goal's heading matched, 20 s.
inline QueryResult planWith(GridSetup &setup, const std::string &planner, const PlannerParams &params,
                            const Pose2 &start, const Pose2 &goal)
{
    const auto p = configurePlanner(setup.ss->getSpaceInformation(), {planner, params, false, false});
    return runQuery(setup, p, start, goal, 20.0, false);
}

}  // namespace gridcar::test
