// Continuous curvature: the G2 quintic against Eigen's spline module, smoothCurvature() on
// bang-bang paths, the drivable check's curvature rate, and the car-lattice planners' paths.
#include "PlannerTestUtil.h"

#include "gridcar/path/PathMetrics.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/core/Angles.h"
#include "gridcar/curves/ClothoidTurns.h"
#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>
#include <unsupported/Eigen/Splines>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace gridcar;
namespace ob = ompl::base;

namespace
{
/// Straight @p a metres, an arc of radius @p r turning by @p turn (signed), straight @p b
/// metres, sampled every @p ds: the curvature jumps 0 -> 1/r -> 0, as a lattice path's does;
/// then @p tail metres of arc at 1/r in two steps (a Reeds-Shepp shot landing on its goal).
std::vector<Pose2> straightArcStraight(double a, double r, double turn, double b, double ds, Pose2 p = {0, 0, 0},
                                       double tail = 0)
{
    std::vector<Pose2> out{p};
    auto go = [&](double len, double k) {
        const int n = std::max(1, int(std::ceil(len / ds)));
        for (int i = 0; i < n; ++i)
        {
            const double s = len / n;
            if (k == 0)
                p = {p.x + s * std::cos(p.yaw), p.y + s * std::sin(p.yaw), p.yaw};
            else
            {
                const double y2 = p.yaw + s * k;
                p = {p.x + (std::sin(y2) - std::sin(p.yaw)) / k, p.y - (std::cos(y2) - std::cos(p.yaw)) / k, wrapAngle(y2)};
            }
            out.push_back(p);
        }
    };
    go(a, 0.0);
    go(std::abs(turn) * r, turn > 0 ? 1.0 / r : -1.0 / r);
    go(b, 0.0);
    if (tail > 0) go(tail, 1.0 / r), go(tail / 2, 1.0 / r);
    return out;
}

CurvatureSmoothingOptions options(double kmax, double sigma)
{
    CurvatureSmoothingOptions o;
    o.maxCurvature = kmax;
    o.maxCurvatureRate = sigma;
    o.step = 0.02;
    o.free = [](const std::vector<Pose2> &) { return true; };
    return o;
}
/// Straight @p a metres, a clothoid turn (ClothoidTurn: curvature up to 1 / @p r at @p sigma
/// and back) of @p turn radians, straight @p b metres, sampled every @p ds from the origin:
/// within the rate already, as a lattice path of clothoid turns is.
std::vector<Pose2> straightClothoidStraight(double a, double r, double sigma, double turn, double b, double ds)
{
    std::vector<Pose2> out{{0.0, 0.0, 0.0}};
    const ClothoidTurn t(r, sigma);
    const double len = t.length(turn);
    const Pose2 e = t.pose(turn, len);
    const int na = int(std::ceil(a / ds)), nt = int(std::ceil(len / ds)), nb = int(std::ceil(b / ds));
    for (int i = 1; i <= na; ++i) out.push_back({a * i / na, 0.0, 0.0});
    for (int i = 1; i <= nt; ++i)
    {
        const Pose2 q = t.pose(turn, len * i / nt);
        out.push_back({a + q.x, q.y, wrapAngle(q.yaw)});
    }
    for (int i = 1; i <= nb; ++i)
        out.push_back({a + e.x + b * i / nb * std::cos(e.yaw), e.y + b * i / nb * std::sin(e.yaw), wrapAngle(e.yaw)});
    return out;
}
}  // namespace

// Our quintic is the same curve as Eigen's clamped quintic B-spline on its Bezier points: the
// position and its first three derivatives agree, and so curvature and its rate, computed from
// Eigen's derivatives, agree with G2Quintic's.
TEST(ContinuousCurvature, QuinticAgreesWithEigenSplines)
{
    const G2Quintic q({0.0, 0.0, 0.2}, 0.1, {6.0, 2.5, 1.1}, -0.3, 7.0);
    const auto b = q.bezierPoints();
    Eigen::Matrix<double, 2, 6> ctrl;
    for (int j = 0; j < 6; ++j) ctrl.col(j) << b[std::size_t(j)][0], b[std::size_t(j)][1];
    Eigen::Matrix<double, 1, 12> knots;
    knots << 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1;
    const Eigen::Spline<double, 2, 5> spline(knots, ctrl);
    for (int i = 0; i <= 50; ++i)
    {
        const double u = i / 50.0;
        const auto d = q.derivatives(u);
        const Eigen::Matrix<double, 2, 4> e = spline.derivatives(u, 3);
        for (int k = 0; k < 4; ++k)
        {
            EXPECT_NEAR(d[std::size_t(k)][0], e(0, k), 1e-9 * (1 + std::abs(e(0, k)))) << "u " << u << " order " << k;
            EXPECT_NEAR(d[std::size_t(k)][1], e(1, k), 1e-9 * (1 + std::abs(e(1, k)))) << "u " << u << " order " << k;
        }
        const double sp = std::hypot(e(0, 1), e(1, 1));
        const double kEigen = (e(0, 1) * e(1, 2) - e(1, 1) * e(0, 2)) / (sp * sp * sp);
        EXPECT_NEAR(q.curvature(u), kEigen, 1e-9);
        // the rate against a central difference of Eigen's curvature over arc length
        if (i > 0 && i < 50)
        {
            const double h = 1e-5;
            auto kAt = [&](double uu) {
                const Eigen::Matrix<double, 2, 3> f = spline.derivatives(uu, 2);
                const double s = std::hypot(f(0, 1), f(1, 1));
                return (f(0, 1) * f(1, 2) - f(1, 1) * f(0, 2)) / (s * s * s);
            };
            EXPECT_NEAR(q.curvatureRate(u), (kAt(u + h) - kAt(u - h)) / (2 * h) / sp, 1e-5);
        }
    }
    // the end conditions: the poses' tangents and the curvatures asked for
    EXPECT_NEAR(q.curvature(0.0), 0.1, 1e-12);
    EXPECT_NEAR(q.curvature(1.0), -0.3, 1e-12);
    const auto d1 = q.derivatives(1.0);
    EXPECT_NEAR(std::atan2(d1[1][1], d1[1][0]), 1.1, 1e-12);
    EXPECT_NEAR(d1[0][0], 6.0, 1e-12);
    EXPECT_NEAR(d1[0][1], 2.5, 1e-12);
}

// A turn, 1 m of straight, and 2 cm at full lock onto the goal: the last jump has room only if
// it is smoothed with the turn's (it was left in place, 45 times over the rate)
TEST(ContinuousCurvature, AShortArcOntoTheGoalIsSmoothedWithTheTurnBeforeIt)
{
    const double kmax = 0.53, sigma = 0.4;
    for (double b : {1.0, 1.4, 1.7, 2.0, 2.5})
    {
        const std::vector<Pose2> in = straightArcStraight(10.0, 1.01 / kmax, -M_PI / 4, b, 0.05, {2, 1, 0.3}, 0.011);
        const CurvatureSmoothing r = smoothCurvature(in, options(kmax, sigma));
        EXPECT_LE(curvatureRateProfile(r.path).maxRate, 1.02 * sigma) << b;
        EXPECT_DOUBLE_EQ(r.path.back().yaw, in.back().yaw);
    }
}

// A 90-degree turn at full lock between long straights (a lattice corner): the jumps are
// replaced, the rate is within the limit by the polyline's own measure, curvature within K_max,
// the end poses kept exactly, and the path no longer than before.
TEST(ContinuousCurvature, BangBangTurnBecomesContinuousWithinTheRate)
{
    const double kmax = 0.25, sigma = 0.13;
    for (double turn : {M_PI / 2, -M_PI / 2, M_PI / 8})
    {
        SCOPED_TRACE(turn);
        const std::vector<Pose2> in = straightArcStraight(15.0, 1.01 / kmax, turn, 15.0, 0.05, {3.0, -2.0, 0.4});
        ASSERT_GT(curvatureRateProfile(in).maxRate, 10 * sigma);  // the jumps are there
        const CurvatureSmoothing r = smoothCurvature(in, options(kmax, sigma));
        EXPECT_GT(r.stretches, 0);
        EXPECT_EQ(r.replaced, r.stretches);
        const CurvatureProfile prof = curvatureRateProfile(r.path);
        EXPECT_LE(prof.maxRate, 1.02 * sigma);
        EXPECT_LE(prof.maxCurvature, kmax * 1.001);
        EXPECT_LE(r.maxRate, 1.02 * sigma);
        EXPECT_DOUBLE_EQ(r.path.front().x, in.front().x);
        EXPECT_DOUBLE_EQ(r.path.back().x, in.back().x);
        EXPECT_DOUBLE_EQ(r.path.back().y, in.back().y);
        EXPECT_DOUBLE_EQ(r.path.back().yaw, in.back().yaw);
        EXPECT_LE(pathLength(r.path), pathLength(in) * 1.01);
        // consecutive poses close together and yaws along the motion
        for (std::size_t i = 1; i < r.path.size(); ++i)
        {
            const double dx = r.path[i].x - r.path[i - 1].x, dy = r.path[i].y - r.path[i - 1].y;
            ASSERT_LE(std::hypot(dx, dy), 0.06);
            ASSERT_LT(std::abs(wrapAngle(std::atan2(dy, dx) - r.path[i].yaw)), 0.05);
        }
    }
}

// A clothoid turn at full lock between long straights (within the rate already): widenTurns()
// replaces it by a wider turn, with a lower peak curvature, curvature 0 where it meets the
// straights, a rate that the steering keeps up with at the wider turn's speed (sigma
// sqrt(k_peak / K_max)), the same ends and turning, and no longer.
TEST(ContinuousCurvature, WidenTurnsOpensAFullLockTurnWhereThereIsRoom)
{
    const double kmax = 0.25, sigma = 0.13;
    for (double turn : {M_PI / 2, -M_PI / 3})
    {
        SCOPED_TRACE(turn);
        const std::vector<Pose2> in = straightClothoidStraight(20.0, 1.0 / kmax, sigma, turn, 20.0, 0.05);
        const CurvatureProfile before = curvatureRateProfile(in);
        ASSERT_LE(before.maxRate, 1.02 * sigma);
        ASSERT_GT(before.maxCurvature, 0.8 * kmax);
        const CurvatureSmoothing r = widenTurns(in, options(kmax, sigma));
        EXPECT_EQ(r.stretches, 1);
        EXPECT_EQ(r.replaced, 1);
        const CurvatureProfile after = curvatureRateProfile(r.path);
        EXPECT_LT(after.maxCurvature, 0.6 * before.maxCurvature);
        EXPECT_LE(after.maxRate, 1.02 * sigma * std::sqrt(after.maxCurvature / kmax));
        EXPECT_LE(pathLength(r.path), pathLength(in) + 1e-6);
        EXPECT_DOUBLE_EQ(r.path.front().x, in.front().x);
        EXPECT_DOUBLE_EQ(r.path.back().x, in.back().x);
        EXPECT_DOUBLE_EQ(r.path.back().y, in.back().y);
        EXPECT_DOUBLE_EQ(r.path.back().yaw, in.back().yaw);
        double turned = 0;
        for (std::size_t i = 1; i < r.path.size(); ++i)
        {
            const double dx = r.path[i].x - r.path[i - 1].x, dy = r.path[i].y - r.path[i - 1].y;
            ASSERT_LT(std::abs(wrapAngle(std::atan2(dy, dx) - r.path[i].yaw)), 0.05);
            turned += wrapAngle(r.path[i].yaw - r.path[i - 1].yaw);
        }
        EXPECT_NEAR(turned, turn, 1e-6);
    }
}

// Room only near the turn (the free test refuses any pose more than 1.5 m from the input): the
// turn is widened less or kept, never leaves the room, and stays within the rate; with no room
// at all the path is returned as it was.
TEST(ContinuousCurvature, WidenTurnsStaysWhereTheFreeTestAllows)
{
    const double kmax = 0.25, sigma = 0.13;
    const std::vector<Pose2> in = straightClothoidStraight(20.0, 1.0 / kmax, sigma, M_PI / 2, 20.0, 0.05);
    const auto near = [&in](const Pose2 &q) {
        double best = 1e9;
        for (const Pose2 &p : in) best = std::min(best, std::hypot(p.x - q.x, p.y - q.y));
        return best;
    };
    CurvatureSmoothingOptions o = options(kmax, sigma);
    o.free = [&](const std::vector<Pose2> &poses) {
        return std::all_of(poses.begin(), poses.end(), [&](const Pose2 &q) { return near(q) <= 1.5; });
    };
    const CurvatureSmoothing r = widenTurns(in, o);
    for (const Pose2 &q : r.path) ASSERT_LE(near(q), 1.5 + 1e-9);
    EXPECT_LE(curvatureRateProfile(r.path).maxRate, 1.02 * sigma);
    EXPECT_LE(pathLength(r.path), pathLength(in) + 1e-6);
    EXPECT_DOUBLE_EQ(r.path.back().yaw, in.back().yaw);

    o.free = [](const std::vector<Pose2> &) { return false; };
    const CurvatureSmoothing kept = widenTurns(in, o);
    EXPECT_EQ(kept.replaced, 0);
    ASSERT_EQ(kept.path.size(), in.size());
    for (std::size_t i = 0; i < in.size(); ++i) EXPECT_DOUBLE_EQ(kept.path[i].x, in[i].x);
    o.free = nullptr;
    EXPECT_THROW(widenTurns(in, o), std::invalid_argument);
}

// A turn of 115 degrees at full lock is more than one quintic within the rate can replace
// between the straights' poses: whatever is done, the result is no worse than its input (end
// poses, K_max, no faster change of curvature, no longer).
TEST(ContinuousCurvature, LargeTurnIsNoWorseThanItsInput)
{
    const double kmax = 0.25, sigma = 0.13;
    const std::vector<Pose2> in = straightArcStraight(15.0, 1.01 / kmax, 2.0, 15.0, 0.05);
    const CurvatureSmoothing r = smoothCurvature(in, options(kmax, sigma));
    EXPECT_LE(r.maxRate, curvatureRateProfile(in).maxRate * 1.0001);
    EXPECT_LE(curvatureRateProfile(r.path).maxCurvature, kmax * 1.001);
    EXPECT_LE(pathLength(r.path), pathLength(in) * 1.01);
    EXPECT_DOUBLE_EQ(r.path.back().x, in.back().x);
    EXPECT_DOUBLE_EQ(r.path.back().yaw, in.back().yaw);
}

// Where nothing may change (every candidate collides) the path is returned as it was; the
// stretches are counted but none replaced; a stopped smoothing leaves the input too.
TEST(ContinuousCurvature, KeepsThePathWhereNoReplacementIsFree)
{
    const std::vector<Pose2> in = straightArcStraight(10.0, 4.0, M_PI / 2, 10.0, 0.05);
    CurvatureSmoothingOptions o = options(0.25, 0.13);
    o.free = [](const std::vector<Pose2> &) { return false; };
    const CurvatureSmoothing r = smoothCurvature(in, o);
    EXPECT_GT(r.stretches, 0);
    EXPECT_EQ(r.replaced, 0);
    ASSERT_EQ(r.path.size(), in.size());
    for (std::size_t i = 0; i < in.size(); ++i) EXPECT_DOUBLE_EQ(r.path[i].x, in[i].x);
    CurvatureSmoothingOptions c = options(0.25, 0.13);
    c.cancelled = [] { return true; };
    const CurvatureSmoothing rc = smoothCurvature(in, c);
    EXPECT_TRUE(rc.cancelled);
    EXPECT_EQ(rc.path.size(), in.size());
    CurvatureSmoothingOptions bad = options(0.25, 0.0);
    EXPECT_THROW(smoothCurvature(in, bad), std::invalid_argument);
    bad = options(0.25, 0.1);
    bad.free = nullptr;
    EXPECT_THROW(smoothCurvature(in, bad), std::invalid_argument);
}

// A path with a cusp: each piece smoothed on its own, the cusp pose kept, the reversed piece's
// yaws still against its motion.
TEST(ContinuousCurvature, CuspsAreKept)
{
    std::vector<Pose2> fwd = straightArcStraight(8.0, 4.0, M_PI / 4, 8.0, 0.05);
    std::vector<Pose2> back = straightArcStraight(8.0, 4.0, M_PI / 4, 8.0, 0.05,
                                                  {fwd.back().x, fwd.back().y, wrapAngle(fwd.back().yaw + M_PI)});
    std::vector<Pose2> path = fwd;
    for (std::size_t i = 1; i < back.size(); ++i)
        path.push_back({back[i].x, back[i].y, wrapAngle(back[i].yaw + M_PI)});  // body yaw: motion turned round
    CurvatureSmoothingOptions o = options(0.25, 0.2);
    o.reversing = true;
    const CurvatureSmoothing r = smoothCurvature(path, o);
    const std::vector<PathPiece> pieces = splitAtCusps(r.path);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_FALSE(pieces[0].backward);
    EXPECT_TRUE(pieces[1].backward);
    EXPECT_NEAR(pieces[0].poses.back().x, fwd.back().x, 1e-12);
    EXPECT_NEAR(pieces[0].poses.back().y, fwd.back().y, 1e-12);
    for (const PathPiece &p : pieces) EXPECT_LE(curvatureRateProfile(p.poses).maxRate, 1.02 * 0.2);
    EXPECT_EQ(r.replaced, r.stretches);
}

// The drivable check measures the rate and, when asked, refuses a path above it with the
// place; without the option the rate is only reported.
TEST(ContinuousCurvature, DrivableCheckMeasuresTheRate)
{
    auto grid = std::make_shared<OccupancyGrid>(600, 600, 0.1, CellState::Free);
    const GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-i"));
    const double kmax = s.checker->vehicle().maxCurvature();
    const std::vector<Pose2> in = straightArcStraight(15.0, 1.01 / kmax, M_PI / 2, 15.0, 0.05, {5.0, 5.0, 0.0});
    DrivabilityOptions o;
    Drivability d = checkDrivable(in, *s.checker, o);
    EXPECT_TRUE(d.drivable) << d.reason;
    EXPECT_GT(d.maxCurvatureRate, 1.0);
    // at the arc's entry or its exit (the same jump)
    const double exitAt = 15.0 + M_PI / 2 * 1.01 / kmax;
    EXPECT_LT(std::min(std::abs(d.maxCurvatureRateAt - 15.0), std::abs(d.maxCurvatureRateAt - exitAt)), 0.2);
    o.maxCurvatureRate = 0.4;
    d = checkDrivable(in, *s.checker, o);
    EXPECT_FALSE(d.drivable);
    EXPECT_NE(d.reason.find("curvature changes"), std::string::npos) << d.reason;
    const CurvatureSmoothing r = smoothCurvature(in, options(kmax, 0.4));
    d = checkDrivable(r.path, *s.checker, o);
    EXPECT_TRUE(d.drivable) << d.reason;
}

// The vehicle's rate: presets carry one, a YAML field overrides it, an unset one follows the
// steering rate at the speed of a turn at R_min, scaling keeps the same manoeuvres.
TEST(ContinuousCurvature, VehicleCurvatureRate)
{
    EXPECT_DOUBLE_EQ(VehicleParams::preset("paper-i").curvatureRateLimit(), 0.4);
    EXPECT_DOUBLE_EQ(VehicleParams::preset("paper-c-car").curvatureRateLimit(), 0.13);
    EXPECT_TRUE(std::isinf(VehicleParams::preset("point").curvatureRateLimit()));
    VehicleParams v = VehicleParams::preset("paper-c-car");
    v.maxCurvatureRate = 0.0;
    const double derived = v.curvatureRateLimit();
    EXPECT_NEAR(derived, (60.0 * M_PI / 180 / 2.7) / std::sqrt(2.4 * v.minTurningRadius()), 1e-12);
    EXPECT_NEAR(derived, 0.13, 0.01);  // the preset's value is this rule's, rounded
    EXPECT_NEAR(VehicleParams::preset("paper-c-car").scaled(0.5).curvatureRateLimit(), 0.52, 1e-12);
    v.maxCurvatureRate = -1;
    EXPECT_THROW(v.validate(), std::invalid_argument);
}

// The car-lattice planners' paths with continuous_curvature (the default) against the same
// planner without: on an open map with a 90-degree change of heading, both exact, drivable,
// at the goal pose; the curvature never changes faster than without, and the lattice's
// bang-bang arcs (a jump between two samples) are gone from corner-astar's path.
TEST(ContinuousCurvature, PlannersReturnPathsWithinTheRate)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto grid = std::make_shared<OccupancyGrid>(500, 500, 0.1, CellState::Free);
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        double ccRate = 0;
        for (bool cc : {true, false})
        {
            SCOPED_TRACE(std::string(name) + (cc ? " cc" : " plain"));
            GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-i"));
            auto p = makePlanner(s.ss->getSpaceInformation(), name);
            p->params().setParam("continuous_curvature", cc ? "1" : "0");
            s.ss->setPlanner(p);
            s.setStartAndGoal({8.0, 8.0, 0.0}, {38.0, 40.0, M_PI / 2});
            ASSERT_EQ(s.ss->solve(5.0), ob::PlannerStatus::EXACT_SOLUTION);
            const std::vector<Pose2> path = toPoses(s.ss->getSolutionPath());
            DrivabilityOptions o;
            o.reversing = true;
            o.maxCurvatureRate = s.checker->vehicle().curvatureRateLimit();
            const Drivability d = checkDrivable(path, *s.checker, o);
            EXPECT_TRUE(d.drivable || d.reason.find("curvature changes") != std::string::npos) << d.reason;
            if (cc)
                ccRate = d.maxCurvatureRate;
            else
                EXPECT_LE(ccRate, d.maxCurvatureRate * 1.0001) << "continuous_curvature made the rate worse";
            if (cc && std::string(name) == "corner-astar") EXPECT_TRUE(d.drivable) << d.reason;
            if (!cc) EXPECT_FALSE(d.drivable);  // full-lock arcs joined to straights
            EXPECT_NEAR(path.back().x, 38.0, 1e-6);
            EXPECT_NEAR(path.back().y, 40.0, 1e-6);
            EXPECT_NEAR(wrapAngle(path.back().yaw - M_PI / 2), 0.0, 1e-6);
        }
    }
    GridSetup s = makeGridSetup(grid, VehicleParams::preset("paper-i"));
    auto p = std::dynamic_pointer_cast<CarLatticePlanner>(makePlanner(s.ss->getSpaceInformation(), "corner-astar"));
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->params().setParam("curvature_rate", "-1"));
    EXPECT_FALSE(p->params().setParam("curvature_rate", "nan"));
    ASSERT_TRUE(p->params().setParam("curvature_rate", "0.7"));
    EXPECT_DOUBLE_EQ(p->curvatureRate(), 0.7);
    ASSERT_TRUE(p->params().setParam("continuous_curvature", "false"));
    EXPECT_DOUBLE_EQ(p->curvatureRate(), 0.0);
}
