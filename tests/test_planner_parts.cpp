// The planners layer as parts: new planners built from the parts in a few lines (a length-only
// car lattice, a 4-connected grid node type), and a primitive set that reverses, with its
// analytic expansion, as configuration alone.
#include "PlannerTestUtil.h"

#include "gridcar/path/PathMetrics.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/GridLatticePlanner.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/goals/GoalState.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
/// A new planner from parts: the car lattice with the default (length) cost.
class LengthLattice : public CarLatticePlanner
{
public:
    explicit LengthLattice(const ob::SpaceInformationPtr &si) : CarLatticePlanner(si, "length-lattice") {}
};

/// Successors of a cell: the 4 axis-aligned moves.
struct FourExpander
{
    const GridFamily &f;
    double heuristic(std::uint32_t s) const
    {
        int c, r;
        f.cellIndex().split(s, c, r);
        return f.stepLength(0) * (std::abs(c - f.query().goalCol) + std::abs(r - f.query().goalRow));
    }
    bool isGoal(std::uint32_t s) const
    {
        int c, r;
        f.cellIndex().split(s, c, r);
        return f.isGoal(c, r, -1);
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r;
        f.cellIndex().split(s, c, r);
        for (int d = 0; d < 8; d += 2)
            if (f.moveValid(c, r, d))
            {
                const std::uint32_t n = f.cellIndex().of(c + Moves::dcol[d], r + Moves::drow[d]);
                emit(n, f.stepLength(d), heuristic(n));
            }
    }
};

/// A new grid node type: the cell, 4-connected, Manhattan heuristic (admissible there).
class FourConnected : public GridNodes
{
public:
    std::size_t denseStates(const GridFamily &f) const override { return std::size_t(f.width()) * f.height(); }
    std::vector<std::uint32_t> starts(const GridFamily &f) override { return {f.cellIndex().of(f.query().startCol, f.query().startRow)}; }
    SearchResult search(GridFamily &f, const std::vector<std::uint32_t> &starts, const std::function<bool()> &cancelled,
                        std::atomic<std::uint64_t> *progress) override
    {
        FourExpander ex{f};
        return astar(f.dense(), starts, ex, cancelled, progress);
    }
    void decode(const GridFamily &f, std::uint32_t s, int &col, int &row, int &dir) const override
    {
        f.cellIndex().split(s, col, row);
        dir = -1;
    }
};

class FourConnectedPlanner : public GridLatticePlanner
{
public:
    explicit FourConnectedPlanner(const ob::SpaceInformationPtr &si) : GridLatticePlanner(si, "four-connected") {}

protected:
    std::unique_ptr<GridNodes> makeGridNodes() override { return std::make_unique<FourConnected>(); }
};

}  // namespace

// The length-only car lattice from parts finds a drivable path whose cost is its length, and
// the same path as corner A* with every corner weight 0 (the same search, its cost written out).
// The path as searched: without the continuous-curvature step and the shortcut, which shorten it.
TEST(PlannerParts, LengthOnlyCarLatticeFromParts)
{
    GridSetup s = test::carSetup(SpaceKind::SE2);
    test::setPlainQuery(*s.ss, 10, 30, 50, 30);
    auto parts = std::make_shared<LengthLattice>(s.ss->getSpaceInformation());
    CarLatticeSettings asSearched = parts->carSettings();
    asSearched.continuousCurvature = false;
    asSearched.shortcut = AutoSwitch::Off;
    parts->setCarSettings(asSearched);
    s.ss->setPlanner(parts);
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    const std::vector<Pose2> path = toPoses(s.ss->getSolutionPath());
    const Drivability dv = checkDrivable(path, *s.checker);
    EXPECT_TRUE(dv.drivable) << dv.reason;
    // the cost is the primitives' arc length; the polyline through their samples is a little
    // shorter (chords), never longer
    EXPECT_LE(pathLength(path), parts->lastCost() * (1 + 1e-12));
    EXPECT_NEAR(parts->lastCost(), pathLength(path), 1e-4 * parts->lastCost());
    EXPECT_GT(parts->lastCost(), 40.0);  // round the wall, longer than the chord
    const double partsCost = parts->lastCost();
    const std::uint64_t partsExpanded = parts->expandedNodes();

    s.ss->clear();
    auto corner = std::make_shared<CornerAStar>(s.ss->getSpaceInformation());
    for (const char *w : {"corner_weight_45", "corner_weight_90", "corner_weight_135"})
        ASSERT_TRUE(corner->params().setParam(w, "0"));
    ASSERT_TRUE(corner->params().setParam("shortcut", "off"));
    s.ss->setPlanner(corner);
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_DOUBLE_EQ(corner->lastCost(), partsCost);
    EXPECT_EQ(corner->expandedNodes(), partsExpanded);
}

// A grid node type from parts: axis-aligned moves only, and an optimal 4-connected path:
// its cost is the Manhattan length of its moves and no less than the 8-connected optimum.
TEST(PlannerParts, FourConnectedGridNodeTypeFromParts)
{
    GridSetup s = test::testSetup();
    // both in the left half of the test map (x < 15 m): open floor between them
    test::setPlainQuery(*s.ss, 1.25, 1.25, 13.25, 15.25);
    auto four = std::make_shared<FourConnectedPlanner>(s.ss->getSpaceInformation());
    s.ss->setPlanner(four);
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    const std::vector<Pose2> path = toPoses(s.ss->getSolutionPath());
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const double dx = std::abs(path[i].x - path[i - 1].x), dy = std::abs(path[i].y - path[i - 1].y);
        EXPECT_TRUE(dx < 1e-9 || dy < 1e-9) << "a diagonal step at " << i;
    }
    EXPECT_NEAR(four->lastCost(), pathLength(path), 1e-9);
    EXPECT_NEAR(four->lastCost(), 0.5 * (24 + 28), 1e-9);  // |dx| + |dy| in cells x 0.5 m: open floor
    const double fourCost = four->lastCost();

    s.ss->clear();
    auto dijkstra = makePlanner(s.ss->getSpaceInformation(), "dijkstra");
    s.ss->setPlanner(dijkstra);
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_LT(dynamic_cast<GridPlanner &>(*dijkstra).lastCost(), fourCost);
}

// A grid-lattice planner whose node type is missing says so with a message, not a crash.
TEST(PlannerParts, APlannerWithoutGridNodesSaysSo)
{
    class NoGrid : public GridLatticePlanner
    {
    public:
        explicit NoGrid(const ob::SpaceInformationPtr &si) : GridLatticePlanner(si, "no-grid") {}

    protected:
        std::unique_ptr<GridNodes> makeGridNodes() override { return nullptr; }
    };
    GridSetup s = test::testSetup();
    auto p = std::make_shared<NoGrid>(s.ss->getSpaceInformation());
    try
    {
        p->setup();
        FAIL() << "setup() accepted a planner without a grid node type";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("no grid-lattice node type"), std::string::npos) << e.what();
    }
}

// Reversing is configuration plus primitives: in a dead-end street too narrow to turn in,
// facing its closed end, the forward lattice cannot reach the open square behind the car; the
// same search with `reverse` (its analytic expansion then Reeds-Shepp) backs out, drivably.
TEST(PlannerParts, ReversePrimitivesBackOutOfADeadEnd)
{
    auto g = std::make_shared<OccupancyGrid>(300, 120, 0.1, CellState::Free);
    for (int r = 0; r < g->height(); ++r)
        for (int c = 0; c < g->width(); ++c)
        {
            const double x = g->cellCenterX(c), y = g->cellCenterY(r);
            if (x >= 8.0 && (y < 4.7 || y > 7.3 || x >= 25.0)) g->set(c, r, CellState::Occupied);
        }
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-i"));
    const Pose2 start{18.0, 6.0, 0.0}, goal{4.0, 6.0, 0.0};
    ASSERT_TRUE(fc.isValid(start));
    ASSERT_TRUE(fc.isValid(goal));
    CarLatticeQuery q;
    q.start = start;
    q.goal = goal;
    q.goalYawTolerance = 0.0;
    CarLatticeConfig cfg{0.2, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()};
    LengthCost length;
    const CarLatticeResult forward =
        CarLatticeSearch(fc, std::make_shared<const CarLattice>(cfg)).run(q, length, [] { return false; });
    EXPECT_FALSE(forward.exact);
    cfg.reverse = true;
    const CarLatticeResult back =
        CarLatticeSearch(fc, std::make_shared<const CarLattice>(cfg)).run(q, length, [] { return false; });
    ASSERT_TRUE(back.exact);
    int backwards = 0;
    for (std::size_t i = 1; i < back.path.size(); ++i)
    {
        const double dx = back.path[i].x - back.path[i - 1].x, dy = back.path[i].y - back.path[i - 1].y;
        if (dx * std::cos(back.path[i].yaw) + dy * std::sin(back.path[i].yaw) < 0) ++backwards;
    }
    EXPECT_GT(backwards, 0);
    DrivabilityOptions o;
    o.reversing = true;
    const Drivability dv = checkDrivable(back.path, fc, o);
    EXPECT_TRUE(dv.drivable) << dv.reason;
    EXPECT_NEAR(back.path.back().x, goal.x, 1e-9);
    EXPECT_NEAR(back.path.back().y, goal.y, 1e-9);
    EXPECT_LT(back.cost, 14.0 * 1.2);  // about the 14 m straight back, not a detour
}
