#include "gridcar/planners/CornerAStar.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/vehicle/Dynamics.h"
#include "gridcar/planners/GridAStar.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <filesystem>
#include <queue>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace gridcar::test;

// ---------------------------------------------------------------- corner-weighted A*
namespace
{
/// A number as text that parses back to the same double.
std::string exactText(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

/// Independent reference: Dijkstra over (cell, arrival direction) with the same rules.
double referenceCornerCost(const OccupancyGrid &g, int sc, int sr, int gc, int gr, const CornerWeights &w, double res)
{
    const double turnCost[5] = {0, w.w45, w.w90, w.w135, 0};
    const int W = g.width(), H = g.height();
    std::vector<double> dist(std::size_t(W) * H * 8, 1e300);
    using E = std::pair<double, std::size_t>;
    std::priority_queue<E, std::vector<E>, std::greater<E>> pq;
    for (int d = 0; d < 8; ++d)
    {
        const std::size_t s = (std::size_t(sr) * W + sc) * 8 + d;
        dist[s] = 0;
        pq.push({0.0, s});
    }
    const int dc[8] = {1, 1, 0, -1, -1, -1, 0, 1}, dr[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    while (!pq.empty())
    {
        auto [dd, s] = pq.top();
        pq.pop();
        if (dd > dist[s]) continue;
        const int dir = int(s % 8), cell = int(s / 8), c = cell % W, r = cell / W;
        if (c == gc && r == gr) return dd;
        for (int d = 0; d < 8; ++d)
        {
            int t = ((d - dir) % 8 + 8) % 8;
            if (t > 4) t = 8 - t;
            if (t == 4) continue;
            const int nc = c + dc[d], nr = r + dr[d];
            if (g.isBlocked(nc, nr)) continue;
            if ((d & 1) && (g.isBlocked(nc, r) || g.isBlocked(c, nr))) continue;
            const double nd = dd + res * ((d & 1) ? std::sqrt(2.0) : 1.0) + turnCost[t];
            const std::size_t n = (std::size_t(nr) * W + nc) * 8 + d;
            if (nd < dist[n])
            {
                dist[n] = nd;
                pq.push({nd, n});
            }
        }
    }
    return -1;
}
}  // namespace

TEST(CornerAStar, CostEqualsDijkstraOverTheSameGraphOnRandomMaps)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    std::mt19937 rng(17);
    int compared = 0;
    for (int trial = 0; trial < 12; ++trial)
    {
        auto g = std::make_shared<OccupancyGrid>(40, 30, 0.5);
        g->setUnknownIsFree(true);
        std::uniform_real_distribution<double> u(0, 1);
        for (int r = 0; r < 30; ++r)
            for (int c = 0; c < 40; ++c)
                if (u(rng) < 0.25) g->set(c, r, CellState::Occupied);
        std::uniform_int_distribution<int> uc(0, 39), ur(0, 29);
        int sc, sr, gc, gr;
        do { sc = uc(rng); sr = ur(rng); } while (g->isBlocked(sc, sr));
        do { gc = uc(rng); gr = ur(rng); } while (g->isBlocked(gc, gr) || (gc == sc && gr == sr));
        GridSetup s = makeGridSetup(g, VehicleParams::preset("point"));
        // paper C's 8-connected search, compared with a Dijkstra over the same graph
        auto planner = std::make_shared<CornerAStarGrid>(s.ss->getSpaceInformation());
        CornerWeights w;
        w.w45 = 0.3 + trial * 0.2;
        w.w90 = 1.0 + trial * 0.5;
        w.w135 = 2.0 + trial * 0.7;
        ASSERT_TRUE(planner->params().setParam("corner_weight_45", exactText(w.w45)));
        ASSERT_TRUE(planner->params().setParam("corner_weight_90", exactText(w.w90)));
        ASSERT_TRUE(planner->params().setParam("corner_weight_135", exactText(w.w135)));
        planner->setFreeStartHeading(true);
        s.ss->setPlanner(planner);
        s.setStartAndGoal(cellPose(*g, sc, sr), cellPose(*g, gc, gr));
        const ob::PlannerStatus st = s.ss->solve(5.0);
        const double ref = referenceCornerCost(*g, sc, sr, gc, gr, w, 0.5);
        if (ref < 0)
        {
            EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION);
            continue;
        }
        ASSERT_EQ(st, ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_NEAR(planner->lastCost(), ref, 1e-9) << "trial " << trial;
        ++compared;
    }
    EXPECT_GE(compared, 6);
}

TEST(CornerAStar, PhysicsWeightsFollowTheBrakingModel)
{
    const VehicleParams car = VehicleParams::preset("paper-c-car");
    const CornerWeights w = physicsCornerWeights(car);
    // (v_max - v_c)^2 / 2 (1/a + 1/d) with a = d = 3 m/s^2, v_max 30, corners 10 / 6 / 4 m/s
    EXPECT_NEAR(w.w45, 20.0 * 20.0 / 3.0, 1e-9);
    EXPECT_NEAR(w.w90, 24.0 * 24.0 / 3.0, 1e-9);
    EXPECT_NEAR(w.w135, 26.0 * 26.0 / 3.0, 1e-9);
    EXPECT_LT(w.w45, w.w90);
    EXPECT_LT(w.w90, w.w135);
}

// Paper C derives its weights from the full-size car and then scales "all values" to its robot
// (30 -> 0.6 m/s, 10 -> 0.2 m/s corners: k = 1/50). The physics weights are distances, so they
// scale by k: the car's 133 / 192 m become 2.67 / 3.84 m, the paper's 2.7 / 7 m in order of
// magnitude (45 degrees to 1 %, 90 degrees a factor 1.8 below).
TEST(CornerAStar, PhysicsWeightsOfThePapersCarScaledToItsRobotAreOfThePapersOrder)
{
    const VehicleParams car = VehicleParams::preset("paper-c-car");
    const double k = 0.6 / 30.0;
    const CornerWeights full = physicsCornerWeights(car);
    const CornerWeights w = physicsCornerWeights(car.scaled(k));
    EXPECT_NEAR(w.w45, k * full.w45, 1e-12);
    EXPECT_NEAR(w.w90, k * full.w90, 1e-12);
    EXPECT_NEAR(w.w135, k * full.w135, 1e-12);
    const CornerWeights paper;
    EXPECT_NEAR(w.w45 / paper.w45, 1.0, 0.02);
    EXPECT_GT(w.w90 / paper.w90, 0.5);
    EXPECT_LT(w.w90 / paper.w90, 1.0);
    const CornerSpeeds vc = cornerSpeeds(car.scaled(k));
    EXPECT_NEAR(vc.v45, 0.2, 1e-12);  // the robot's corner speed in the paper
    // the paper's "the distance lost is about 2/3 (45 deg) and 4/5 (90 deg)" is 1 - v_c / v_max
    EXPECT_NEAR(1.0 - vc.v45 / 0.6, 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(1.0 - vc.v90 / 0.6, 4.0 / 5.0, 1e-12);
}

TEST(CornerAStar, NoReversalAndStartHeadingCounts)
{
    // corridor 1 cell high: start facing east, goal to the west: needs a reversal -> impossible
    auto g = std::make_shared<OccupancyGrid>(20, 3, 1.0);
    for (int c = 0; c < 20; ++c)
    {
        g->set(c, 0, CellState::Occupied);
        g->set(c, 2, CellState::Occupied);
    }
    GridSetup s = makeGridSetup(g, VehicleParams::preset("point"));
    auto planner = std::make_shared<CornerAStarGrid>(s.ss->getSpaceInformation());
    s.ss->setPlanner(planner);
    s.setStartAndGoal(cellPose(*g, 10, 1, 0.0), cellPose(*g, 3, 1));
    EXPECT_NE(s.ss->solve(1.0), ob::PlannerStatus::EXACT_SOLUTION);
    // with a free start heading it simply drives west
    s.ss->clear();
    planner->setFreeStartHeading(true);
    ASSERT_EQ(s.ss->solve(1.0), ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_NEAR(planner->lastCost(), 7.0, 1e-12);
}

// ---------------------------------------------------------------- corner-astar on the campus
TEST(CornerAStar, FewerHeadingChangesThanAStarEuclideanOnCampusQueries)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    CampusParams cp;
    cp.width = 1200;
    cp.height = 800;
    cp.resolution = 0.5;
    cp.seed = 3;
    auto grid = std::make_shared<const OccupancyGrid>(generateCampus(cp));
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-c-robot"));
    auto headingChanges = [](const og::PathGeometric &p) {
        int n = 0;
        for (std::size_t i = 2; i < p.getStateCount(); ++i)
        {
            const auto *a = p.getState(i - 1)->as<ob::SE2StateSpace::StateType>();
            const auto *b = p.getState(i)->as<ob::SE2StateSpace::StateType>();
            if (std::abs(std::remainder(b->getYaw() - a->getYaw(), 2 * M_PI)) > 1e-6) ++n;
        }
        return n;
    };
    // query poses: road cells far apart
    std::vector<Pose2> pts;
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> uc(0, grid->width() - 1), ur(0, grid->height() - 1);
    while (pts.size() < 8)
    {
        const int c = uc(rng), r = ur(rng);
        if (s.field->cellDistance(c, r) > 1.5) pts.push_back(cellPose(*grid, c, r));
    }
    int fewer = 0, queries = 0, totalCorner = 0, totalEuclid = 0;
    for (std::size_t i = 0; i + 1 < pts.size(); i += 2)
    {
        int changes[2];
        int k = 0;
        for (const char *name : {"corner-astar-grid", "astar-euclidean"})  // paper C's grid corners
        {
            s.ss->clear();
            auto p = makePlanner(s.ss->getSpaceInformation(), name);
            p->params().setParam("free_start_heading", "1");
            s.ss->setPlanner(p);
            s.setStartAndGoal(pts[i], pts[i + 1]);
            ASSERT_EQ(s.ss->solve(30.0), ob::PlannerStatus::EXACT_SOLUTION) << name;
            changes[k++] = headingChanges(s.ss->getSolutionPath());
        }
        totalCorner += changes[0];
        totalEuclid += changes[1];
        fewer += changes[0] < changes[1] ? 1 : 0;
        ++queries;
    }
    EXPECT_LT(totalCorner, totalEuclid);
    EXPECT_GE(fewer, queries - 1);
    std::printf("heading changes over %d campus queries: corner-astar %d, astar-euclidean %d\n", queries, totalCorner,
                totalEuclid);
}

// cost=time: the driving time in seconds as the car lattice's cost (paper C's future work): an
// exact drivable path whose search cost is at least its length at v_max and at most its
// length at the slowest speed a turn at K_max allows plus the braking; refused on the grid
// lattice and for an unknown cost.
TEST(CornerAStar, DrivingTimeCostOnTheCarLattice)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto grid = std::make_shared<OccupancyGrid>(400, 400, 0.1, CellState::Free);
    for (int r = 100; r < 300; ++r)
        for (int c = 190; c < 210; ++c) grid->set(c, r, CellState::Occupied);  // a wall to go round
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-c-car"));
    auto p = std::make_shared<CornerAStar>(s.ss->getSpaceInformation());
    EXPECT_THROW(p->setCost("fastest"), std::invalid_argument);
    p->setCost("time");
    EXPECT_EQ(p->cost(), "time");
    s.ss->setPlanner(p);
    s.setStartAndGoal({5.0, 20.0, 0.0}, {35.0, 20.0, 0.0});
    ASSERT_EQ(s.ss->solve(5.0), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const std::vector<Pose2> path = toPoses(s.ss->getSolutionPath());
    EXPECT_TRUE(checkDrivable(path, *s.checker).drivable);
    double len = 0;
    for (std::size_t i = 1; i < path.size(); ++i) len += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
    const VehicleParams &v = s.checker->vehicle();
    EXPECT_GE(p->lastCost(), len / v.maxSpeed);  // seconds, at least the length at v_max
    EXPECT_LE(p->lastCost(), len / std::sqrt(lateralAccelLimit(v) * v.minTurningRadius()) + 10 * cornerTimeLost(v, M_PI));
    GridSetup g = makeGridSetup(grid, VehicleParams::preset("paper-c-car"));
    // the driving-time cost is the car lattice's: paper C's grid search does not declare it
    auto q = std::make_shared<CornerAStarGrid>(g.ss->getSpaceInformation());
    EXPECT_FALSE(q->params().hasParam("cost"));
    EXPECT_TRUE(std::make_shared<CornerAStar>(g.ss->getSpaceInformation())->params().hasParam("cost"));
    // so is the turn bound, which only corner weights use
    EXPECT_TRUE(std::make_shared<CornerAStar>(g.ss->getSpaceInformation())->params().hasParam("turn_heuristic"));
    EXPECT_FALSE(std::make_shared<ImprovedAStar>(g.ss->getSpaceInformation())->params().hasParam("turn_heuristic"));
}
