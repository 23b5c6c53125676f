// Polygon footprints (Nav2's `footprint`): read from a vehicle file, checked exactly by the fast
// checks and by FCL, the rectangle as a special case, a non-convex body beside an obstacle its
// bounding box would hit, grown bodies and the proven-blocked relaxation.
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Errors.h"
#include "gridcar/vehicle/VehicleParams.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace gridcar;

namespace
{
using Poly = std::vector<std::array<double, 2>>;

std::shared_ptr<OccupancyGrid> randomBlocks(unsigned seed)
{
    auto g = std::make_shared<OccupancyGrid>(120, 90, 0.25);
    g->setOrigin(-3.0, 5.0);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> cw(0, 119), ch(0, 89), sz(1, 8);
    for (int k = 0; k < 60; ++k)
    {
        const int c = cw(rng), r = ch(rng), w = sz(rng), h = sz(rng);
        for (int rr = r; rr < std::min(90, r + h); ++rr)
            for (int cc = c; cc < std::min(120, c + w); ++cc) g->set(cc, rr, CellState::Occupied);
    }
    return g;
}

/// Reference by dense sampling: any point of the polygon (its boundary and a grid of interior
/// points every 1 cm) on a blocked cell. Only used where the exact answers agree with margin.
bool sampledCollides(const OccupancyGrid &g, const Poly &poly, double x, double y, double yaw)
{
    const double cs = std::cos(yaw), sn = std::sin(yaw);
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto &p : poly)
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    const auto inside = [&](double u, double v) {
        bool in = false;
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
            if ((poly[i][1] > v) != (poly[j][1] > v) &&
                u < (poly[j][0] - poly[i][0]) * (v - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0])
                in = !in;
        return in;
    };
    for (double u = x0; u <= x1; u += 0.01)
        for (double v = y0; v <= y1; v += 0.01)
            if (inside(u, v))
            {
                const Cell c = g.worldToCell(x + cs * u - sn * v, y + sn * u + cs * v);
                if (g.isBlocked(c.col, c.row)) return true;
            }
    return false;
}

VehicleParams withPolygon(const Poly &poly)
{
    VehicleParams v = VehicleParams::preset("paper-c-robot");
    v.setFootprint(poly);
    return v;
}
}  // namespace

TEST(PolygonFootprint, ReadFromAVehicleFileAsNav2WritesIt)
{
    const std::string f = test::tmpDir() + "/poly.yaml";
    std::ofstream(f) << "preset: paper-c-robot\nfootprint: [[0.4, 0.2], [-0.1, 0.2], [-0.1, -0.2], [0.4, -0.2], [0.5, 0]]\n";
    const VehicleParams v = VehicleParams::fromNameOrFile(f);
    ASSERT_TRUE(v.hasPolygon());
    EXPECT_EQ(v.footprint.size(), 5u);
    EXPECT_DOUBLE_EQ(v.length, 0.6);
    EXPECT_DOUBLE_EQ(v.width, 0.4);
    EXPECT_DOUBLE_EQ(v.rearOverhang, 0.1);
    // the string form of Nav2's parameter files, clockwise: stored counter-clockwise
    const std::string f2 = test::tmpDir() + "/poly2.yaml";
    std::ofstream(f2) << "preset: paper-c-robot\nfootprint: \"[[0.3, 0.2], [0.3, -0.2], [-0.2, -0.2], [-0.2, 0.2]]\"\n";
    const VehicleParams v2 = VehicleParams::fromNameOrFile(f2);
    ASSERT_EQ(v2.footprint.size(), 4u);
    double area2 = 0;
    for (std::size_t i = 0; i < 4; ++i)
        area2 += v2.footprint[i][0] * v2.footprint[(i + 1) % 4][1] - v2.footprint[(i + 1) % 4][0] * v2.footprint[i][1];
    EXPECT_GT(area2, 0);
    // refused: with length, self-crossing, too few points, not numbers
    const auto bad = [](const std::string &name, const std::string &text, const std::string &why) {
        const std::string file = test::tmpDir() + "/" + name;
        std::ofstream(file) << text;
        try
        {
            VehicleParams::fromNameOrFile(file);
            ADD_FAILURE() << name << ": accepted";
        }
        catch (const MapLoadError &e)
        {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    };
    bad("b1.yaml", "length: 2\nfootprint: [[0, 0], [1, 0], [1, 1]]\n", "give either 'footprint' or length");
    bad("b2.yaml", "footprint: [[0, 0], [2, 2], [2, 0], [0, 1]]\n", "not a simple polygon");
    bad("b3.yaml", "footprint: [[0, 0], [1, 0]]\n", "at least 3 vertices");
    bad("b4.yaml", "footprint: [[0, 0], [1, x], [1, 1]]\n", "point 2 must hold two numbers");
    bad("b5.yaml", "footprint: [[0, 0], [1, 0], [2, 0]]\n", "no area");
    bad("b6.yaml", "footprint: 7\n", "must be a list");
}

TEST(PolygonFootprint, TheRectangleAsAPolygonGivesTheRectanglesAnswers)
{
    auto grid = randomBlocks(5);
    auto field = std::make_shared<DistanceField>(*grid);
    const VehicleParams rect = VehicleParams::preset("paper-i");
    VehicleParams poly = rect;
    poly.setFootprint(rect.outline());
    FootprintChecker a(grid, field, rect), b(grid, field, poly);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> ux(-3, 27), uy(5, 27.5), uyaw(-M_PI, M_PI);
    int differ = 0, collisions = 0;
    for (int i = 0; i < 4000; ++i)
    {
        const double x = ux(rng), y = uy(rng), yaw = uyaw(rng);
        const bool ra = a.isValid(x, y, yaw);
        collisions += ra ? 0 : 1;
        differ += ra != b.isValid(x, y, yaw) || ra != b.isValidExact(x, y, yaw) ? 1 : 0;
    }
    EXPECT_LE(differ, 2) << "touching cases aside, the same body must give the same answers";
    EXPECT_GT(collisions, 500);
    EXPECT_GT(b.stats().exact, 0u);
}

TEST(PolygonFootprint, NonConvexBodiesAreExactNotTheirBoundingBox)
{
    // an L: the notch at the front left is not body
    const Poly L{{-0.5, -0.5}, {1.5, -0.5}, {1.5, 0.0}, {0.2, 0.0}, {0.2, 0.5}, {-0.5, 0.5}};
    auto grid = std::make_shared<OccupancyGrid>(80, 80, 0.05);
    grid->setOrigin(0, 0);
    // a blocked cell in the notch of the L placed at (2, 2, 0): (3.0, 2.3)
    const Cell c = grid->worldToCell(3.0, 2.3);
    grid->set(c.col, c.row, CellState::Occupied);
    auto field = std::make_shared<DistanceField>(*grid);
    FootprintChecker fc(grid, field, withPolygon(L));
    EXPECT_TRUE(fc.isValid(2, 2, 0));
    EXPECT_TRUE(fc.isValidExact(2, 2, 0));
    // turned half round, the long arm covers that cell
    EXPECT_FALSE(fc.isValid(2, 2.3, 0));
    EXPECT_FALSE(fc.isValidExact(2, 2.3, 0));
    // the bounding rectangle would collide at the first pose
    VehicleParams box = VehicleParams::preset("paper-c-robot");
    box.length = 2.0;
    box.width = 1.0;
    box.rearOverhang = 0.5;
    FootprintChecker fb(grid, field, box);
    EXPECT_FALSE(fb.isValid(2, 2, 0));
    // grown bodies: the cell square spans x 2.95-3.0 / y 2.3-2.35 (or so), 0.05 m from the
    // notch's inner edges: a 0.01 m margin stays free, 0.2 m does not
    EXPECT_TRUE(fc.isValidInflated({2, 2, 0}, 0.01));
    EXPECT_FALSE(fc.isValidInflated({2, 2, 0}, 0.2));
}

TEST(PolygonFootprint, FastChecksAndFclAgreeWithDenseSamplingOnRandomMaps)
{
    const std::vector<Poly> bodies{
        {{-0.1, -0.2}, {0.4, -0.2}, {0.55, 0.0}, {0.4, 0.2}, {-0.1, 0.2}},                          // a pointed nose
        {{-0.3, -0.3}, {0.6, -0.3}, {0.6, -0.1}, {0.0, -0.1}, {0.0, 0.1}, {0.6, 0.1}, {0.6, 0.3}, {-0.3, 0.3}},  // a C
        {{0.2, -0.4}, {1.0, -0.2}, {1.0, 0.2}, {0.2, 0.4}}};  // the reference point outside the body
    int disagreements = 0, collisions = 0, total = 0;
    for (unsigned seed : {1u, 2u})
    {
        auto grid = randomBlocks(seed);
        auto field = std::make_shared<DistanceField>(*grid);
        for (const Poly &poly : bodies)
        {
            FootprintChecker fc(grid, field, withPolygon(poly));
            std::mt19937 rng(seed * 31 + unsigned(poly.size()));
            std::uniform_real_distribution<double> ux(-3, 27), uy(5, 27.5), uyaw(-M_PI, M_PI);
            for (int i = 0; i < 600; ++i, ++total)
            {
                const double x = ux(rng), y = uy(rng), yaw = uyaw(rng);
                const bool valid = fc.isValid(x, y, yaw), exact = fc.isValidExact(x, y, yaw);
                const bool sampled = sampledCollides(*grid, poly, x, y, yaw);
                collisions += sampled ? 1 : 0;
                // a sampled hit is a real hit: both exact answers must say so
                if (sampled && (valid || exact)) ++disagreements, ADD_FAILURE() << x << "," << y << "," << yaw;
                // the two exact answers agree (touching aside: only a 1 cm sample would tell)
                if (valid != exact && !sampled && fc.clearance(x, y, yaw) > 0.02) ++disagreements;
                // proven blocked is never wrong
                if (fc.provenBlocked({x, y, yaw}) && valid) ++disagreements, ADD_FAILURE() << "proven blocked but free";
                // grown bodies: free when grown means free
                if (fc.isValidInflated({x, y, yaw}, 0.05) && !valid) ++disagreements, ADD_FAILURE() << "inflated free";
            }
        }
    }
    EXPECT_EQ(disagreements, 0) << "of " << total;
    EXPECT_GT(collisions, total / 10);
}
