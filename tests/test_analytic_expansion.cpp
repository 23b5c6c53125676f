// AnalyticExpansion: when the car lattice's shot to the goal is tried, which curves it takes
// (Dubins, Reeds-Shepp when the lattice reverses, clothoid turns with a curvature rate), that
// they are free and end at the goal pose, and what they cost.
#include "PlannerTestUtil.h"

#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/planners/search/AnalyticExpansion.h"
#include "gridcar/planners/search/CarLatticeSearch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace gridcar;

namespace
{
/// An empty 20 m x 20 m map at 0.1 m, origin (0, 0), and paper C's robot on it.
struct OpenMap
{
    std::shared_ptr<OccupancyGrid> grid{std::make_shared<OccupancyGrid>(200, 200, 0.1, CellState::Free)};
    std::shared_ptr<DistanceField> field;
    std::unique_ptr<FootprintChecker> checker;
    std::unique_ptr<FootprintCollision> col;
    OpenMap()
    {
        field = std::make_shared<DistanceField>(*grid);
        checker = std::make_unique<FootprintChecker>(grid, field, VehicleParams::preset("paper-c-robot"));
        col = std::make_unique<FootprintCollision>(*checker);
    }
    void wall(int c0, int r0, int c1, int r1)
    {
        for (int r = r0; r <= r1; ++r)
            for (int c = c0; c <= c1; ++c) grid->set(c, r, CellState::Occupied);
        field = std::make_shared<DistanceField>(*grid);
        checker = std::make_unique<FootprintChecker>(grid, field, VehicleParams::preset("paper-c-robot"));
        col = std::make_unique<FootprintCollision>(*checker);
    }
    CarLatticeConfig lattice(bool reverse = false, double rate = 0.0) const
    {
        CarLatticeConfig cfg = test::randomBlocksLattice(*checker, reverse);
        cfg.curvatureRate = rate;
        return cfg;
    }
    /// Every pose of @p from + @p poses free, curvature within the turning radius.
    void expectDrivable(const Pose2 &from, const std::vector<Pose2> &poses, bool reversing) const
    {
        std::vector<Pose2> path{from};
        path.insert(path.end(), poses.begin(), poses.end());
        DrivabilityOptions o;
        o.reversing = reversing;
        const Drivability d = checkDrivable(path, *checker, o);
        EXPECT_TRUE(d.drivable) << d.reason;
    }
};
}  // namespace

TEST(AnalyticExpansion, TriedNearTheGoalAlwaysFartherOutEveryEighthUnlessSomethingIsInTheWay)
{
    OpenMap m;
    const CarLattice lattice(m.lattice());
    const AnalyticExpansion shot(*m.col, lattice);
    const double R = lattice.config().turnRadius, c = lattice.cell();
    const Pose2 goal{10, 10, 0};
    int asked = 0;
    const auto free = [&] { return ++asked, std::hypot(5.0, 0.0); };  // the straight line: nothing in the way
    // near: at any expansion, the obstacle distance not asked
    EXPECT_EQ(shot.due({10 + 2 * R, 10, 0}, goal, 3, free), AnalyticExpansion::Range::Near);
    EXPECT_EQ(asked, 0);
    // out of range: never
    EXPECT_EQ(shot.due({10 + 30 * R + 10 * c + 0.01, 10, 0}, goal, 8, free), AnalyticExpansion::Range::Out);
    // between: every 8th expansion, where the obstacle-aware distance is near the straight line
    const Pose2 far{15, 10, 0};
    ASSERT_GT(5.0, 2 * R + 2 * c);
    EXPECT_EQ(shot.due(far, goal, 7, free), AnalyticExpansion::Range::Out);
    EXPECT_EQ(asked, 0);
    EXPECT_EQ(shot.due(far, goal, 16, free), AnalyticExpansion::Range::Far);
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(shot.due(far, goal, 16, [] { return 1.1 * 5.0 + 0.0; }), AnalyticExpansion::Range::Far);
    EXPECT_EQ(shot.due(far, goal, 16, [&] { return 1.1 * 5.0 + R + 0.01; }), AnalyticExpansion::Range::Out);
    EXPECT_EQ(shot.due(far, goal, 16, [] { return -1.0; }), AnalyticExpansion::Range::Far);  // no 2D distance
}

TEST(AnalyticExpansion, AFreeDubinsCurveEndsExactlyAtTheGoalPose)
{
    OpenMap m;
    const CarLattice lattice(m.lattice());
    const AnalyticExpansion shot(*m.col, lattice);
    EXPECT_EQ(shot.clothoidTurns(), nullptr);
    CarLatticeQuery q;
    q.start = {4, 4, 0};
    q.goal = {9, 7, M_PI / 2};
    q.goalYawTolerance = 0;
    LengthCost cost;
    AnalyticShot out;
    int tried = 0;
    ASSERT_TRUE(shot.shoot(q.start, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_GE(tried, 1);
    ASSERT_FALSE(out.poses.empty());
    EXPECT_EQ(out.poses.back().x, 9.0);
    EXPECT_EQ(out.poses.back().y, 7.0);
    EXPECT_EQ(out.poses.back().yaw, M_PI / 2);
    // forwards only, no penalty: the cost is the curve's length (the poses sample it)
    std::vector<Pose2> all{q.start};
    all.insert(all.end(), out.poses.begin(), out.poses.end());
    EXPECT_NEAR(out.cost, pathLength(all), 0.02 * out.cost);
    EXPECT_GE(out.cost, std::hypot(5.0, 3.0));
    m.expectDrivable(q.start, out.poses, false);
    // the termination condition fired: no shot
    const std::function<bool()> stop = [] { return true; };
    EXPECT_FALSE(shot.shoot(q.start, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, &stop, out, tried));
}

TEST(AnalyticExpansion, ABlockedCurveIsRefused)
{
    OpenMap m;
    m.wall(60, 0, 62, 199);  // a wall across the whole map at x = 6.0-6.3 m: nothing gets through
    const CarLattice lattice(m.lattice());
    const AnalyticExpansion shot(*m.col, lattice);
    CarLatticeQuery q;
    q.goal = {9, 10, 0};
    q.goalYawTolerance = -1;  // any heading: several end yaws, the shortest curves of each tried
    LengthCost cost;
    AnalyticShot out;
    int tried = 0;
    EXPECT_FALSE(shot.shoot({3, 10, 0}, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_EQ(tried, 3);  // near the goal, forwards: the three shortest
    tried = 0;
    EXPECT_FALSE(shot.shoot({3, 10, 0}, 0, q, 0.0, AnalyticExpansion::Range::Far, cost, nullptr, out, tried));
    EXPECT_EQ(tried, 1);  // farther out: the shortest only
    // the free check itself, poses half the lattice's spacing apart: through the wall, and short of it
    const double ds = lattice.config().spacing / 2;
    EXPECT_FALSE(shot.free({3, 10, 0}, int(6 / ds), [&](int i) { return Pose2{3 + ds * i, 10, 0}; }, nullptr));
    EXPECT_TRUE(shot.free({7, 10, 0}, int(2 / ds), [&](int i) { return Pose2{7 + ds * i, 10, 0}; }, nullptr));
    // beyond the wall the same curve is found
    ASSERT_TRUE(shot.shoot({7, 10, 0}, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_NEAR(out.cost, 2.0, 1e-9);
}

TEST(AnalyticExpansion, AReversingLatticeShootsReedsSheppCurvesCostedWithItsPenalties)
{
    OpenMap m;
    const CarLattice lattice(m.lattice(true));
    const AnalyticExpansion shot(*m.col, lattice);
    CarLatticeQuery q;
    q.goal = {8, 10, 0};  // straight behind the start, same heading: backing up is the curve
    q.goalYawTolerance = 0;
    q.settings.reversePenalty = 2.0;
    q.cuspPenalty = 1.5;
    LengthCost cost;
    AnalyticShot out;
    int tried = 0;
    const Pose2 from{10, 10, 0};
    ASSERT_TRUE(shot.shoot(from, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_EQ(out.poses.back().x, 8.0);
    EXPECT_NEAR(out.cost, 2.0 * 2.0, 1e-9);  // 2 m backwards at twice the cost
    m.expectDrivable(from, out.poses, true);
    // reached forwards, it sets off backwards: a gear change more
    ASSERT_TRUE(shot.shoot(from, 1, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_NEAR(out.cost, 4.0 + 1.5, 1e-9);
    // searched from the goal back (time reversed): the same motion is driven forwards
    q.timeReversed = true;
    ASSERT_TRUE(shot.shoot(from, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_NEAR(out.cost, 2.0, 1e-9);
}

TEST(AnalyticExpansion, WithClothoidTurnsTheShotKeepsTheCurvatureRate)
{
    OpenMap m;
    const double rate = 0.5;
    const CarLattice lattice(m.lattice(false, rate));
    const AnalyticExpansion shot(*m.col, lattice);
    ASSERT_NE(shot.clothoidTurns(), nullptr);
    CarLatticeQuery q;
    q.goal = {14, 12, M_PI / 2};
    q.goalYawTolerance = 0;
    LengthCost cost;
    AnalyticShot out;
    int tried = 0;
    const Pose2 from{5, 5, 0};
    ASSERT_TRUE(shot.shoot(from, 0, q, 0.0, AnalyticExpansion::Range::Near, cost, nullptr, out, tried));
    EXPECT_EQ(out.poses.back().yaw, M_PI / 2);
    std::vector<Pose2> all{from};
    all.insert(all.end(), out.poses.begin(), out.poses.end());
    const CurvatureProfile p = curvatureRateProfile(all);
    EXPECT_LE(p.maxRate, rate * 1.05);
    EXPECT_LE(p.maxCurvature, 1.0 / lattice.config().turnRadius * 1.01);
    m.expectDrivable(from, out.poses, false);
}
