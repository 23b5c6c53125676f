// CarGoal: the car lattice's goal manager (goal test, nearest state, aiming, the analytic
// expansion's end headings) for each kind of goal a query can have.
#include "gridcar/planners/search/CarGoal.h"

#include "gridcar/core/Angles.h"
#include "gridcar/planners/search/CarLattice.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;

TEST(CarGoal, GoalTestAndClosenessForEachKindOfGoal)
{
    CarGoalTerms t;
    t.goal = {3.0, 4.0, 0.5};
    const CarGoal g(t);  // a view: it sees later changes of the terms
    // a pose to reach by the analytic expansion only: no state is in the goal by itself
    EXPECT_FALSE(g.reached({3.0, 4.0, 0.5}));
    EXPECT_TRUE(g.aimed());
    EXPECT_TRUE(g.shootable());
    EXPECT_DOUBLE_EQ(g.closeness({0.0, 0.0, 0.0}), 25.0);
    EXPECT_DOUBLE_EQ(g.closeness({3.0, 1.0, 2.0}), 9.0);  // position only

    // a goal region tested at the states
    t.inGoal = [](const Pose2 &p) { return p.x > 2.0; };
    EXPECT_TRUE(g.reached({2.5, 0.0, 0.0}));
    EXPECT_FALSE(g.reached({1.5, 0.0, 0.0}));

    // a region with nothing to aim at: no shot, no heuristic; its own distance for the
    // approximate answer, or none (then every state is as near: the start is kept)
    t.aim = false;
    EXPECT_FALSE(g.aimed());
    EXPECT_FALSE(g.shootable());
    EXPECT_DOUBLE_EQ(g.closeness({0.0, 0.0, 0.0}), 0.0);
    t.goalDistance = [](const Pose2 &p) { return std::abs(p.x - 7.0); };
    EXPECT_DOUBLE_EQ(g.closeness({1.0, 100.0, 0.0}), 6.0);

    t.aim = true;
    t.shoot = false;  // a sampled region: aimed at, decided by the region
    EXPECT_TRUE(g.aimed());
    EXPECT_FALSE(g.shootable());
}

TEST(CarGoal, EndHeadingsOfTheAnalyticExpansion)
{
    const CarLattice lattice(CarLatticeConfig{0.5, 16, 2.0, 0.05, 1.0});
    CarGoalTerms t;
    t.goal = {10.0, 0.0, 1.0};
    const CarGoal g(t);
    const Pose2 from{0.0, 10.0, 0.0};

    t.goalYawTolerance = 0;  // the goal's heading exactly
    EXPECT_TRUE(g.exactHeading());
    ASSERT_EQ(g.endYaws(from, lattice, 0.3).size(), 1u);
    EXPECT_DOUBLE_EQ(g.endYaws(from, lattice, 0.3)[0], 1.0);

    t.goalYawTolerance = 0.25;  // within a tolerance: the heading and both ends of it
    EXPECT_FALSE(g.exactHeading());
    const auto within = g.endYaws(from, lattice, 0.3);
    ASSERT_EQ(within.size(), 3u);
    EXPECT_DOUBLE_EQ(within[1], 0.75);
    EXPECT_DOUBLE_EQ(within[2], 1.25);
    t.goal.yaw = M_PI - 0.1;  // wrapped into OMPL's range
    EXPECT_NEAR(g.endYaws(from, lattice, 0.3)[2], -M_PI + 0.15, 1e-12);

    t.goalYawTolerance = -1;  // any heading: the bearing to the goal and every lattice heading,
                              // turned by the lattice frame's yaw
    const auto any = g.endYaws(from, lattice, 0.3);
    ASSERT_EQ(any.size(), 1u + std::size_t(lattice.neighbourCount()));
    EXPECT_DOUBLE_EQ(any[0], -M_PI / 4);
    for (int h = 0; h < lattice.neighbourCount(); ++h)
        EXPECT_NEAR(any[std::size_t(h) + 1], wrapYaw(0.3 + lattice.stepYaw(h)), 1e-12) << h;
}
