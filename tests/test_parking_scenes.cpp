// The generated parking scenes (map/ParkingScenes.h): sizes as stated, start and goal poses free
// for the car they were made for, the same scenes every time, bad sizes refused.
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/ParkingScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <stdexcept>

using namespace gridcar;

namespace
{
FootprintChecker checkerFor(const ParkingScene &s, const VehicleParams &v)
{
    auto grid = std::make_shared<const OccupancyGrid>(s.grid);
    return FootprintChecker(grid, std::make_shared<const DistanceField>(*grid), v);
}
}  // namespace

TEST(ParkingScenes, EveryQueryStartsAndEndsWhereTheCarFitsForBothCars)
{
    for (const char *name : {"paper-c-car", "paper-i"})
    {
        const VehicleParams v = VehicleParams::preset(name);
        const auto scenes = parkingScenes(v);
        ASSERT_EQ(scenes.size(), 4u);
        std::set<std::string> queryNames;
        for (const ParkingScene &s : scenes)
        {
            EXPECT_DOUBLE_EQ(s.grid.resolution(), 0.05);
            EXPECT_GE(s.queries.size(), 2u) << s.name;
            const FootprintChecker fc = checkerFor(s, v);
            for (const ParkingQuery &q : s.queries)
            {
                EXPECT_TRUE(queryNames.insert(q.name).second) << q.name;
                EXPECT_EQ(q.name.rfind(s.name + "/", 0), 0u) << q.name;
                EXPECT_TRUE(fc.isValidExact(q.start.x, q.start.y, q.start.yaw)) << name << " " << q.name << " start";
                EXPECT_TRUE(fc.isValidExact(q.goal.x, q.goal.y, q.goal.yaw)) << name << " " << q.name << " goal";
            }
            // the parked cars are obstacles: the car does not fit where one of them stands
            for (const Pose2 &p : s.parkedCars) EXPECT_FALSE(fc.isValidExact(p.x, p.y, p.yaw)) << s.name;
        }
        EXPECT_EQ(queryNames.size(), 12u);
    }
}

TEST(ParkingScenes, TheSlotsAndTheGapHaveTheStatedSizes)
{
    const VehicleParams v = VehicleParams::preset("paper-c-car");
    const auto scenes = parkingScenes(v);
    // perpendicular: the parked cars of one row stand a slot width (car width + 0.8 m) apart
    const ParkingScene &perp = scenes[0];
    ASSERT_EQ(perp.name, "perpendicular");
    EXPECT_NEAR(std::abs(perp.parkedCars[1].x - perp.parkedCars[3].x), 2.6, 1e-9);
    // parallel: 1.5 car lengths of curb between the two cars round the gap
    const ParkingScene &par = scenes[1];
    ASSERT_EQ(par.name, "parallel");
    const double behindFront = par.parkedCars[0].x + v.length - v.rearOverhang;
    const double aheadRear = par.parkedCars[2].x - v.rearOverhang;
    EXPECT_NEAR(aheadRear - behindFront, 1.5 * v.length, 1e-9);
    // dead end: free 7 m across, a wall at its far end
    const ParkingScene &dead = scenes[2];
    ASSERT_EQ(dead.name, "dead-end");
    const OccupancyGrid &g = dead.grid;
    int freeAcross = 0;
    const Cell mid = g.worldToCell(20.0, g.originY() + g.sizeY() / 2);
    for (int r = 0; r < g.height(); ++r) freeAcross += !g.isBlocked(mid.col, r);
    EXPECT_NEAR(freeAcross * g.resolution(), 7.0, 2 * g.resolution());
}

TEST(ParkingScenes, TheSameEveryTimeAndBadSizesRefused)
{
    const VehicleParams v = VehicleParams::preset("paper-i");
    const auto a = parkingScenes(v), b = parkingScenes(v);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(a[k].grid.cells() == b[k].grid.cells()) << a[k].name;
    ParkingSceneParams p;
    p.resolution = 0;
    EXPECT_THROW(parkingScenes(v, p), std::invalid_argument);
    p = ParkingSceneParams();
    p.streetWidth = 1.0;
    EXPECT_THROW(parkingScenes(v, p), std::invalid_argument);
    EXPECT_THROW(parkingScenes(VehicleParams::preset("point")), std::invalid_argument);
}
