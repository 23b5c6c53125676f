// The car lattice's table of node-to-node Reeds-Shepp / Dubins distances (CurveTable) against
// OMPL's own curve spaces, and the bound it gives to a goal between nodes (CurveTableBound)
// against the exact distance: never above it, and above the straight line where a turn is needed.
#include "gridcar/planners/search/CarLattice.h"
#include "gridcar/planners/search/CurveTable.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace
{
using gridcar::CarLattice;
using gridcar::CarLatticeConfig;
using gridcar::CurveTable;
using gridcar::CurveTableBound;
using gridcar::Pose2;

CarLatticeConfig config(bool reverse, int headings = 16)
{
    CarLatticeConfig c;
    c.cell = 0.45;
    c.headings = headings;
    c.turnRadius = 3.9;
    c.reverse = reverse;
    return c;
}

/// OMPL's shortest-curve length between two poses at radius @p r.
template <class Space>
double omplLength(const Pose2 &a, const Pose2 &b, double r)
{
    auto space = std::make_shared<Space>(r);
    ompl::base::ScopedState<ompl::base::SE2StateSpace> sa(space), sb(space);
    sa->setXY(a.x, a.y);
    sa->setYaw(a.yaw);
    sb->setXY(b.x, b.y);
    sb->setYaw(b.yaw);
    return space->distance(sa.get(), sb.get());
}

template <class Space>
void entriesMatchOmpl(bool reverse, int headings)
{
    const CarLattice lattice(config(reverse, headings));
    const CurveTable table(lattice, 6.0);
    ASSERT_EQ(table.span(), 14);
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> off(-table.span(), table.span()), head(0, headings - 1);
    for (int k = 0; k < 3000; ++k)
    {
        const int di = off(rng), dj = off(rng), hs = head(rng), hg = head(rng);
        const double d = table.distance(di, dj, hs, hg);
        const Pose2 a{di * lattice.cell(), dj * lattice.cell(), lattice.yaw(hs)}, b{0.0, 0.0, lattice.yaw(hg)};
        const double ompl = omplLength<Space>(a, b, lattice.config().turnRadius);
        // a float rounded down: never above, and within float precision below
        ASSERT_LE(d, ompl + 1e-9) << di << " " << dj << " " << hs << " " << hg;
        ASSERT_GE(d, ompl - 1e-5 * (1.0 + ompl)) << di << " " << dj << " " << hs << " " << hg;
    }
    EXPECT_GT(table.computed(), 0u);
    EXPECT_LE(table.computed(), 3000u);
}

TEST(CurveTable, ReedsSheppEntriesAreOmplsDistancesBetweenNodes) { entriesMatchOmpl<ompl::base::ReedsSheppStateSpace>(true, 16); }

TEST(CurveTable, DubinsEntriesAreOmplsDistancesBetweenNodes) { entriesMatchOmpl<ompl::base::DubinsStateSpace>(false, 16); }

TEST(CurveTable, EightHeadingsToo) { entriesMatchOmpl<ompl::base::ReedsSheppStateSpace>(true, 8); }

TEST(CurveTable, FillComputesEveryEntryOnceAndBeyondTheSpanIsNoValue)
{
    const CarLattice lattice(config(true, 8));
    const CurveTable table(lattice, 1.0);
    const double before = table.distance(1, 2, 3, 5);
    EXPECT_EQ(table.computed(), 1u);
    table.fill();
    EXPECT_EQ(table.computed(), table.size());
    // 8 headings: the goal headings of a quarter turn (2) are stored, the others turned onto them
    EXPECT_EQ(table.size(), std::size_t(7 * 7 * 8 * 2));
    EXPECT_EQ(table.distance(1, 2, 3, 5), before);
    EXPECT_LT(table.distance(table.span() + 1, 0, 0, 0), 0.0);
    EXPECT_LT(table.distance(0, -table.span() - 1, 0, 0), 0.0);
    EXPECT_EQ(table.distance(0, 0, 2, 2), 0.0);
}

// A range of a whole number of cells is that many cells, however span x cell rounds (0.45 x 89
// / 0.45 is above 89 in doubles): the search builds its table so and keeps it while the span
// stays; a table one cell wider each time was rebuilt at every run.
TEST(CurveTable, ARangeOfWholeCellsIsThatManyCells)
{
    for (double cell : {0.05, 0.3, 0.45})
    {
        CarLatticeConfig c = config(true, 8);
        c.cell = cell;
        const CarLattice lattice(c);
        for (int span = 1; span <= 120; ++span)
            ASSERT_EQ(CurveTable(lattice, span * cell).span(), span) << "cell " << cell;
        EXPECT_EQ(CurveTable(lattice, 2.5 * cell).span(), 3);
    }
}

TEST(CurveTable, RefusesAHybridLatticeAndAnAbsurdRange)
{
    CarLatticeConfig h = config(true);
    h.hybrid = true;
    EXPECT_THROW(CurveTable(CarLattice(h), 5.0), std::invalid_argument);
    const CarLattice lattice(config(true));
    EXPECT_THROW(CurveTable(lattice, 0.0), std::invalid_argument);
    EXPECT_THROW(CurveTable(lattice, std::nan("")), std::invalid_argument);
    EXPECT_THROW(CurveTable(lattice, 1e6), std::invalid_argument);  // billions of entries
}

/// Goals anywhere (between nodes, at any yaw) and nodes round them: the bound never exceeds
/// OMPL's distance from the node to the goal, and where a car must turn round it says so.
template <class Space>
void boundIsALowerBound(bool reverse)
{
    const CarLattice lattice(config(reverse));
    const CurveTable table(lattice, 12.0);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> pos(-3.0, 3.0), yaw(-M_PI, M_PI);
    std::uniform_int_distribution<int> off(-20, 20), head(0, 15);
    int informative = 0, total = 0;
    for (int g = 0; g < 40; ++g)
    {
        const Pose2 goal{pos(rng), pos(rng), yaw(rng)};
        const CurveTableBound bound(table, goal);
        ASSERT_TRUE(bound.active());
        ASSERT_EQ(bound.references(), 2);
        EXPECT_LE(bound.slack(0), bound.slack(1));
        for (int k = 0; k < 100; ++k)
        {
            const int i = off(rng), j = off(rng), h = head(rng);
            const Pose2 s{i * lattice.cell(), j * lattice.cell(), lattice.yaw(h)};
            const double exact = omplLength<Space>(s, goal, lattice.config().turnRadius);
            const double b = bound(i, j, h);
            ASSERT_GE(b, 0.0);
            ASSERT_LE(b, exact + 1e-9) << "goal " << goal.x << " " << goal.y << " " << goal.yaw << " node " << i << " "
                                       << j << " " << h;
            ++total;
            if (b > std::hypot(goal.x - s.x, goal.y - s.y) + 1.0) ++informative;
        }
    }
    // a random heading needs a turn more often than not: the bound must show it on many
    EXPECT_GT(informative, total / 4) << informative << " of " << total;
}

TEST(CurveTableBound, ReedsSheppBoundNeverExceedsTheDistanceToAGoalBetweenNodes)
{
    boundIsALowerBound<ompl::base::ReedsSheppStateSpace>(true);
}

TEST(CurveTableBound, DubinsBoundNeverExceedsTheDistanceToAGoalBetweenNodes)
{
    boundIsALowerBound<ompl::base::DubinsStateSpace>(false);
}

TEST(CurveTableBound, AGoalOnANodeHasNoSlack)
{
    const CarLattice lattice(config(true));
    const CurveTable table(lattice, 8.0);
    const CurveTableBound bound(table, {3 * lattice.cell(), -2 * lattice.cell(), lattice.yaw(5)});
    EXPECT_NEAR(bound.slack(0), 0.0, 1e-6);
    // then the bound is the table's own entry
    EXPECT_NEAR(bound(-4, 6, 9), table.distance(-4 - 3, 6 + 2, 9, 5), 1e-6);
}

}  // namespace
