#include "gridcar/path/PathMetrics.h"
#include "gridcar/path/PostProcess.h"

#include "gridcar/spaces/Setup.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;

namespace
{
/// Open 80 x 80 map of 0.25 m cells with one block in the middle (a corner to go round).
GridSetup blockSetup()
{
    auto g = std::make_shared<OccupancyGrid>(80, 80, 0.25);
    for (int r = 30; r < 80; ++r)
        for (int c = 30; c < 80; ++c) g->set(c, r, CellState::Occupied);  // lower-right quadrant blocked
    VehicleParams v = VehicleParams::preset("paper-i");
    v.length = 2.0;
    v.width = 1.0;
    v.rearOverhang = 0.4;
    v.wheelbase = 1.2;
    v.maxSteerDeg = 35;  // K_max = 0.58 1/m
    return makeGridSetup(g, v);
}

bool pathValid(const FootprintChecker &c, const std::vector<Pose2> &p)
{
    for (std::size_t i = 1; i < p.size(); ++i)
        if (!c.isMotionValid(p[i - 1], p[i])) return false;
    return true;
}

/// An L-shaped grid path round the block corner of blockSetup(), one pose per cell.
std::vector<Pose2> roundTheBlock(const OccupancyGrid &g)
{
    std::vector<Pose2> path;
    for (int c = 5; c <= 20; ++c) path.push_back({g.cellCenterX(c), g.cellCenterY(70), 0});
    for (int r = 69; r >= 12; --r) path.push_back({g.cellCenterX(20), g.cellCenterY(r), M_PI / 2});
    for (int c = 21; c <= 70; ++c) path.push_back({g.cellCenterX(c), g.cellCenterY(12), 0});
    return path;
}
}  // namespace

TEST(PostProcess, ParabolaCurvatureByHand)
{
    // y = -x^2 + 2x through (0,0), (1,1), (2,0): y'' = -2, y'(1) = 0 -> K = 2
    EXPECT_NEAR(parabolaCurvature({0, 0, 0}, {1, 1, 0}, {2, 0, 0}), 2.0, 1e-12);
    // the same triple turned by 90 degrees: vertical legs, y(x) not a function in map axes
    EXPECT_NEAR(parabolaCurvature({0, 0, 0}, {-1, 1, 0}, {0, 2, 0}), 2.0, 1e-12);
    // and turned by 30 degrees about the origin: the chord frame makes K independent of the map axes
    auto rot = [](double x, double y) {
        const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
        return Pose2{c * x - s * y, s * x + c * y, 0};
    };
    EXPECT_NEAR(parabolaCurvature(rot(0, 0), rot(1, 1), rot(2, 0)), 2.0, 1e-12);
    // an asymmetric triple by hand: (0,0), (1,1), (3,0) -> y = -x^2/2 + 3x/2: y'' = -1, y'(1) = 1/2
    EXPECT_NEAR(parabolaCurvature({0, 0, 0}, {1, 1, 0}, {3, 0, 0}), 1.0 / std::pow(1.25, 1.5), 1e-12);
    EXPECT_EQ(parabolaCurvature({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), 0.0);  // collinear
    EXPECT_TRUE(std::isinf(parabolaCurvature({0, 0, 0}, {2, 0, 0}, {0, 0, 0})));  // reversal
}

TEST(PostProcess, TurningPointsDropCollinearAndRepeatedPoints)
{
    const std::vector<Pose2> p = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 1, 0}, {4, 2, 0}, {4, 3, 0}};
    const auto t = turningPoints(p);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[1].x, 2.0);
    EXPECT_EQ(t[2].x, 4.0);
    EXPECT_EQ(t[2].y, 2.0);
}

TEST(PostProcess, BezierCornerCurvatureMatchesTheClosedForm)
{
    for (double turnDeg : {20.0, 45.0, 90.0, 135.0})
    {
        const double th = turnDeg * M_PI / 180;
        const Pose2 p0{-3, 0, 0}, p1{0, 0, 0}, p2{2 * std::cos(th), 2 * std::sin(th), 0};
        const BezierCorner bc = bezierCorner(p0, p1, p2, false, false);
        // a = half the shorter leg = 1
        EXPECT_NEAR(bc.maxCurvature, std::sin(th / 2) / std::pow(std::cos(th / 2), 2), 1e-12);
        std::vector<Pose2> samples;
        for (int i = 0; i <= 4000; ++i)
        {
            const double t = i / 4000.0, u = 1 - t;
            samples.push_back({u * u * bc.a.x + 2 * t * u * bc.p.x + t * t * bc.c.x,
                               u * u * bc.a.y + 2 * t * u * bc.p.y + t * t * bc.c.y, 0});
        }
        EXPECT_NEAR(maxMengerCurvature(samples), bc.maxCurvature, 1e-3 * bc.maxCurvature) << turnDeg;
    }
}

TEST(PostProcess, SmoothedPathIsCollisionFreeAndWithinKmaxWhereAdjusted)
{
    GridSetup s = blockSetup();
    const auto &g = *s.grid;
    const std::vector<Pose2> path = roundTheBlock(g);
    ASSERT_TRUE(pathValid(*s.checker, path));
    const double kmax = s.checker->vehicle().maxCurvature();
    SmoothingParams prm;
    prm.lineOfSight = false;  // keep both grid corners (the line of sight would cut the first)
    const SmoothingResult r = smoothPath(path, *s.checker, prm);
    ASSERT_EQ(r.corners.size(), 2u);
    EXPECT_TRUE(pathValid(*s.checker, r.path));
    for (const CornerReport &c : r.corners)
    {
        EXPECT_TRUE(c.curvatureOk) << "K " << c.bezierCurvature << " parabola " << c.parabolaCurvature;
        EXPECT_TRUE(c.smoothed);
    }
    EXPECT_EQ(r.adjustFailures, 0);
    EXPECT_EQ(r.bezierFallbacks, 0);
    // every corner succeeded, so the whole output is within K_max (Menger of the samples)
    EXPECT_LE(r.maxCurvature, kmax * 1.001);
    EXPECT_GT(r.seconds, 0.0);
    EXPECT_NEAR(r.path.front().x, path.front().x, 1e-9);
    EXPECT_NEAR(r.path.back().y, path.back().y, 1e-9);
}

TEST(PostProcess, ACancelStopsTheSmoothingAndReturnsTheInput)
{
    GridSetup s = blockSetup();
    const auto &g = *s.grid;
    const std::vector<Pose2> path = roundTheBlock(g);
    SmoothingParams prm;
    prm.lineOfSight = false;
    int calls = 0, callsAfterTrue = 0;
    prm.cancelled = [&] {
        if (calls >= 2) ++callsAfterTrue;
        return ++calls > 2;  // false twice (the start, the first corner), then true
    };
    const SmoothingResult r = smoothPath(path, *s.checker, prm);
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(callsAfterTrue, 1) << "nothing more after the condition said stop";
    ASSERT_EQ(r.path.size(), path.size());
    for (std::size_t i = 0; i < path.size(); ++i) EXPECT_EQ(r.path[i].x, path[i].x);
    prm.cancelled = [] { return false; };
    EXPECT_FALSE(smoothPath(path, *s.checker, prm).cancelled);
}

TEST(PostProcess, FailuresAreReportedNotHidden)
{
    GridSetup s = blockSetup();
    const auto &g = *s.grid;
    // a short dog-leg: two 45-degree corners 0.7 m apart, far too tight for K_max
    std::vector<Pose2> path = {{g.cellCenterX(5), g.cellCenterY(20), 0},
                               {g.cellCenterX(40), g.cellCenterY(20), 0},
                               {g.cellCenterX(42), g.cellCenterY(18), 0},
                               {g.cellCenterX(70), g.cellCenterY(18), 0}};
    ASSERT_TRUE(pathValid(*s.checker, path));
    SmoothingParams prm;
    prm.lineOfSight = false;
    prm.maxAdjustSteps = 0;  // no adjustment: both corners must be reported
    const SmoothingResult r = smoothPath(path, *s.checker, prm);
    ASSERT_EQ(r.corners.size(), 2u);
    EXPECT_TRUE(pathValid(*s.checker, r.path));
    EXPECT_EQ(r.adjustFailures, 2);
    for (const CornerReport &c : r.corners) EXPECT_FALSE(c.curvatureOk);
    EXPECT_GT(r.maxCurvature, s.checker->vehicle().maxCurvature());
    // with the adjustment the corners move apart (in free space) until both are within K_max
    prm.maxAdjustSteps = 40;
    const SmoothingResult r2 = smoothPath(path, *s.checker, prm);
    EXPECT_TRUE(pathValid(*s.checker, r2.path));
    EXPECT_LT(r2.adjustFailures, 2);
    int moved = 0;
    for (const CornerReport &c : r2.corners) moved += c.moves;
    EXPECT_GT(moved, 0);
}

TEST(PostProcess, LineOfSightRemovesStaircaseJogs)
{
    GridSetup s = blockSetup();
    const auto &g = *s.grid;
    // a staircase E, NE, E, NE ... across the free upper half
    std::vector<Pose2> path;
    int c = 2, r = 25;
    for (int i = 0; i < 20; ++i)
    {
        path.push_back({g.cellCenterX(c), g.cellCenterY(r), 0});
        c += 1;
        if (i % 2) r -= 1;
    }
    const SmoothingResult r1 = smoothPath(path, *s.checker);
    EXPECT_EQ(r1.turningPoints.size(), 2u);
    EXPECT_GT(r1.latticeTurningPoints, 10);
    EXPECT_TRUE(pathValid(*s.checker, r1.path));
}

TEST(PathMetrics, MaxCurvatureAndPathDistance)
{
    GridSetup s = blockSetup();
    const auto &g = *s.grid;
    std::vector<Pose2> line;
    for (int c = 12; c <= 20; ++c) line.push_back({g.cellCenterX(c), g.cellCenterY(10), 0});
    const PathMetrics m = computePathMetrics(line, s.checker.get());
    EXPECT_EQ(m.maxCurvature, 0.0);
    // row 10 is 10 cells below the map's top edge (the border ring is at row -1)
    EXPECT_NEAR(m.minPathDistance, 11 * 0.25, 1e-6);
    // a right angle between 1-cell segments: Menger 2 sin(90) / (0.25 sqrt 2)
    const std::vector<Pose2> corner = {{0, 0, 0}, {0.25, 0, 0}, {0.25, 0.25, 0}};
    EXPECT_NEAR(maxMengerCurvature(corner), 2.0 / (0.25 * std::sqrt(2.0)), 1e-9);
}
