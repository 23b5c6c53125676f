// OMPL's car spaces in gridcar set-ups (spaces/CarSpaces.h): the motion validator along the
// curves, OMPL's planners returning drivable Reeds-Shepp / Dubins paths (checked by the
// independent dense check), cusps in the metrics and the driving time (core/Cusps.h).
#include "gridcar/core/Cusps.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/path/PathMetrics.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/spaces/CarSpaces.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"
#include "gridcar/vehicle/Dynamics.h"

#include <gtest/gtest.h>

#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <cmath>
#include <memory>

using namespace gridcar;
using namespace gridcar::test;

TEST(CarSpaces, NamesAndMisuse)
{
    EXPECT_EQ(parseSpaceKind("reeds-shepp"), SpaceKind::ReedsShepp);
    EXPECT_EQ(spaceKindName(parseSpaceKind("dubins")), "dubins");
    EXPECT_THROW(parseSpaceKind("hybrid"), std::invalid_argument);
    SetupOptions o;
    o.space = SpaceKind::ReedsShepp;
    try
    {
        makeGridSetup(wallMap(), VehicleParams::preset("point"), o);
        FAIL() << "a point vehicle has no turning radius";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("turning radius"), std::string::npos) << e.what();
    }
}

TEST(CarSpaces, MotionValidatorChecksTheFootprintAlongTheCurve)
{
    const GridSetup s = carSetup(SpaceKind::ReedsShepp);
    const auto &si = s.ss->getSpaceInformation();
    ASSERT_TRUE(std::dynamic_pointer_cast<CurveMotionValidator>(si->getMotionValidator()));
    ompl::base::State *a = si->allocState(), *b = si->allocState(), *last = si->allocState();
    // both ends free, the straight line between them crosses the wall
    setPose(a, {20, 15, 0});
    setPose(b, {40, 15, 0});
    EXPECT_TRUE(si->isValid(a) && si->isValid(b));
    EXPECT_FALSE(si->checkMotion(a, b));
    std::pair<ompl::base::State *, double> lv(last, 0.0);
    EXPECT_FALSE(si->checkMotion(a, b, lv));
    // the last valid pose is just before the wall: the front bumper short of it, within a step
    const VehicleParams &v = s.checker->vehicle();
    const double front = v.length - v.rearOverhang;
    EXPECT_LT(toPose(last).x + front, 30.0);
    EXPECT_GT(toPose(last).x + front, 30.0 - 0.5);
    // a motion in the open above the wall is fine
    setPose(a, {20, 36, 0});
    setPose(b, {40, 36, 0});
    EXPECT_TRUE(si->checkMotion(a, b));
    for (auto *st : {a, b, last}) si->freeState(st);
}

TEST(CarSpaces, OmplPlannersReturnDrivablePathsOnReedsSheppAndDubins)
{
    // round the wall: every exact solution must pass the independent 2 cm FCL check with
    // curvature within K_max (Reeds-Shepp paths split at their cusps)
    int exact = 0;
    for (SpaceKind kind : {SpaceKind::ReedsShepp, SpaceKind::Dubins})
        for (const char *name : {"rrtconnect", "rrtconnect+simplify", "rrtstar"})
            for (int attempt = 1; attempt <= 3; ++attempt)
            {
                SCOPED_TRACE(spaceKindName(kind) + " " + name + " attempt " + std::to_string(attempt));
                GridSetup s = carSetup(kind);
                auto planner = configurePlanner(s.ss->getSpaceInformation(), {name, {}, false, false});
                const QueryResult q = runQuery(s, planner, {10, 10, 0}, {50, 10, 0}, 1.0);
                if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
                ++exact;
                EXPECT_TRUE(q.drivability.drivable) << q.drivability.reason;
                DrivabilityOptions o;
                o.reversing = kind == SpaceKind::ReedsShepp;
                const Drivability d = checkDrivable(q.path, *s.checker, o);
                EXPECT_TRUE(d.drivable) << d.reason;
                EXPECT_LE(d.maxCurvature, s.checker->vehicle().maxCurvature() * 1.001);
                if (kind == SpaceKind::Dubins) EXPECT_EQ(q.metrics.cusps, 0);
            }
    EXPECT_GE(exact, 9) << "of 18 queries, so few exact solutions that the check proves little";
}

TEST(CarSpaces, CuspsSplitMetricsAndCostAStop)
{
    // 10 m forwards along +x, then 5 m in reverse: the yaw stays +x while the car moves along -x
    std::vector<Pose2> fwdBack, straight;
    for (int i = 0; i <= 100; ++i) fwdBack.push_back({0.1 * i, 0, 0});
    for (int i = 99; i >= 50; --i) fwdBack.push_back({0.1 * i, 0, 0});
    for (int i = 0; i <= 150; ++i) straight.push_back({0.1 * i, 0, 0});
    const auto pieces = splitAtCusps(fwdBack);
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_FALSE(pieces[0].backward);
    EXPECT_TRUE(pieces[1].backward);
    EXPECT_NEAR(pieces[1].poses.front().x, 10.0, 1e-9);  // the cusp pose is shared
    EXPECT_EQ(splitAtCusps(straight).size(), 1u);
    const PathMetrics m = computePathMetrics(fwdBack, nullptr, TurnParams(), true);
    EXPECT_EQ(m.cusps, 1);
    EXPECT_NEAR(m.length, 15.0, 1e-9);
    EXPECT_LT(m.maxCurvature, 1e-6) << "the reversal is no curvature";
    EXPECT_EQ(computePathMetrics(straight, nullptr, TurnParams(), true).cusps, 0);
    // the same 15 m with a stop in the middle take longer than in one go
    const VehicleParams v = VehicleParams::preset("paper-i");
    DrivingTimeParams rev;
    rev.reversing = true;
    const double tSplit = drivingTime(fwdBack, v, rev), tStraight = drivingTime(straight, v, rev);
    // (the piece driven backwards at the reverse speed limit)
    VehicleParams back = v;
    back.maxSpeed = reverseSpeedLimit(v);
    EXPECT_LT(back.maxSpeed, v.maxSpeed);
    EXPECT_NEAR(tSplit, drivingTime(std::vector<Pose2>(fwdBack.begin(), fwdBack.begin() + 101), v) +
                            drivingTime(pieces[1].poses, back),
                1e-9);
    EXPECT_GT(tSplit, tStraight + 0.5);
    // a grid path's first step against a start yaw it ignores is no cusp
    const std::vector<Pose2> grid{{0, 0, 0}, {-1, 0, M_PI}, {-2, 0, M_PI}, {-3, 0, M_PI}};
    EXPECT_EQ(splitAtCusps(grid).size(), 1u);
}
