// CarLatticeSearch and the planners on it: the obstacle-aware heuristic against exhaustive
// search, drivable paths of every car-lattice planner, free start and goal heading, PositionGoal.
#include "PlannerTestUtil.h"

#include "gridcar/path/PathMetrics.h"
#include "gridcar/core/Angles.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/ParkingScenes.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace gridcar;
using test::randomBlocks;
using test::randomFree;
namespace ob = ompl::base;

// The heuristic's claim: h(start) - seed radius <= the cheapest lattice path into the goal
// region (nodes within the seed radius of the goal), found here by exhaustive search (Dijkstra
// order: the same search with no heuristic). A* with the heuristic must then find that cost too.
TEST(CarLatticeSearch, HeuristicIsALowerBoundAgainstExhaustiveSearchOnRandomMaps)
{
    double worstRatio = 0, worstAstar = 0;
    int compared = 0;
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        for (int headings : {8, 16})
        {
            auto lattice = std::make_shared<const CarLattice>(
                CarLatticeConfig{0.1, headings, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()});
            CarLatticeSearch search(fc, lattice);
            std::mt19937 rng(seed * 31 + unsigned(headings));
            for (int k = 0; k < 4; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.shoot = false;
                const double radius = 1.5 * lattice->cell();
                q.inGoal = [&](const Pose2 &p) { return std::hypot(p.x - q.goal.x, p.y - q.goal.y) <= radius; };
                LengthCost cost;
                const CarLatticeResult a = search.run(q, cost, [] { return false; });
                const double h = search.heuristicAt(0, 0);
                CarLatticeQuery blind = q;
                blind.aim = false;
                const CarLatticeResult d = search.run(blind, cost, [] { return false; });
                ASSERT_EQ(a.exact, d.exact) << "seed " << seed;
                if (!d.exact) continue;
                ++compared;
                EXPECT_LE(h - radius, d.cost * (1 + 1e-9)) << "seed " << seed << " headings " << headings;
                worstRatio = std::max(worstRatio, (h - radius) / d.cost);
                worstAstar = std::max(worstAstar, a.cost / d.cost);
                // closed states stay closed (Hybrid A*), and the Euclidean part overestimates by up
                // to the goal radius inside the region: near-optimal, not optimal
                EXPECT_LE(a.cost, d.cost * 1.06);
                EXPECT_LE(a.expanded, d.expanded);
            }
        }
    }
    EXPECT_GT(compared, 20);
    std::printf("heuristic: worst (h - seed radius) / exhaustive optimum %.3f, worst A* / optimum %.6f over %d queries\n",
                worstRatio, worstAstar, compared);
}

// A cost model in other units than metres whose 2D search is not weighted (as corner-astar's
// cost=time, seconds): the obstacle heuristic's metres are scaled by the model's least cost per
// metre, so the search still finds the optimum. Read as metres they overestimated V times (5
// here), and the search returned paths far costlier than the optimum.
TEST(CarLatticeSearch, HeuristicIsALowerBoundForACostInOtherUnits)
{
    struct Seconds : LatticeCostModel
    {
        double stepCost(const Pose2 &, const std::vector<Pose2> &, double length, double) const override { return length / 5.0; }
        double minCostPerMetre() const override { return 1.0 / 5.0; }
    };
    int compared = 0;
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        auto lattice = std::make_shared<const CarLattice>(
            test::randomBlocksLattice(fc));
        CarLatticeSearch search(fc, lattice);
        std::mt19937 rng(seed * 13);
        for (int k = 0; k < 4; ++k)
        {
            CarLatticeQuery q;
            q.start = randomFree(fc, rng);
            q.goal = randomFree(fc, rng);
            q.shoot = false;
            const double radius = 1.5 * lattice->cell();
            q.inGoal = [&](const Pose2 &p) { return std::hypot(p.x - q.goal.x, p.y - q.goal.y) <= radius; };
            Seconds cost;
            const CarLatticeResult a = search.run(q, cost, [] { return false; });
            const double h = search.heuristicAt(0, 0);
            CarLatticeQuery blind = q;
            blind.aim = false;
            const CarLatticeResult d = search.run(blind, cost, [] { return false; });
            ASSERT_EQ(a.exact, d.exact) << "seed " << seed;
            if (!d.exact) continue;
            ++compared;
            // heuristicAt() is in metres (LengthCost): the bound in this model's seconds is a fifth
            EXPECT_LE((h - radius) / 5.0, d.cost * (1 + 1e-9)) << "seed " << seed << " query " << k;
            // the search aimed by it finds the optimum as with a cost in metres
            EXPECT_LE(a.cost, d.cost * 1.06) << "seed " << seed << " query " << k;
        }
    }
    EXPECT_GT(compared, 5);
}

TEST(CarLatticeSearch, EveryCarLatticePlannerReturnsDrivablePathsOnTheCampus)
{
    auto grid = std::make_shared<const OccupancyGrid>(generateCampus());
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-i"));
    std::mt19937 rng(7);
    const std::vector<std::pair<std::string, PlannerParams>> planners = {
        {"improved-astar", {{"mode", "paper"}}}, {"improved-astar", {{"mode", "integral"}}}, {"corner-astar", {}}};
    for (const auto &[name, params] : planners)
    {
        auto p = configurePlanner(s.ss->getSpaceInformation(), {name, params, true, false});
        int exact = 0;
        for (int k = 0; k < 5; ++k)
        {
            const Pose2 a = randomFree(*s.checker, rng), b = randomFree(*s.checker, rng);
            const QueryResult r = runQuery(s, p, a, b, 20.0, /*freeGoalHeading=*/true);  // a random yaw means nothing
            if (r.status != ob::PlannerStatus::EXACT_SOLUTION) continue;
            ++exact;
            // independent: exact FCL at 2 cm, curvature <= K_max
            EXPECT_TRUE(r.drivability.drivable) << name << ": " << r.drivability.reason;
            EXPECT_NEAR(r.path.back().x, b.x, 1e-9);
            EXPECT_NEAR(r.path.back().y, b.y, 1e-9);
            EXPECT_NEAR(r.path.front().x, a.x, 1e-9);
        }
        EXPECT_GE(exact, 4) << name;
    }
}

/// A 40 m x 20 m map whose only free space is a north-south corridor 3 m wide and an east-west
/// street 8 m wide at its top: the 4.5 m car fits in the corridor only heading north or south.
std::shared_ptr<OccupancyGrid> corridorMap()
{
    auto g = std::make_shared<OccupancyGrid>(400, 200, 0.1, CellState::Occupied);
    for (int r = 20; r < 190; ++r)
        for (int c = 185; c < 215; ++c) g->set(c, r, CellState::Free);  // corridor x in [18.5, 21.5]
    for (int r = 10; r < 90; ++r)
        for (int c = 20; c < 380; ++c) g->set(c, r, CellState::Free);  // street, y in [11, 19]
    return g;
}

TEST(CarLatticeSearch, FreeStartAndGoalHeadingInANorthSouthCorridor)
{
    GridSetup s = makeGridSetup(corridorMap(), VehicleParams::preset("paper-c-car"));
    const Pose2 start{20.0, 3.0, 0.0}, goal{10.0, 15.0, 0.0};
    ASSERT_FALSE(s.checker->isValid(start));  // sideways: no
    double yaw = 0;
    ASSERT_TRUE(s.checker->fitsAtSomeHeading(start.x, start.y, 72, &yaw));
    const std::vector<std::pair<std::string, PlannerParams>> planners = {
        {"improved-astar", {{"mode", "paper"}}}, {"improved-astar", {{"mode", "integral"}}}, {"corner-astar", {}}};
    for (const auto &[name, params] : planners)
    {
        auto p = configurePlanner(s.ss->getSpaceInformation(), {name, params, true, false});
        const QueryResult r = runQuery(s, p, {start.x, start.y, yaw}, goal, 20.0, /*freeGoalHeading=*/true);
        EXPECT_EQ(r.status, ob::PlannerStatus::EXACT_SOLUTION)
            << name << " " << params[0].second << " ends at " << r.path.back().x << "," << r.path.back().y;
        if (r.status != ob::PlannerStatus::EXACT_SOLUTION) continue;
        EXPECT_TRUE(r.drivability.drivable) << name << ": " << r.drivability.reason;
        EXPECT_NEAR(std::abs(wrapAngle(r.path.front().yaw)), M_PI / 2, 1e-9) << name;  // drives north
    }
}

TEST(CarLatticeSearch, PositionGoalWithAndWithoutHeadingTolerance)
{
    GridSetup s = makeGridSetup(corridorMap(), VehicleParams::preset("paper-c-car"));
    auto si = s.ss->getSpaceInformation();
    auto p = std::make_shared<ImprovedAStar>(si);
    p->setFreeStartHeading(true);
    s.ss->setPlanner(p);
    ob::ScopedState<ob::SE2StateSpace> st(s.space);
    st->setXY(20.0, 3.0);
    st->setYaw(M_PI / 2);
    s.ss->setStartState(st);
    // any heading, exact position
    s.ss->setGoal(std::make_shared<PositionGoal>(si, 30.0, 15.0, 0.0));
    ASSERT_EQ(s.ss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION);
    Pose2 end = toPose(s.ss->getSolutionPath().getState(s.ss->getSolutionPath().getStateCount() - 1));
    EXPECT_NEAR(end.x, 30.0, 1e-9);
    EXPECT_NEAR(end.y, 15.0, 1e-9);
    // heading west within 10 degrees: the car must turn round in the street
    s.ss->clear();
    s.ss->setGoal(std::make_shared<PositionGoal>(si, 10.0, 15.0, 0.3, M_PI, 10 * M_PI / 180));
    ASSERT_EQ(s.ss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION);
    const auto &path = s.ss->getSolutionPath();
    end = toPose(path.getState(path.getStateCount() - 1));
    EXPECT_LE(std::hypot(end.x - 10.0, end.y - 15.0), 0.3);
    EXPECT_LE(std::abs(wrapAngle(end.yaw - M_PI)), 10 * M_PI / 180 + 1e-9);
    EXPECT_TRUE(checkDrivable(toPoses(path), *s.checker).drivable);
    // an OMPL sampling planner can aim at it too
    PositionGoal free(si, 30.0, 15.0, 0.5);
    ob::ScopedState<ob::SE2StateSpace> sample(s.space);
    free.sampleGoal(sample.get());
    EXPECT_TRUE(si->isValid(sample.get()));
    EXPECT_TRUE(free.isSatisfied(sample.get()));
    EXPECT_THROW(PositionGoal(si, 0, 0, -1), std::invalid_argument);
}

// A cost model that depends on a motion's shape alone (LatticeCostModel::shapeOnly()) is asked
// once per primitive, and the search finds the same path and cost as when it is asked for
// every motion: the lengths and heading changes of a primitive do not depend on where it is.
TEST(CarLatticeSearch, AShapeOnlyCostIsAskedOncePerPrimitiveAndChangesNothing)
{
    struct Counting : LatticeCostModel
    {
        bool shape{false};
        mutable long calls{0};
        double stepCost(const Pose2 &from, const std::vector<Pose2> &samples, double length, double absTurn) const override
        {
            ++calls;
            // length and heading change, measured on the samples as a time cost would
            double turn = 0;
            Pose2 a = from;
            for (const Pose2 &b : samples) turn += std::abs(wrapAngle(b.yaw - a.yaw)), a = b;
            return length + 2.0 * turn + 0.0 * absTurn;
        }
        bool shapeOnly() const override { return shape; }
    };
    int solved = 0;
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        for (const bool clothoid : {false, true})
        {
            CarLatticeConfig cfg = test::randomBlocksLattice(fc, true);
            if (clothoid) cfg.curvatureRate = fc.vehicle().curvatureRateLimit();
            CarLatticeSearch search(fc, std::make_shared<const CarLattice>(cfg));
            std::mt19937 rng(seed * 7 + (clothoid ? 1 : 0));
            for (int k = 0; k < 4; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.goalYawTolerance = 0;
                Counting each, once;
                once.shape = true;
                const CarLatticeResult a = search.run(q, each, [] { return false; });
                const CarLatticeResult b = search.run(q, once, [] { return false; });
                ASSERT_EQ(a.exact, b.exact);
                EXPECT_EQ(a.expanded, b.expanded);
                EXPECT_NEAR(a.cost, b.cost, 1e-9 * std::max(1.0, a.cost));
                EXPECT_EQ(a.path.size(), b.path.size());
                std::size_t prims = 0;
                for (int h = 0; h < 16; ++h) prims += search.lattice().primitives(h).size();
                EXPECT_LE(once.calls, long(prims) + 64);  // the analytic expansion's curves besides
                if (a.exact && a.expanded > 100)
                {
                    ++solved;
                    EXPECT_GT(each.calls, 4 * once.calls);
                }
            }
        }
    }
    EXPECT_GE(solved, 6);
}

// The curve bound read from the lattice's CurveTable (CarLatticeQuery::curveTable) on paper I's
// car's perpendicular-parking and parking-lot queries (goal poses, reversing): every query is
// solved, the table is read (and kept: a second run computes nothing new), and the searches
// expand fewer states in all than without a curve bound.
TEST(CarLatticeSearch, TheCurveTableBoundCutsExpansionsOnParkingQueries)
{
    const VehicleParams v = VehicleParams::preset("paper-i");
    std::uint64_t off = 0, fromTable = 0;
    int queries = 0;
    for (const ParkingScene &scene : parkingScenes(v))
    {
        if (scene.name != "perpendicular" && scene.name != "lot") continue;
        auto g = std::make_shared<const OccupancyGrid>(scene.grid);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, v);
        CarLatticeConfig cfg{0.3, 16, 1.01 * v.minTurningRadius(), 0.05, fc.reach()};
        cfg.reverse = true;
        auto lattice = std::make_shared<const CarLattice>(cfg);
        CarLatticeSearch search(fc, lattice);
        for (const ParkingQuery &pq : scene.queries)
        {
            CarLatticeQuery q;
            q.start = pq.start;
            q.goal = pq.goal;
            q.goalYawTolerance = 0;
            q.settings.reversePenalty = 2.0;
            q.cuspPenalty = 2.0;
            LengthCost cost;
            const CarLatticeResult a = search.run(q, cost, [] { return false; });
            q.curveWithin = 10 * cfg.turnRadius;
            q.settings.curveHeuristic = CurveHeuristic::Table;
            const CarLatticeResult b = search.run(q, cost, [] { return false; });
            ASSERT_TRUE(a.exact && b.exact) << pq.name;
            const std::size_t kept = search.curveTable()->computed();
            EXPECT_GT(kept, 0u) << pq.name;
            const CarLatticeResult again = search.run(q, cost, [] { return false; });
            EXPECT_EQ(search.curveTable()->computed(), kept) << pq.name;  // read what the first run computed
            EXPECT_EQ(again.cost, b.cost) << pq.name;
            off += a.expanded;
            fromTable += b.expanded;
            ++queries;
        }
    }
    EXPECT_EQ(queries, 8);
    EXPECT_LT(fromTable, off);
    std::printf("paper I's car, perpendicular and lot queries: %llu expansions without a curve bound, %llu with the table\n",
                static_cast<unsigned long long>(off), static_cast<unsigned long long>(fromTable));
}

// Motions checked when the search comes to them (the default where costs are known before the
// check) against every motion checked when generated: the same states expanded and the same
// path, on forward and reversing lattices, with the analytic expansion and with a node goal.
TEST(CarLatticeSearch, LazyMotionChecksChangeNothingButTheWork)
{
    int compared = 0, exact = 0;
    for (unsigned seed = 1; seed <= 5; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        for (bool reverse : {false, true})
        {
            CarLatticeSearch search(fc, std::make_shared<const CarLattice>(test::randomBlocksLattice(fc, reverse)));
            std::mt19937 rng(seed * 7 + unsigned(reverse));
            for (int k = 0; k < 4; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.goalYawTolerance = 0;
                q.settings.reversePenalty = 1.5;
                q.cuspPenalty = 1.0;
                if (k % 2)
                {
                    q.shoot = false;
                    q.goalYawTolerance = -1;
                    q.inGoal = [&](const Pose2 &p) { return std::hypot(p.x - q.goal.x, p.y - q.goal.y) <= 0.15; };
                }
                LengthCost cost;
                const CarLatticeResult lazy = search.run(q, cost, [] { return false; });
                CarLatticeQuery checked = q;
                checked.lazyChecks = false;
                const CarLatticeResult eager = search.run(checked, cost, [] { return false; });
                ASSERT_EQ(lazy.outcome, eager.outcome) << "seed " << seed << " query " << k;
                EXPECT_EQ(lazy.exact, eager.exact);
                EXPECT_EQ(lazy.expanded, eager.expanded) << "seed " << seed << " query " << k;
                EXPECT_EQ(lazy.cost, eager.cost) << "seed " << seed << " query " << k;
                ASSERT_EQ(lazy.path.size(), eager.path.size());
                for (std::size_t n = 0; n < lazy.path.size(); ++n) ASSERT_LT(test::poseError(lazy.path[n], eager.path[n]), 1e-12);
                EXPECT_GE(lazy.states, eager.states);  // (blocked motions' ends are states too)
                ++compared;
                exact += lazy.exact;
            }
        }
    }
    EXPECT_EQ(compared, 40);
    EXPECT_GE(exact, 25);
}
