// The independent drivability check (path/Drivability.h).
#include "gridcar/path/Drivability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gridcar;

namespace
{
struct World
{
    std::shared_ptr<OccupancyGrid> grid;
    std::shared_ptr<DistanceField> field;
    std::unique_ptr<FootprintChecker> checker;
};

/// 80 m x 40 m free, with a wall at x = 40 m from y = 0 to y = 20 m.
World world(const std::string &vehicle)
{
    World w;
    w.grid = std::make_shared<OccupancyGrid>(800, 400, 0.1, CellState::Free);
    for (int r = 200; r < 400; ++r)
        for (int c = 400; c < 405; ++c) w.grid->set(c, r, CellState::Occupied);
    w.field = std::make_shared<DistanceField>(*w.grid);
    w.checker = std::make_unique<FootprintChecker>(w.grid, w.field, VehicleParams::preset(vehicle));
    return w;
}

std::vector<Pose2> arc(double cx, double cy, double r, double a0, double a1, int n)
{
    std::vector<Pose2> p;
    for (int k = 0; k <= n; ++k)
    {
        const double a = a0 + (a1 - a0) * k / n;
        p.push_back({cx + r * std::cos(a), cy + r * std::sin(a), a + M_PI / 2});
    }
    return p;
}
}  // namespace

TEST(Drivability, StraightPathInTheOpenIsDrivable)
{
    const World w = world("paper-i");
    const Drivability d = checkDrivable({{10, 30, 0}, {70, 30, 0}}, *w.checker);
    EXPECT_TRUE(d.drivable) << d.reason;
    EXPECT_GE(d.posesChecked, 3000) << "60 m at 2 cm";
    EXPECT_EQ(d.firstCollision, -1.0);
}

TEST(Drivability, ACancelStopsTheCheckWithoutAVerdictOfDrivable)
{
    const World w = world("paper-i");
    std::vector<Pose2> path;
    for (int i = 0; i <= 600; ++i) path.push_back({10 + 0.1 * i, 30, 0});  // 60 m, 600 segments
    DrivabilityOptions o;
    o.cancelled = [] { return true; };
    const Drivability d = checkDrivable(path, *w.checker, o);
    EXPECT_FALSE(d.drivable);
    EXPECT_NE(d.reason.find("stopped"), std::string::npos) << d.reason;
    EXPECT_LT(d.posesChecked, 1000) << "stopped at the first poll, not after 3000 poses";
    o.cancelled = [] { return false; };
    EXPECT_TRUE(checkDrivable(path, *w.checker, o).drivable);
}

TEST(Drivability, APathThroughTheWallIsNotAndSaysWhere)
{
    const World w = world("paper-i");
    const Drivability d = checkDrivable({{10, 10, 0}, {70, 10, 0}}, *w.checker);
    EXPECT_FALSE(d.drivable);
    // the front bumper (4.3 m ahead of the rear axle for paper I's car) reaches x = 40 m first
    EXPECT_GT(d.firstCollision, 40.0 - 10.0 - 4.5);
    EXPECT_LT(d.firstCollision, 40.0 - 10.0 - 3.5);
    EXPECT_NE(d.reason.find("hits an obstacle"), std::string::npos);
}

TEST(Drivability, CurvatureAboveKmaxIsNotDrivable)
{
    const World w = world("paper-i");
    const double rmin = VehicleParams::preset("paper-i").minTurningRadius();
    const Drivability wide = checkDrivable(arc(60, 25, 1.5 * rmin, -M_PI / 2, 0, 200), *w.checker);
    EXPECT_TRUE(wide.drivable) << wide.reason;
    const Drivability tight = checkDrivable(arc(60, 25, 0.6 * rmin, -M_PI / 2, 0, 200), *w.checker);
    EXPECT_FALSE(tight.drivable);
    EXPECT_NE(tight.reason.find("exceeds K_max"), std::string::npos) << tight.reason;
    // a grid path's sharp corner
    const Drivability corner = checkDrivable({{50, 25, 0}, {60, 25, 0}, {60, 33, M_PI / 2}}, *w.checker);
    EXPECT_FALSE(corner.drivable);
    EXPECT_NE(corner.reason.find("too sharp"), std::string::npos) << "long legs do not make a kink drivable: " << corner.reason;
    // the same quarter circle sampled coarsely (1 m apart) is still within 2 cm of a drivable curve
    const Drivability coarse = checkDrivable(arc(60, 25, 2.0 * rmin, -M_PI / 2, 0, 8), *w.checker);
    EXPECT_TRUE(coarse.drivable) << coarse.reason;
}

TEST(Drivability, APointVehicleHasNoCurvatureLimit)
{
    const World w = world("point");
    EXPECT_TRUE(checkDrivable({{50, 30, 0}, {60, 30, 0}, {60, 38, M_PI / 2}}, *w.checker).drivable);
    EXPECT_FALSE(checkDrivable({{30, 10, 0}, {50, 10, 0}}, *w.checker).drivable);
}

// A pose repeated to within a micron (a curve's end sampled twice, rounding apart) is the same
// pose: it makes no curvature, no curvature rate and no kink (before, a 1e-7 m step's heading,
// at right angles to the path, counted as a turn of 90 degrees over 1e-7 m).
TEST(Drivability, APoseRepeatedWithinAMicronIsOnePose)
{
    const World w = world("paper-i");
    std::vector<Pose2> path;
    for (int i = 0; i <= 100; ++i)
    {
        path.push_back({10 + 0.1 * i, 30, 0});
        if (i == 50) path.push_back({10 + 0.1 * i, 30 + 1e-7, 0});
    }
    DrivabilityOptions o;
    o.maxCurvatureRate = 0.5;
    const Drivability d = checkDrivable(path, *w.checker, o);
    EXPECT_TRUE(d.drivable) << d.reason;
    EXPECT_LT(d.maxCurvature, 1e-6);
    EXPECT_LT(d.maxCurvatureRate, 1e-6);
}
