// CarLatticeSearch and the planners on it: the obstacle-aware heuristic against exhaustive
// search, drivable paths of every car-lattice planner, free start and goal heading, PositionGoal.
#include "PlannerTestUtil.h"

#include "gridcar/path/PathMetrics.h"
#include "gridcar/core/Angles.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/path/Cusps.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/bench/PlanQuery.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
std::shared_ptr<OccupancyGrid> randomBlocks(unsigned seed)
{
    auto g = std::make_shared<OccupancyGrid>(90, 70, 0.1, CellState::Free);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> uc(0, 89), ur(0, 69), sz(1, 9);
    for (int k = 0; k < 30; ++k)
    {
        const int c = uc(rng), r = ur(rng), w = sz(rng), h = sz(rng);
        for (int rr = r; rr < std::min(70, r + h); ++rr)
            for (int cc = c; cc < std::min(90, c + w); ++cc) g->set(cc, rr, CellState::Occupied);
    }
    return g;
}

Pose2 randomFree(const FootprintChecker &fc, std::mt19937 &rng)
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
}  // namespace

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
            CarLatticeConfig{0.1, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()});
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

// CarLatticeSearch::shortcut() on searched paths, forwards only and reversing, on seeded random
// maps: the ends stay to the last bit, the path never gets longer or costlier or gains a cusp,
// and it stays drivable by the independent check (exact FCL every 2 cm, K_max, split at cusps);
// and it does shorten some of them (else it does nothing).
TEST(CarLatticeSearch, ShortcutKeepsEndsAndGuaranteesAndShortens)
{
    int shortened = 0, paths = 0;
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        for (const bool reverse : {false, true})
        {
            CarLatticeConfig cfg{0.1, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()};
            cfg.reverse = reverse;
            CarLatticeSearch search(fc, std::make_shared<const CarLattice>(cfg));
            std::mt19937 rng(seed * 17 + unsigned(reverse));
            for (int k = 0; k < 5; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.goalYawTolerance = 0;
                q.reversePenalty = 2.0;
                q.cuspPenalty = 1.0;
                LengthCost cost;
                CarLatticeResult r = search.run(q, cost, [] { return false; });
                if (!r.exact) continue;
                ++paths;
                std::vector<Pose2> p = r.path;
                const int cuspsBefore = int(splitAtCusps(p).size()) - 1;
                const ShortcutReport rep = search.shortcut(p, q, cost, [] { return false; }, 3000);
                SCOPED_TRACE("seed " + std::to_string(seed) + (reverse ? " reversing" : " forwards") + " query " +
                             std::to_string(k));
                EXPECT_EQ(p.front().x, r.path.front().x);
                EXPECT_EQ(p.front().y, r.path.front().y);
                EXPECT_EQ(p.front().yaw, r.path.front().yaw);
                EXPECT_EQ(p.back().x, r.path.back().x);
                EXPECT_EQ(p.back().y, r.path.back().y);
                EXPECT_EQ(p.back().yaw, r.path.back().yaw);
                EXPECT_NEAR(rep.lengthAfter, pathLength(p), 1e-9);
                EXPECT_NEAR(rep.lengthBefore, pathLength(r.path), 1e-9);
                EXPECT_LE(rep.lengthAfter, rep.lengthBefore + 1e-9);
                EXPECT_LE(rep.costAfter, rep.costBefore + 1e-9);
                EXPECT_LE(int(splitAtCusps(p).size()) - 1, cuspsBefore);
                DrivabilityOptions o;
                o.reversing = reverse;
                const Drivability d = checkDrivable(p, fc, o);
                EXPECT_TRUE(d.drivable) << d.reason;
                if (!reverse) EXPECT_EQ(splitAtCusps(p).size(), 1u);
                if (rep.replaced > 0 && rep.lengthAfter < rep.lengthBefore - 0.05) ++shortened;
            }
        }
    }
    EXPECT_GE(paths, 20);
    EXPECT_GE(shortened, paths / 4) << "of " << paths;
}

// With clothoid turns (a curvature rate) the shortcut keeps the rate: its curves start and end
// at curvature 0 and join the path only where it runs straight, so the independent check with
// the rate passes after it as before it; it still shortens paths, also with wider turns.
TEST(CarLatticeSearch, ShortcutWithClothoidTurnsKeepsTheCurvatureRate)
{
    int shortened = 0, paths = 0;
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
        auto g = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        CarLatticeConfig cfg{0.1, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()};
        cfg.curvatureRate = fc.vehicle().curvatureRateLimit();
        CarLatticeSearch search(fc, std::make_shared<const CarLattice>(cfg));
        std::mt19937 rng(seed * 31);
        for (int k = 0; k < 16; ++k)
        {
            CarLatticeQuery q;
            q.start = randomFree(fc, rng);
            q.goal = randomFree(fc, rng);
            q.goalYawTolerance = 0;
            LengthCost cost;
            const CarLatticeResult r = search.run(q, cost, [] { return false; });
            if (!r.exact) continue;
            SCOPED_TRACE("seed " + std::to_string(seed) + " query " + std::to_string(k));
            DrivabilityOptions o;
            o.maxCurvatureRate = cfg.curvatureRate;
            const Drivability before = checkDrivable(r.path, fc, o);
            if (!before.drivable) continue;  // the rate is the shortcut's to keep, not to mend
            ++paths;
            std::vector<Pose2> p = r.path;
            const ShortcutReport rep = search.shortcut(p, q, cost, [] { return false; }, 3000);
            const Drivability after = checkDrivable(p, fc, o);
            EXPECT_TRUE(after.drivable) << after.reason;
            EXPECT_LE(after.maxCurvatureRate, 1.02 * cfg.curvatureRate);
            EXPECT_LE(rep.lengthAfter, rep.lengthBefore + 1e-9);
            EXPECT_EQ(p.back().x, r.path.back().x);
            EXPECT_EQ(p.back().yaw, r.path.back().yaw);
            if (rep.lengthAfter < rep.lengthBefore - 0.05) ++shortened;
        }
    }
    EXPECT_GE(paths, 10);
    EXPECT_GE(shortened, paths / 4) << "of " << paths;
}

// Stopped at once, the shortcut leaves the path as it was.
TEST(CarLatticeSearch, ShortcutStoppedAtOnceKeepsThePath)
{
    auto g = randomBlocks(2);
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
    CarLatticeSearch search(fc, std::make_shared<const CarLattice>(
                                    CarLatticeConfig{0.1, 16, 1.01 * fc.vehicle().minTurningRadius(), 0.05, fc.reach()}));
    std::mt19937 rng(3);
    int tried = 0;
    for (int k = 0; k < 10 && tried < 3; ++k)
    {
        CarLatticeQuery q;
        q.start = randomFree(fc, rng);
        q.goal = randomFree(fc, rng);
        q.goalYawTolerance = 0;
        LengthCost cost;
        const CarLatticeResult r = search.run(q, cost, [] { return false; });
        if (!r.exact) continue;
        ++tried;
        std::vector<Pose2> p = r.path;
        const ShortcutReport rep = search.shortcut(p, q, cost, [] { return true; }, 3000);
        EXPECT_EQ(rep.replaced, 0);
        ASSERT_EQ(p.size(), r.path.size());
        for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i].x, r.path[i].x);
    }
    EXPECT_GE(tried, 1);
}

// The parking suite's parallel park for paper C's car: the lattice's path (24 m, its 16
// headings and 0.45 m cells) is shortened by the shortcut (`shortcut`, on by default), with no
// more cusps, exact at the goal pose, drivable, and the simulation still drives it to the goal.
TEST(CarLatticeSearch, ShortcutShortensAParallelParkThatIsStillDriven)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ParkingQuery q;
    GridSetup s = test::parkingSetup("paper-c-car", "parallel", q, "parallel/park");
    QueryResult off, on;
    for (const bool shortcut : {false, true})
    {
        auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
        p->params().setParam("reverse", "on");
        if (!shortcut) p->params().setParam("shortcut", "0");
        EXPECT_EQ(p->params().getParam("shortcut")->getValue(), shortcut ? "auto" : "off");
        (shortcut ? on : off) = runQuery(s, p, q.start, q.goal, 5.0);
    }
    ASSERT_EQ(off.status, ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(on.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(on.drivability.drivable) << on.drivability.reason;
    EXPECT_LT(on.metrics.length, 0.97 * off.metrics.length);
    EXPECT_LE(on.metrics.cusps, off.metrics.cusps);
    EXPECT_LT(test::poseError(on.path.back(), q.goal), 1e-6);
    const DriveResult d = drivePath(on.path, *s.checker, Scenario());
    EXPECT_EQ(d.outcome, DriveResult::Outcome::Reached) << d.reason;
}

// `shortcut` = auto shortcuts on a reversing lattice only (a forward route keeps the searched
// path: docs/planners.md says why); on and off (1, 0) force it; anything else is refused.
TEST(CarLatticeSearch, ShortcutParameterModes)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    auto grid = std::make_shared<const OccupancyGrid>(generateCampus());
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-c-car"));
    auto planner = std::dynamic_pointer_cast<GridPlanner>(makePlanner(s.ss->getSpaceInformation(), "corner-astar"));
    ASSERT_TRUE(planner);
    EXPECT_EQ(planner->shortcut(), "auto");
    EXPECT_FALSE(planner->shortcutting());
    planner->setReverse("on");
    EXPECT_TRUE(planner->shortcutting());
    planner->setShortcut("0");
    EXPECT_EQ(planner->shortcut(), "off");
    EXPECT_FALSE(planner->shortcutting());
    planner->setReverse("off");
    planner->setShortcut("1");
    EXPECT_TRUE(planner->shortcutting());
    EXPECT_THROW(planner->setShortcut("yes"), std::invalid_argument);
    EXPECT_EQ(planner->shortcut(), "on");
}
