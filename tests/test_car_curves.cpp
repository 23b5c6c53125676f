// gridcar's Dubins and Reeds-Shepp curves (include/gridcar/curves/CarCurves.h) against OMPL's:
// the same shortest lengths on a million random pose pairs each, every curve landing on its
// goal, and the degenerate cases (equal positions, collinear poses, headings at +-pi) on which
// OMPL's assertions are the risk, where ours must still give a curve that lands.
#include "gridcar/curves/CarCurves.h"

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include <cmath>
#include <cstdlib>
#include <random>

namespace
{
using gridcar::CarCurve;
using gridcar::Pose2;

/// How far the curve's end is from @p b (position in m, heading in rad, the larger).
double landingError(const Pose2 &a, const Pose2 &b, const CarCurve &c)
{
    const Pose2 e = gridcar::curvePose(a, c, c.length);
    return std::max(std::hypot(e.x - b.x, e.y - b.y), std::abs(std::remainder(e.yaw - b.yaw, 2 * M_PI)));
}

/// Pairs to draw: 10^6 by default (GRIDCAR_CURVE_PAIRS changes it, e.g. for a quick look).
int pairCount()
{
    const char *env = std::getenv("GRIDCAR_CURVE_PAIRS");
    return env ? std::max(1, std::atoi(env)) : 1000000;
}

template <class Space, class Ours>
void compareWithOmpl(Ours ours, int pairs, unsigned seed)
{
    auto space = std::make_shared<Space>(1.0);
    ompl::base::ScopedState<ompl::base::SE2StateSpace> sa(space), sb(space);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-8.0, 8.0), yaw(-M_PI, M_PI), radius(0.5, 8.0);
    int shorter = 0;
    double worstLanding = 0.0;
    for (int i = 0; i < pairs; ++i)
    {
        const double r = radius(rng);
        // positions in units of the radius, so that every word family comes up
        const Pose2 a{r * pos(rng), r * pos(rng), yaw(rng)}, b{r * pos(rng), r * pos(rng), yaw(rng)};
        const CarCurve c = ours(a, b, r);
        ASSERT_FALSE(c.empty()) << "no curve for pair " << i;
        sa->setXY(a.x / r, a.y / r);
        sa->setYaw(a.yaw);
        sb->setXY(b.x / r, b.y / r);
        sb->setYaw(b.yaw);
        const double omplLength = r * space->distance(sa.get(), sb.get());
        // never longer than OMPL's; shorter only if it lands (it always must)
        ASSERT_LE(c.length, omplLength + 1e-7 * r) << "pair " << i;
        if (c.length < omplLength - 1e-7 * r) ++shorter;
        worstLanding = std::max(worstLanding, landingError(a, b, c) / r);
    }
    EXPECT_LT(worstLanding, 1e-6);
    // OMPL picks the true shortest word; ours may only win by rounding, never by a real margin
    EXPECT_EQ(shorter, 0);
}

TEST(CarCurves, DubinsLengthsMatchOmplOnAMillionPairs)
{
    compareWithOmpl<ompl::base::DubinsStateSpace>(gridcar::dubinsCurve, pairCount(), 1);
}

TEST(CarCurves, ReedsSheppLengthsMatchOmplOnAMillionPairs)
{
    compareWithOmpl<ompl::base::ReedsSheppStateSpace>(gridcar::reedsSheppCurve, pairCount(), 2);
}

TEST(CarCurves, DubinsIsForwardOnlyAndReedsSheppNoLongerThanDubins)
{
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-20.0, 20.0), yaw(-M_PI, M_PI);
    for (int i = 0; i < 20000; ++i)
    {
        const Pose2 a{pos(rng), pos(rng), yaw(rng)}, b{pos(rng), pos(rng), yaw(rng)};
        const CarCurve d = gridcar::dubinsCurve(a, b, 3.0), rs = gridcar::reedsSheppCurve(a, b, 3.0);
        for (int s = 0; s < d.count; ++s) ASSERT_GE(d.segments[s].length, 0.0);
        ASSERT_EQ(d.cusps(), 0);
        ASSERT_LE(rs.length, d.length + 1e-9);
    }
}

/// Degenerate pairs: equal positions (with equal, opposite, and nearly equal headings),
/// collinear poses ahead, behind and beside, headings exactly at +-pi, and tiny offsets.
std::vector<std::pair<Pose2, Pose2>> degeneratePairs()
{
    std::vector<std::pair<Pose2, Pose2>> v;
    const double headings[] = {0.0, M_PI, -M_PI, M_PI / 2, -M_PI / 2, 1e-12, -1e-12, M_PI - 1e-12, 2 * M_PI, 3.0};
    const double offsets[] = {0.0, 1e-12, 1e-9, 1e-6, 0.5, 2.0, 4.0, 4.0 + 1e-12, 100.0};
    for (double h0 : headings)
        for (double h1 : headings)
            for (double d : offsets)
            {
                v.push_back({{1.0, 2.0, h0}, {1.0 + d, 2.0, h1}});                            // ahead / behind on x
                v.push_back({{1.0, 2.0, h0}, {1.0, 2.0 + d, h1}});                            // beside
                v.push_back({{1.0, 2.0, h0}, {1.0 + d * std::cos(h0), 2.0 + d * std::sin(h0), h0}});  // straight on
            }
    return v;
}

TEST(CarCurves, DegenerateCasesGiveCurvesThatLand)
{
    for (const auto &[a, b] : degeneratePairs())
        for (double r : {1.0, 3.86})
        {
            const CarCurve d = gridcar::dubinsCurve(a, b, r), rs = gridcar::reedsSheppCurve(a, b, r);
            ASSERT_FALSE(d.empty());
            ASSERT_FALSE(rs.empty());
            EXPECT_LT(landingError(a, b, d), 1e-5) << a.x << "," << a.y << "," << a.yaw << " -> " << b.x << "," << b.y << "," << b.yaw;
            EXPECT_LT(landingError(a, b, rs), 1e-5);
            EXPECT_LE(rs.length, d.length + 1e-9);
        }
    // equal poses: no motion; straight ahead: the straight line
    EXPECT_EQ(gridcar::dubinsCurve({1, 2, 0.3}, {1, 2, 0.3}, 2.0).length, 0.0);
    EXPECT_EQ(gridcar::reedsSheppCurve({1, 2, M_PI}, {1, 2, -M_PI}, 2.0).length, 0.0);
    EXPECT_NEAR(gridcar::dubinsCurve({0, 0, 0}, {10, 0, 0}, 2.0).length, 10.0, 1e-12);
    EXPECT_NEAR(gridcar::reedsSheppCurve({0, 0, 0}, {-10, 0, 0}, 2.0).length, 10.0, 1e-12);
    const CarCurve back = gridcar::reedsSheppCurve({0, 0, 0}, {-10, 0, 0}, 2.0);
    for (int i = 0; i < back.count; ++i)  // the word keeps its arcs of length 0
        EXPECT_EQ(back.segments[i].length, back.segments[i].steer == gridcar::Steer::Straight ? -10.0 : 0.0);
    EXPECT_EQ(back.cusps(), 0);
}

TEST(CarCurves, NonFiniteInputGivesNoCurve)
{
    const double nan = std::nan("");
    EXPECT_TRUE(gridcar::dubinsCurve({nan, 0, 0}, {1, 1, 0}, 1.0).empty());
    EXPECT_TRUE(gridcar::reedsSheppCurve({0, 0, 0}, {1, 1, INFINITY}, 1.0).empty());
    EXPECT_TRUE(gridcar::dubinsCurve({0, 0, 0}, {1, 1, 0}, 0.0).empty());
}

TEST(CarCurves, SamplingFollowsTheSegmentsAtTheRadius)
{
    // a quarter turn left of radius 2 then 3 m straight: known poses along it
    const CarCurve c = gridcar::dubinsCurve({0, 0, 0}, {2, 5, M_PI / 2}, 2.0);
    ASSERT_EQ(c.count, 3);  // L, S and a last arc of length 0
    EXPECT_NEAR(c.length, M_PI + 3.0, 1e-9);
    const Pose2 mid = gridcar::curvePose({0, 0, 0}, c, M_PI / 2);  // half the arc
    EXPECT_NEAR(mid.x, 2 * std::sin(M_PI / 4), 1e-9);
    EXPECT_NEAR(mid.y, 2 - 2 * std::cos(M_PI / 4), 1e-9);
    EXPECT_NEAR(mid.yaw, M_PI / 4, 1e-9);
    // samples 1 cm apart are never farther apart than 1 cm (arc length parametrisation)
    const CarCurve rs = gridcar::reedsSheppCurve({0, 0, 0}, {0.5, 1.0, M_PI}, 1.0);
    Pose2 prev = gridcar::curvePose({0, 0, 0}, rs, 0.0);
    for (double s = 0.01; s <= rs.length; s += 0.01)
    {
        const Pose2 p = gridcar::curvePose({0, 0, 0}, rs, s);
        ASSERT_LE(std::hypot(p.x - prev.x, p.y - prev.y), 0.01 + 1e-12);
        prev = p;
    }
}

}  // namespace

// The analytic expansion's alternatives: the k shortest distinct words, shortest first, the
// first the shortest curve itself, every one landing on the goal; Reeds-Shepp has more of them.
TEST(CarCurves, TheShortestWordsComeShortestFirstAndAllLand)
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> xy(-8, 8), yaw(-M_PI, M_PI);
    int moreRs = 0;
    for (int k = 0; k < 2000; ++k)
    {
        const Pose2 a{xy(rng), xy(rng), yaw(rng)}, b{xy(rng), xy(rng), yaw(rng)};
        const std::vector<CarCurve> rs = gridcar::reedsSheppCurves(a, b, 2.0, 6), du = gridcar::dubinsCurves(a, b, 2.0, 6);
        ASSERT_FALSE(rs.empty());
        ASSERT_FALSE(du.empty());
        EXPECT_NEAR(rs.front().length, gridcar::reedsSheppCurve(a, b, 2.0).length, 1e-12);
        EXPECT_NEAR(du.front().length, gridcar::dubinsCurve(a, b, 2.0).length, 1e-12);
        for (const auto *set : {&rs, &du})
            for (std::size_t i = 0; i < set->size(); ++i)
            {
                EXPECT_LT(landingError(a, b, (*set)[i]), 1e-6);
                if (i > 0) EXPECT_GE((*set)[i].length, (*set)[i - 1].length);
            }
        EXPECT_LE(du.size(), 6u);
        moreRs += rs.size() > du.size();
    }
    EXPECT_GT(moreRs, 1000);
    EXPECT_TRUE(gridcar::reedsSheppCurves({0, 0, NAN}, {1, 1, 0}, 2.0, 3).empty());
}
