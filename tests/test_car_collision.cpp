// The car lattice's collision model on gridcar's checker (FootprintCollision) and the
// distance-field shortcuts it is built on: each shortcut changes how many lookups a question
// takes, never its answer, so every test here compares with the plain definition.
#include "gridcar/planners/search/CarCollision.h"

#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

using namespace gridcar;

namespace
{
/// A 30 m x 22.5 m map at 0.25 m, origin (-3, 5), with 40 random blocks, some cut by the border.
std::shared_ptr<const OccupancyGrid> blocks(unsigned seed)
{
    auto g = test::randomBlocks(seed, 120, 90, 0.25, 40, 9);
    g->setOrigin(-3.0, 5.0);
    return g;
}

const char *const kVehicles[] = {"paper-i", "paper-c-car", "paper-c-robot", "point"};
}  // namespace

/// The inscribed-disc test by its definition, on the grid and the field themselves (not the
/// checker's bit per cell): a disc is proven blocked where its centre's cell is blocked or the
/// field there is below its radius less half a cell diagonal.
bool plainDiscsBlocked(const OccupancyGrid &g, const DistanceField &f, const VehicleParams &v, double x, double y,
                       const std::vector<std::array<double, 2>> &discs)
{
    const double r = std::min(v.length, v.width) / 2, halfDiag = g.resolution() * std::sqrt(2.0) / 2;
    for (const auto &o : discs)
    {
        const Cell c = g.worldToCell(x + o[0], y + o[1]);
        if (g.isBlocked(c.col, c.row) || f.cellDistance(c.col, c.row) + halfDiag < r) return true;
    }
    return false;
}

TEST(CarCollision, BitPerCellShortcutsGiveTheDiscTestsAnswers)
{
    // provenBlockedAt() (one bit per cell) is the disc test by its definition;
    // discsClearAtEveryYaw() answers every yaw at once (never where a disc is proven blocked),
    // from the point's distance or from its own bit; points off the map included
    int clearEverywhere = 0, blocked = 0, asked = 0;
    for (unsigned seed : {1u, 2u})
    {
        const auto g = blocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        for (const char *veh : kVehicles)
        {
            FootprintChecker fc(g, field, VehicleParams::preset(veh));
            std::mt19937 rng(seed * 7 + 1);
            std::uniform_real_distribution<double> ux(-6.0, 30.0), uy(2.0, 30.5);
            for (int i = 0; i < 400; ++i)
            {
                const double x = ux(rng), y = uy(rng);
                const Cell cell = g->worldToCell(x, y);
                const bool clear = fc.discsClearAtEveryYaw(field->cellDistance(cell.col, cell.row));
                EXPECT_EQ(clear, fc.discsClearAtEveryYawAt(x, y)) << veh << " " << x << "," << y;
                clearEverywhere += clear;
                for (int k = 0; k < 24; ++k)
                {
                    const auto discs = fc.inscribedDiscOffsets(k * M_PI / 12);
                    const bool plain = plainDiscsBlocked(*g, *field, fc.vehicle(), x, y, discs);
                    ++asked;
                    blocked += plain;
                    EXPECT_EQ(plain, fc.provenBlockedAt(x, y, discs)) << veh << " " << x << "," << y << " yaw step " << k;
                    if (clear) EXPECT_FALSE(plain) << veh << " " << x << "," << y;
                }
            }
        }
    }
    EXPECT_GT(clearEverywhere, 100);  // both branches are exercised
    EXPECT_GT(blocked, asked / 10);
}

TEST(CarCollision, FreeSlackStopsEarlyOnlyAtOrBelowTheThresholdAsked)
{
    const auto g = blocks(3);
    FootprintChecker fc(g, std::make_shared<DistanceField>(*g), VehicleParams::preset("paper-i"));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(-3.0, 27.0), uy(5.0, 27.5), uyaw(-M_PI, M_PI);
    int early = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const Pose2 p{ux(rng), uy(rng), uyaw(rng)};
        const double full = fc.freeSlack(p);
        for (double below : {0.07, 0.5})
        {
            const double v = fc.freeSlack(p, below);
            if (full > below)
                EXPECT_EQ(v, full);
            else
            {
                EXPECT_LE(v, below);
                EXPECT_GE(v, full);  // the least of the discs looked at
                early += v != full;
            }
        }
    }
    EXPECT_GT(early, 0);
}

TEST(CarCollision, CurveFreeIsEveryPoseFreeWithTheMargin)
{
    // random arcs from random poses, each asked at three margins and from the same start in
    // turn (the start's room is kept between calls): the answer is that of the grown body at
    // every pose, however the proofs fall, with the yaws' cosines and sines computed by the
    // check or given to it
    int freeCurves = 0, blockedCurves = 0;
    for (unsigned seed : {4u, 5u})
    {
        const auto g = blocks(seed);
        auto field = std::make_shared<DistanceField>(*g);
        for (const char *veh : {"paper-i", "paper-c-car"})
        {
            FootprintChecker fc(g, field, VehicleParams::preset(veh));
            FootprintCollision col(fc);
            std::mt19937 rng(seed * 3 + 2);
            std::uniform_real_distribution<double> ux(-3.0, 27.0), uy(5.0, 27.5), uyaw(-M_PI, M_PI), uk(-0.3, 0.3), ul(1.0, 25.0);
            for (int i = 0; i < 300; ++i)
            {
                const Pose2 from{ux(rng), uy(rng), uyaw(rng)};
                if (!fc.isValidInflated(from, 0.05)) continue;
                for (int c = 0; c < 3; ++c)
                {
                    const double kappa = uk(rng), len = ul(rng);
                    for (double margin : {0.2, 0.05, 0.1})
                    {
                        // poses 2 margin apart for the farthest body point, as the lattice samples
                        const double ds = 2 * margin / (1.0 + fc.reach() * std::abs(kappa));
                        const int n = std::max(1, int(std::ceil(len / ds)));
                        const auto poseAt = [&](int k) {
                            const double s = len * k / n, th = from.yaw + kappa * s;
                            if (std::abs(kappa) < 1e-9)
                                return Pose2{from.x + s * std::cos(from.yaw), from.y + s * std::sin(from.yaw), th};
                            return Pose2{from.x + (std::sin(th) - std::sin(from.yaw)) / kappa,
                                         from.y - (std::cos(th) - std::cos(from.yaw)) / kappa, th};
                        };
                        bool every = true;
                        for (int k = 1; k <= n && every; ++k) every = fc.isValidInflated(poseAt(k), margin);
                        EXPECT_EQ(col.curveFree(from, n, poseAt, margin), every)
                            << veh << " from " << from.x << "," << from.y << "," << from.yaw << " kappa " << kappa << " length "
                            << len << " margin " << margin;
                        // the inlined form, each pose's cosine and sine given by turning the
                        // start's (as the lattice's primitives give theirs)
                        const double c0 = std::cos(from.yaw), s0 = std::sin(from.yaw);
                        EXPECT_EQ(col.curveFreeOriented(from, n, [&](int k) {
                            const double turn = kappa * len * k / n, ct = std::cos(turn), st = std::sin(turn);
                            return OrientedPose{poseAt(k), c0 * ct - s0 * st, s0 * ct + c0 * st};
                        }, margin), every) << veh << " (cosines and sines given)";
                        (every ? freeCurves : blockedCurves)++;
                    }
                }
            }
        }
    }
    EXPECT_GT(freeCurves, 100);
    EXPECT_GT(blockedCurves, 100);
}

TEST(CarCollision, HeuristicStandingTestsAreTheDiscTests)
{
    // mayStandOnAxis / axesStanding / mayStandAt: "not proven blocked" at an axis (either way),
    // at each axis at once, or at some heading, answered with the point's own bit first
    const auto g = blocks(6);
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-i"));
    FootprintCollision col(fc);
    std::vector<double> yaws;
    for (int h = 0; h < 16; ++h) yaws.push_back(0.1 + h * M_PI / 8);
    col.setHeadings(yaws);
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> ux(-5.0, 29.0), uy(3.0, 29.5);
    int no = 0;
    for (int i = 0; i < 1500; ++i)
    {
        const double x = ux(rng), y = uy(rng);
        const std::uint32_t axes = col.axesStanding(x, y, 16);
        bool any = false;
        for (int h = 0; h < 16; ++h)
        {
            const bool fwd = !fc.provenBlockedAt(x, y, fc.inscribedDiscOffsets(yaws[std::size_t(h)]));
            const bool back = !fc.provenBlockedAt(x, y, fc.inscribedDiscOffsets(yaws[std::size_t(h)] + M_PI));
            any = any || fwd;
            EXPECT_EQ(col.mayStandOnAxis(x, y, h), fwd || back) << x << "," << y << " heading " << h;
            EXPECT_EQ(((axes >> h) & 1u) != 0, fwd || back) << x << "," << y << " heading " << h << " (all axes at once)";
        }
        EXPECT_EQ(col.mayStandAt(x, y), any) << x << "," << y;
        no += !any;
    }
    EXPECT_GT(no, 50);
    // more axes than headings set (or than the answer's 32 bits) is a caller's error
    EXPECT_THROW(col.axesStanding(1.0, 1.0, 17), std::invalid_argument);
    EXPECT_THROW(col.axesStanding(1.0, 1.0, -1), std::invalid_argument);
}
