// PathShortcut::apply(): a found path shortened by the analytic expansion's curves,
// with its guarantees kept (ends, drivability, cusps, the curvature rate with clothoid turns),
// stopped at once, on paper C's parallel park, and the `shortcut` parameter.
#include "PlannerTestUtil.h"

#include "gridcar/path/PathMetrics.h"
#include "gridcar/core/Angles.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/search/PathShortcut.h"
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

// PathShortcut::apply() on searched paths, forwards only and reversing, on seeded random
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
            CarLatticeSearch search(fc, std::make_shared<const CarLattice>(test::randomBlocksLattice(fc, reverse)));
            std::mt19937 rng(seed * 17 + unsigned(reverse));
            for (int k = 0; k < 5; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.goalYawTolerance = 0;
                q.settings.reversePenalty = 2.0;
                q.cuspPenalty = 1.0;
                LengthCost cost;
                CarLatticeResult r = search.run(q, cost, [] { return false; });
                if (!r.exact) continue;
                ++paths;
                std::vector<Pose2> p = r.path;
                const int cuspsBefore = int(splitAtCusps(p).size()) - 1;
                const ShortcutReport rep = PathShortcut(search).apply(p, q, cost, [] { return false; }, 3000);
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
        CarLatticeConfig cfg = test::randomBlocksLattice(fc);
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
            const ShortcutReport rep = PathShortcut(search).apply(p, q, cost, [] { return false; }, 3000);
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
    // the lattice's clothoid turns of up to 90 degrees leave it less to take off than arcs do
    EXPECT_GE(shortened, 2) << "of " << paths;
}

// Stopped at once, the shortcut leaves the path as it was.
TEST(CarLatticeSearch, ShortcutStoppedAtOnceKeepsThePath)
{
    auto g = randomBlocks(2);
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
    CarLatticeSearch search(fc, std::make_shared<const CarLattice>(
                                    test::randomBlocksLattice(fc)));
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
        const ShortcutReport rep = PathShortcut(search).apply(p, q, cost, [] { return true; }, 3000);
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
    auto planner = std::dynamic_pointer_cast<CarLatticePlanner>(makePlanner(s.ss->getSpaceInformation(), "corner-astar"));
    ASSERT_TRUE(planner);
    auto &params = planner->params();
    EXPECT_EQ(planner->carSettings().shortcut, AutoSwitch::Auto);
    EXPECT_FALSE(planner->shortcutting());  // reverse=auto: routes forwards, as the forward lattice's
    ASSERT_TRUE(params.setParam("reverse", "off"));
    EXPECT_FALSE(planner->shortcutting());
    ASSERT_TRUE(params.setParam("reverse", "on"));
    EXPECT_TRUE(planner->shortcutting());
    ASSERT_TRUE(params.setParam("shortcut", "0"));
    EXPECT_EQ(planner->carSettings().shortcut, AutoSwitch::Off);
    EXPECT_FALSE(planner->shortcutting());
    ASSERT_TRUE(params.setParam("reverse", "off"));
    ASSERT_TRUE(params.setParam("shortcut", "1"));
    EXPECT_TRUE(planner->shortcutting());
    EXPECT_FALSE(params.setParam("shortcut", "yes"));  // refused, the setting kept
    EXPECT_EQ(params.getParam("shortcut")->getValue(), "on");
}
