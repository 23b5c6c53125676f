// The car lattice (search/CarLattice.h, CarLatticeSearch.h, ObstacleHeuristic.h): primitives,
// the grown-footprint check against a brute-force reference, the heuristic against exhaustive
// search, and the planners on it: drivable paths, free start and goal heading, PositionGoal.
#include "PlannerTestUtil.h"
#include "TestData.h"

#include "gridcar/core/Angles.h"
#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/search/CarLatticeSearch.h"
#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
using test::randomBlocks;

/// Brute force: does the rectangle of @p v at the pose overlap a blocked cell (or leave the map)?
/// Samples the rectangle on a grid 1/8 cell apart, boundary included.
bool bruteCollides(const OccupancyGrid &g, const VehicleParams &v, const Pose2 &p)
{
    const double step = g.resolution() / 8;
    const int nl = int(std::ceil(v.length / step)), nw = int(std::ceil(v.width / step));
    const double c = std::cos(p.yaw), s = std::sin(p.yaw);
    for (int i = 0; i <= nl; ++i)
        for (int j = 0; j <= nw; ++j)
        {
            const double bx = -v.rearOverhang + v.length * i / nl, by = -v.width / 2 + v.width * j / nw;
            const Cell cell = g.worldToCell(p.x + c * bx - s * by, p.y + s * bx + c * by);
            if (g.isBlocked(cell.col, cell.row)) return true;
        }
    return false;
}

VehicleParams grown(VehicleParams v, double m)
{
    v.length += 2 * m;
    v.width += 2 * m;
    v.rearOverhang += m;
    return v;
}
}  // namespace

TEST(CarLattice, PrimitivesJoinNodesWithBoundedCurvatureAndDenseSamples)
{
    for (int headings : {8, 16})
        for (double cell : {0.1, 0.3, 0.45})
            for (double radius : {0.6, 1.9, 3.9})
            {
                CarLatticeConfig cfg{cell, headings, radius, 0.05, 3.0};
                const CarLattice L(cfg);
                for (int h = 0; h < headings; ++h)
                {
                    ASSERT_EQ(L.primitives(h).size(), 3u);
                    for (const LatticePrimitive &p : L.primitives(h))
                    {
                        // ends exactly on the node at the end heading, which is a neighbour heading
                        EXPECT_DOUBLE_EQ(p.samples.back().x, p.di * cell);
                        EXPECT_DOUBLE_EQ(p.samples.back().y, p.dj * cell);
                        EXPECT_EQ(std::abs(((p.to - p.from) % headings + headings + headings / 2) % headings - headings / 2),
                                  p.turn == 0 ? 0 : 1);
                        Pose2 prev{0, 0, L.yaw(h)};
                        double len = 0;
                        for (const Pose2 &q : p.samples)
                        {
                            const double ds = std::hypot(q.x - prev.x, q.y - prev.y);
                            const double dyaw = std::abs(wrapAngle(q.yaw - prev.yaw));
                            // no body point moves more than the spacing between two samples
                            EXPECT_LE(ds + dyaw * cfg.reach, cfg.spacing + 1e-9);
                            // curvature: heading change per distance within 1 / radius
                            if (ds > 1e-9) EXPECT_LE(dyaw / ds, 1.0 / radius * (1 + 1e-3));  // chord, not arc: 1e-3
                            len += ds;
                            prev = q;
                        }
                        EXPECT_NEAR(len, p.length, 1e-3 * p.length + 1e-6);
                        EXPECT_NEAR(wrapAngle(p.samples.back().yaw - L.yaw(p.to)), 0.0, 1e-9);
                    }
                }
            }
}

// Clothoid turns (CarLatticeConfig::curvatureRate): every primitive still joins nodes exactly
// and stays within 1 / radius, starts and ends straight (curvature 0), and its curvature
// changes no faster than the rate, so a path of primitives has continuous curvature.
TEST(CarLattice, ClothoidTurnsJoinNodesWithContinuousCurvatureWithinTheRate)
{
    for (int headings : {8, 16})
        for (double radius : {0.56, 3.9})
            for (double sigma : {0.13, 2.0, 16.0})
            {
                CarLatticeConfig cfg{radius / 4, headings, radius, 0.02, 0.0};
                cfg.curvatureRate = sigma;
                const CarLattice L(cfg);
                for (int h = 0; h < headings; ++h)
                {
                    // turns of up to 90 degrees each: a corner need not straighten the wheel
                    double widest = 0;
                    for (const LatticePrimitive &p : L.primitives(h)) widest = std::max(widest, std::abs(p.turn));
                    EXPECT_NEAR(widest, M_PI / 2, 1e-9) << "heading " << h;
                }
                for (int h = 0; h < headings; ++h)
                    for (std::size_t k = 0; k < L.primitives(h).size(); ++k)
                    {
                        const LatticePrimitive &p = L.primitives(h)[k];
                        EXPECT_DOUBLE_EQ(p.samples.back().x, p.di * cfg.cell);
                        EXPECT_DOUBLE_EQ(p.samples.back().y, p.dj * cfg.cell);
                        EXPECT_NEAR(wrapAngle(p.samples.back().yaw - L.yaw(p.to)), 0.0, 1e-9);
                        // curvature per interval, from the start pose (yaw of heading h)
                        std::vector<double> kap, mid;
                        Pose2 prev{0, 0, L.yaw(h)};
                        double s = 0;
                        for (const Pose2 &q : p.samples)
                        {
                            const double ds = std::hypot(q.x - prev.x, q.y - prev.y);
                            if (ds > 1e-9)
                            {
                                kap.push_back(wrapAngle(q.yaw - prev.yaw) / ds);
                                mid.push_back(s + ds / 2);
                            }
                            s += ds;
                            prev = q;
                        }
                        ASSERT_GE(kap.size(), 2u);
                        const double ds = mid[1] - mid[0];
                        EXPECT_LE(std::abs(kap.front()), sigma * ds + 1e-6) << "starts straight";
                        EXPECT_LE(std::abs(kap.back()), sigma * ds + 1e-6) << "ends straight";
                        for (std::size_t i = 0; i < kap.size(); ++i)
                        {
                            EXPECT_LE(std::abs(kap[i]), 1.0 / radius * (1 + 1e-3));
                            if (i > 0)
                                EXPECT_LE(std::abs(kap[i] - kap[i - 1]) / (mid[i] - mid[i - 1]), sigma * 1.02 + 1e-6)
                                    << "heading " << h << " primitive " << k << " at " << mid[i] << " m";
                        }
                    }
            }
}

// The primitive set from its configuration: further radii add wider turns (where they land on
// another node), reverse adds each forward primitive mirrored, the body turned round.
TEST(CarLattice, FurtherRadiiAndReverseAreConfigurationOnly)
{
    for (int headings : {8, 16})
    {
        const CarLatticeConfig base{0.2, headings, 1.9, 0.05, 3.0};
        const CarLattice plain(base);
        CarLatticeConfig wide = base;
        wide.extraRadii = {3.8, 7.6};
        const CarLattice radii(wide);
        CarLatticeConfig back = base;
        back.reverse = true;
        const CarLattice reversing(back);
        for (int h = 0; h < headings; ++h)
        {
            std::size_t extra = 0;
            for (const LatticePrimitive &p : radii.primitives(h))
            {
                EXPECT_FALSE(p.reverse);
                if (p.turn == 0) continue;
                EXPECT_TRUE(p.radius == 1.9 || p.radius == 3.8 || p.radius == 7.6) << p.radius;
                if (p.radius > 1.9) ++extra;
                // no two turns of the set end on the same node and heading
                for (const LatticePrimitive &o : radii.primitives(h))
                    if (&o != &p) EXPECT_FALSE(o.to == p.to && o.di == p.di && o.dj == p.dj);
                Pose2 prev{0, 0, radii.yaw(h)};
                for (const Pose2 &q : p.samples)
                {
                    const double ds = std::hypot(q.x - prev.x, q.y - prev.y);
                    if (ds > 1e-9) EXPECT_LE(std::abs(wrapAngle(q.yaw - prev.yaw)) / ds, 1.0 / p.radius * (1 + 1e-3));
                    prev = q;
                }
            }
            EXPECT_GE(extra, 2u) << "heading " << h;  // a wider turn each side at least
            ASSERT_EQ(reversing.primitives(h).size(), 2 * plain.primitives(h).size());
            const int opposite = (h + headings / 2) % headings;
            for (std::size_t k = 0; k < plain.primitives(h).size(); ++k)
            {
                const LatticePrimitive &r = reversing.primitives(h)[plain.primitives(h).size() + k];
                const LatticePrimitive &f = plain.primitives(opposite)[k];
                EXPECT_TRUE(r.reverse);
                EXPECT_EQ(r.from, h);
                EXPECT_EQ(r.to, (f.to + headings / 2) % headings);
                EXPECT_EQ(r.di, f.di);
                EXPECT_EQ(r.dj, f.dj);
                EXPECT_DOUBLE_EQ(r.length, f.length);
                ASSERT_EQ(r.samples.size(), f.samples.size());
                for (std::size_t i = 0; i < r.samples.size(); ++i)
                {
                    EXPECT_DOUBLE_EQ(r.samples[i].x, f.samples[i].x);
                    EXPECT_NEAR(wrapAngle(r.samples[i].yaw - f.samples[i].yaw - M_PI), 0.0, 1e-12);
                    // the reference point moves against the body's heading
                }
                const Pose2 &e = r.samples.front();
                EXPECT_LT(e.x * std::cos(reversing.yaw(h)) + e.y * std::sin(reversing.yaw(h)), 0.0);
            }
        }
    }
    CarLatticeConfig bad{0.2, 16, 1.9, 0.05, 3.0};
    bad.extraRadii = {1.0};
    EXPECT_THROW(CarLattice{bad}, std::invalid_argument);
}

TEST(CarLattice, BadConfigurationsThrow)
{
    EXPECT_THROW(CarLattice({0.0, 16, 1.0, 0.05, 1.0}), std::invalid_argument);
    EXPECT_THROW(CarLattice({0.5, 32, 1.0, 0.05, 1.0}), std::invalid_argument);
    EXPECT_THROW(CarLattice({0.5, 8, std::nan(""), 0.05, 1.0}), std::invalid_argument);
    EXPECT_THROW(CarLattice({0.5, 8, 1.0, -1.0, 1.0}), std::invalid_argument);
    auto s = test::testSetup("paper-c-robot");
    auto p = std::make_shared<CornerAStar>(s.ss->getSpaceInformation());
    EXPECT_FALSE(p->params().setParam("headings", "72"));
    EXPECT_FALSE(p->params().setParam("lattice_cell", "-1"));
    EXPECT_TRUE(p->params().setParam("headings", "8"));
    EXPECT_EQ(p->carSettings().headings, 8);
}

/// The grown-rectangle test, its distance-field-only proof and the plain test against a
/// brute-force rasterisation: never free where the reference collides.
void compareGrown(const std::shared_ptr<const OccupancyGrid> &g, const VehicleParams &v, int n, unsigned seed,
                  int &wrongFree, int &wrongHit, int &hits)
{
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, v);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(g->originX(), g->originX() + g->sizeX()),
        uy(g->originY(), g->originY() + g->sizeY()), uyaw(-M_PI, M_PI);
    for (int i = 0; i < n; ++i)
    {
        const Pose2 p{ux(rng), uy(rng), uyaw(rng)};
        for (double m : {0.0, 0.025, 0.1})
        {
            const bool ref = bruteCollides(*g, grown(v, m), p);
            const bool valid = m > 0 ? fc.isValidInflated(p, m) : fc.isValid(p);
            hits += ref;
            if (ref && valid) ++wrongFree;
            if (ref && fc.provenFree(p, m)) ++wrongFree;
            // the 2D heuristic's relaxation: a pose "proven blocked" must really collide
            if (m == 0 && fc.provenBlocked(p) && !ref) ++wrongHit;
            // the brute force samples at 1/8 cell: a free verdict it gives may still touch
            if (!ref && !valid && !bruteCollides(*g, grown(v, m + g->resolution() / 4), p)) ++wrongHit;
        }
    }
}

TEST(CarLattice, GrownFootprintNeverCallsACollidingPoseFree)
{
    int wrongFree = 0, wrongHit = 0, hits = 0;
    for (unsigned seed : {1u, 2u})
        for (const char *veh : {"paper-i", "paper-c-robot"})
            compareGrown(randomBlocks(seed, 160, 120, 0.1, 90, 12), VehicleParams::preset(veh), 1500, seed, wrongFree,
                         wrongHit, hits);
    EXPECT_EQ(wrongFree, 0);
    EXPECT_EQ(wrongHit, 0);
    EXPECT_GT(hits, 1000);
}

TEST(CarLattice, GrownFootprintAgreesOnTheNativeTsudanumaMap)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    auto g = std::make_shared<const OccupancyGrid>(loadRosMap(test::sharedMaps() + "/ros/tsudanuma_campus/tsudanuma_all.yaml"));
    // poses near the roads: crop to the mapped part by sampling only where the centre cell is free
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-i"));
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> uc(0, g->width() - 1), ur(0, g->height() - 1);
    std::uniform_real_distribution<double> uyaw(-M_PI, M_PI);
    int wrongFree = 0, hits = 0, n = 0;
    while (n < 4000)
    {
        const int c = uc(rng), r = ur(rng);
        if (g->isBlocked(c, r) || field->cellDistance(c, r) > 4.0) continue;  // near obstacles only
        ++n;
        const Pose2 p{g->cellCenterX(c), g->cellCenterY(r), uyaw(rng)};
        for (double m : {0.0, 0.025})
        {
            const bool ref = bruteCollides(*g, grown(fc.vehicle(), m), p);
            hits += ref;
            if (ref && (m > 0 ? fc.isValidInflated(p, m) : fc.isValid(p))) ++wrongFree;
            if (!ref && m == 0 && !fc.isValidExact(p.x, p.y, p.yaw) &&
                !bruteCollides(*g, grown(fc.vehicle(), g->resolution() / 4), p))
                ++wrongFree;  // FCL reference disagrees with the brute force on a clear case
        }
    }
    EXPECT_EQ(wrongFree, 0) << "of " << n << " poses";
    EXPECT_GT(hits, 500);
}

// The planners with clothoid turns (`turns=clothoid`): round the wall of wallMap(), paper I's
// car, exact and drivable paths whose curvature changes within the vehicle's rate, to a goal
// pose on the lattice and to one off it, reached by the analytic expansion (clothoidCurves()).
TEST(CarLattice, ClothoidTurnsGivePathsWithinTheCurvatureRate)
{
    GridSetup setup = test::carSetup(SpaceKind::SE2);
    const VehicleParams v = VehicleParams::preset("paper-i");
    for (const std::string name : {"corner-astar", "improved-astar"})
    {
        const auto planner = configurePlanner(setup.ss->getSpaceInformation(), {name, {{"turns", "clothoid"}}, false, false});
        const QueryResult q = runQuery(setup, planner, {5, 5, M_PI / 2}, {55, 5, -M_PI / 2}, 30.0, false);
        ASSERT_EQ(q.status, ob::PlannerStatus::EXACT_SOLUTION) << name;
        EXPECT_TRUE(q.drivability.drivable) << name << ": " << q.drivability.reason;
        EXPECT_LE(q.drivability.maxCurvatureRate, 1.02 * v.curvatureRateLimit()) << name;
        // a goal pose off the lattice (position and heading): the analytic expansion ends the
        // path, with clothoid turns too (a Dubins curve's arcs there would break the rate)
        const QueryResult f = runQuery(setup, planner, {5, 5, M_PI / 2}, {52.37, 7.91, -1.2}, 30.0, false);
        ASSERT_EQ(f.status, ob::PlannerStatus::EXACT_SOLUTION) << name;
        EXPECT_TRUE(f.drivability.drivable) << name << ": " << f.drivability.reason;
        EXPECT_NEAR(f.path.back().x, 52.37, 1e-6);
        EXPECT_NEAR(f.path.back().y, 7.91, 1e-6);
        EXPECT_LE(f.drivability.maxCurvatureRate, 1.02 * v.curvatureRateLimit()) << name;
    }
}

// `turns=auto` (the default): clothoid turns towards a goal position (a route: within the
// rate), the arcs' lattice towards a goal pose (a manoeuvre: the same path as `turns=arc`).
TEST(CarLattice, TurnsAutoIsClothoidForRoutesAndArcsForPoses)
{
    GridSetup setup = test::carSetup(SpaceKind::SE2);
    const VehicleParams v = VehicleParams::preset("paper-i");
    const auto planner = [&](const char *turns) {
        PlannerParams p;
        if (turns) p.push_back({"turns", turns});
        return configurePlanner(setup.ss->getSpaceInformation(), {"corner-astar", p, false, false});
    };
    const auto byDefault = planner(nullptr);
    EXPECT_EQ(byDefault->params().getParam("turns")->getValue(), "auto");
    const QueryResult route = runQuery(setup, byDefault, {5, 5, M_PI / 2}, {55, 5, 0.0}, 30.0, /*freeGoalHeading=*/true);
    ASSERT_EQ(route.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(route.drivability.drivable) << route.drivability.reason;
    EXPECT_LE(route.drivability.maxCurvatureRate, 1.02 * v.curvatureRateLimit());
    const QueryResult pose = runQuery(setup, byDefault, {5, 5, M_PI / 2}, {55, 5, -M_PI / 2}, 30.0, false);
    const QueryResult arcs = runQuery(setup, planner("arc"), {5, 5, M_PI / 2}, {55, 5, -M_PI / 2}, 30.0, false);
    ASSERT_EQ(pose.status, ob::PlannerStatus::EXACT_SOLUTION);
    ASSERT_EQ(arcs.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(pose.path.size(), arcs.path.size());
    EXPECT_DOUBLE_EQ(pose.metrics.length, arcs.metrics.length);
    const QueryResult clothoid = runQuery(setup, planner("clothoid"), {5, 5, M_PI / 2}, {55, 5, -M_PI / 2}, 30.0, false);
    ASSERT_EQ(clothoid.status, ob::PlannerStatus::EXACT_SOLUTION);
    EXPECT_NE(clothoid.metrics.length, arcs.metrics.length);  // the choice really differs here
}
