#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/planners/PlannerFactory.h"

#include "gridcar/path/PostProcess.h"
#include "gridcar/spaces/Setup.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>

#include <cmath>
#include <queue>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
/// A small car for 0.5 m cells: K_max = tan 30 / 0.8 = 0.72 1/m, so a turn needs 3 straight
/// or 2 diagonal steps.
VehicleParams smallCar()
{
    VehicleParams v = VehicleParams::preset("paper-i");
    v.name = "small";
    v.length = 1.0;
    v.width = 0.6;
    v.rearOverhang = 0.2;
    v.wheelbase = 0.8;
    v.maxSteerDeg = 30;
    return v;
}

/// These tests are about paper I's lattice on the map's cells.
std::shared_ptr<ImprovedAStarGrid> improved(const GridSetup &s)
{
    auto p = std::dynamic_pointer_cast<ImprovedAStarGrid>(makePlanner(s.ss->getSpaceInformation(), "improved-astar-grid"));
    EXPECT_TRUE(p);
    return p;
}

/// Independent reference: Dijkstra over (cell, heading, straight run) with the rules the class
/// comment states, and the integral cost length x (1 + (o(a) + o(b)) / 2), o = delta / d_O.
double referenceIntegralCost(const GridSetup &s, int sc, int sr, int gc, int gr, double delta, int needS, int needD)
{
    const OccupancyGrid &g = *s.grid;
    const int W = g.width(), H = g.height(), K = std::max(needS, needD) + 1;
    const int need[2] = {needS, needD};
    const double res = g.resolution();
    auto o = [&](int c, int r) { return delta / s.field->cellDistance(c, r); };
    auto idx = [&](int c, int r, int d, int k) { return ((std::size_t(r) * W + c) * 8 + d) * K + k; };
    std::vector<double> dist(std::size_t(W) * H * 8 * K, 1e300);
    using E = std::pair<double, std::size_t>;
    std::priority_queue<E, std::vector<E>, std::greater<E>> pq;
    for (int d = 0; d < 8; ++d)
    {
        const std::size_t i = idx(sc, sr, d, need[d & 1] / 2);
        dist[i] = 0;
        pq.push({0.0, i});
    }
    const int dcol[8] = {1, 1, 0, -1, -1, -1, 0, 1}, drow[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    while (!pq.empty())
    {
        const auto [dd, i] = pq.top();
        pq.pop();
        if (dd > dist[i]) continue;
        const int k = int(i % K), d0 = int((i / K) % 8);
        const int cell = int(i / K / 8), c = cell % W, r = cell / W;
        if (c == gc && r == gr && k >= need[d0 & 1] - need[d0 & 1] / 2) return dd;
        for (int turn : {0, 1, -1})
        {
            if (turn && k < need[d0 & 1]) continue;
            const int d = (d0 + turn + 8) % 8;
            const int nc = c + dcol[d], nr = r + drow[d];
            if (!g.inBounds(nc, nr)) continue;
            if ((d & 1) && (g.isBlocked(nc, r) || g.isBlocked(c, nr))) continue;
            const double yaw = d * M_PI / 4;
            if (!s.checker->isMotionValid({g.cellCenterX(c), g.cellCenterY(r), yaw},
                                          {g.cellCenterX(nc), g.cellCenterY(nr), yaw}))
                continue;
            const int nk = std::min(turn ? 1 : k + 1, K - 1);
            const double step = (d & 1) ? res * std::sqrt(2.0) : res;
            const double nd = dd + step * (1 + 0.5 * (o(c, r) + o(nc, nr)));
            const std::size_t j = idx(nc, nr, d, nk);
            if (nd < dist[j])
            {
                dist[j] = nd;
                pq.push({nd, j});
            }
        }
    }
    return -1.0;
}
}  // namespace

TEST(ImprovedAStar, PaperEvaluationByHand)
{
    // eq. 4-5: f = g' + h (1 + o), g' = g while g < o, else 0
    EXPECT_DOUBLE_EQ(paperPriority(0.5, 10.0, 0.8), 0.5 + 10.0 * 1.8);
    EXPECT_DOUBLE_EQ(paperPriority(0.8, 10.0, 0.8), 18.0);  // g >= o: g' = 0
    EXPECT_DOUBLE_EQ(paperPriority(25.0, 4.0, 0.5), 6.0);
    EXPECT_DOUBLE_EQ(paperPriority(0.0, 0.0, 0.0), 0.0);
}

TEST(ImprovedAStar, HeuristicsObstacleCostAndLattice)
{
    auto g = std::make_shared<OccupancyGrid>(40, 40, 0.298);
    g->set(20, 20, CellState::Occupied);
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-i"));
    auto p = improved(s);
    p->setup();
    // eq. 6-7 with phi_max = 40 deg: h = d phi / sin phi = 1.0861 d
    const double d = 0.298 * 5.0;  // (0,0) -> (3,4): 5 cells
    EXPECT_NEAR(p->heuristicAt(0, 0, 3, 4), d * (40 * M_PI / 180) / std::sin(40 * M_PI / 180), 1e-12);
    p->params().setParam("heuristic", "euclidean");
    p->setup();
    EXPECT_NEAR(p->heuristicAt(0, 0, 3, 4), d, 1e-12);
    p->params().setParam("mode", "integral");
    p->params().setParam("heuristic", "auto");
    p->setup();
    EXPECT_NEAR(p->heuristicAt(0, 0, 3, 4), 0.298 * (4 + 3 * (std::sqrt(2.0) - 1)), 1e-12);  // octile
    // eq. 8: o = delta / d_min, d_min the cell's obstacle distance (3 cells from the obstacle)
    p->params().setParam("delta", "2.0");
    EXPECT_NEAR(p->obstacleCostAt(23, 20), 2.0 / (3 * 0.298), 1e-6);
    // the lattice of the paper's car: L_turn = 0.897 R_min = 0.897 x 1.859 m = 1.667 m
    EXPECT_EQ(p->stepsBeforeTurn(0), 6);  // ceil(1.667 / 0.298)
    EXPECT_EQ(p->stepsBeforeTurn(1), 4);  // ceil(1.667 / 0.421)
    // setters throw std::invalid_argument, which OMPL's setParam() turns into false (value kept)
    const bool modeBefore = p->improvedSettings().paperMode;
    EXPECT_FALSE(p->params().setParam("mode", "bogus"));
    EXPECT_EQ(p->improvedSettings().paperMode, modeBefore);
    EXPECT_FALSE(p->params().setParam("delta", "-1"));
    EXPECT_DOUBLE_EQ(p->improvedSettings().delta, 2.0);
    EXPECT_THROW(p->setHeuristic("magic"), std::invalid_argument);
    EXPECT_EQ(p->heuristic(), "auto");
    // the settings' own messages name the setting, the value and the choices
    ImprovedSettings settings;
    for (const auto &f : improvedSettingFields())
        if (f.name == "mode") EXPECT_THROW(f.parse(settings, "fast"), std::invalid_argument);
    // the car-lattice planner declares what acts in it: not the grid search's switches
    auto car = std::make_shared<ImprovedAStar>(s.ss->getSpaceInformation());
    for (const char *gridOnly : {"heuristic", "contour", "smooth", "allow_corner_cutting", "lattice"})
        EXPECT_FALSE(car->params().hasParam(gridOnly)) << gridOnly;
    for (const char *grid : {"heuristic", "contour", "smooth", "allow_corner_cutting", "mode", "delta"})
        EXPECT_TRUE(p->params().hasParam(grid)) << grid;
    EXPECT_FALSE(p->params().hasParam("headings"));
}

TEST(ImprovedAStar, IntegralModeEqualsDijkstraOverTheSameCost)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    std::mt19937 rng(7);
    int compared = 0;
    for (int trial = 0; trial < 16; ++trial)
    {
        auto g = std::make_shared<OccupancyGrid>(28, 24, 0.5);
        std::bernoulli_distribution blocked(0.05);
        for (int r = 0; r < g->height(); ++r)
            for (int c = 0; c < g->width(); ++c)
                if (blocked(rng)) g->set(c, r, CellState::Occupied);
        GridSetup s = makeGridSetup(g, smallCar());
        auto p = improved(s);
        p->params().setParam("mode", "integral");
        p->params().setParam("delta", "0.7");
        p->params().setParam("smooth", "0");
        p->params().setParam("free_start_heading", "1");
        p->setup();
        ASSERT_EQ(p->stepsBeforeTurn(0), 3);
        ASSERT_EQ(p->stepsBeforeTurn(1), 2);
        std::uniform_int_distribution<int> col(0, g->width() - 1), row(0, g->height() - 1);
        auto freeCell = [&](int &c, int &r) {
            for (int k = 0; k < 1000; ++k)
            {
                c = col(rng);
                r = row(rng);
                if (s.checker->isValid(g->cellCenterX(c), g->cellCenterY(r), 0.0)) return true;
            }
            return false;
        };
        int sc, sr, gc, gr;
        ASSERT_TRUE(freeCell(sc, sr));
        ASSERT_TRUE(freeCell(gc, gr));
        const double ref = referenceIntegralCost(s, sc, sr, gc, gr, 0.7, 3, 2);
        s.ss->setPlanner(p);
        s.setStartAndGoal({g->cellCenterX(sc), g->cellCenterY(sr), 0.0}, {g->cellCenterX(gc), g->cellCenterY(gr), 0.0});
        const auto st = s.ss->solve(10.0);
        if (ref < 0)
        {
            EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION) << "trial " << trial;
            continue;
        }
        ASSERT_EQ(st, ob::PlannerStatus::EXACT_SOLUTION) << "trial " << trial;
        EXPECT_NEAR(p->lastCost(), ref, 1e-9 * ref) << "trial " << trial;
        ++compared;
    }
    EXPECT_GE(compared, 8);
}

TEST(ImprovedAStar, LatticePathKeepsTheCurvatureLimitAndSmoothingKeepsIt)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    // an open room with a wall to go round: the path must turn by 90+ degrees twice
    auto g = std::make_shared<OccupancyGrid>(120, 90, 0.298);
    for (int r = 0; r < 60; ++r) g->set(60, r, CellState::Occupied);
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-i"));
    for (const char *mode : {"paper", "integral"})
    {
        auto p = improved(s);
        p->params().setParam("mode", mode);
        s.ss->setPlanner(p);
        s.ss->clear();
        s.setStartAndGoal({g->cellCenterX(20), g->cellCenterY(20), -M_PI / 2}, {g->cellCenterX(100), g->cellCenterY(20), 0.0});
        ASSERT_EQ(s.ss->solve(20.0), ob::PlannerStatus::EXACT_SOLUTION) << mode;
        // the lattice path: every vertex turns by 45 degrees, legs between vertices >= L_turn
        const auto tp = turningPoints(p->lastLatticePath());
        ASSERT_GE(tp.size(), 4u) << mode;
        const double kmax = s.checker->vehicle().maxCurvature();
        const double lturn = 2 * std::sin(M_PI / 8) / (kmax * std::pow(std::cos(M_PI / 8), 2));
        for (std::size_t i = 1; i + 1 < tp.size(); ++i)
        {
            const double h0 = std::atan2(tp[i].y - tp[i - 1].y, tp[i].x - tp[i - 1].x);
            const double h1 = std::atan2(tp[i + 1].y - tp[i].y, tp[i + 1].x - tp[i].x);
            EXPECT_NEAR(std::abs(std::remainder(h1 - h0, 2 * M_PI)), M_PI / 4, 1e-9) << mode;
            if (i + 2 < tp.size())
                EXPECT_GE(std::hypot(tp[i + 1].x - tp[i].x, tp[i + 1].y - tp[i].y), lturn - 1e-9) << mode;
        }
        // the solution is the smoothed path: collision-free, and within K_max wherever the
        // adjustment and the Bezier piece succeeded
        const SmoothingResult &sm = p->lastSmoothing();
        const auto &path = s.ss->getSolutionPath();
        EXPECT_TRUE(path.check()) << mode;
        ASSERT_EQ(path.getStateCount(), sm.path.size());
        for (std::size_t i = 1; i < sm.path.size(); ++i)
            EXPECT_TRUE(s.checker->isMotionValid(sm.path[i - 1], sm.path[i])) << mode << " pose " << i;
        bool allOk = true;
        for (const CornerReport &c : sm.corners)
        {
            allOk = allOk && c.curvatureOk && c.smoothed;
            if (c.curvatureOk && c.smoothed) EXPECT_LT(c.bezierCurvature, kmax) << mode;
        }
        EXPECT_EQ(sm.adjustFailures + sm.bezierFallbacks, 0) << mode << ": the lattice should leave nothing to fix here";
        if (allOk) EXPECT_LE(sm.maxCurvature, kmax * 1.001) << mode;
    }
}

TEST(ImprovedAStar, DetectionPointContourIsSelectable)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto g = std::make_shared<OccupancyGrid>(80, 40, 0.298);
    for (int c = 0; c < 80; ++c)
    {
        g->set(c, 14, CellState::Occupied);  // a road 11 cells (3.3 m) wide
        g->set(c, 26, CellState::Occupied);
    }
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-i"));
    auto p = improved(s);
    p->params().setParam("contour", "points");
    p->params().setParam("smooth", "0");
    s.ss->setPlanner(p);
    s.setStartAndGoal({g->cellCenterX(15), g->cellCenterY(20), 0.0}, {g->cellCenterX(65), g->cellCenterY(20), 0.0});
    ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
    // every lattice pose keeps its detection points (D/2 = 0.92 m = 3+ cells) off the curbs
    for (const Pose2 &q : p->lastLatticePath()) EXPECT_TRUE(s.checker->isValidDetectionPoints(q.x, q.y));
}
