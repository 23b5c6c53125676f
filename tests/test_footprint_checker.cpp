#include "gridcar/collision/FootprintChecker.h"

#include "gridcar/map/MapIO.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace gridcar;

namespace
{
/// Reference answer by rasterisation: does the closed rectangle overlap any blocked cell
/// square? Separating-axis test per cell near the rectangle. Also reports whether any
/// separating distance was within 1e-9 (a touching case where either answer is allowed).
bool bruteCollides(const FootprintChecker &fc, double x, double y, double yaw, bool &ambiguous)
{
    const OccupancyGrid &g = fc.grid();
    double cx[4], cy[4];
    fc.corners(x, y, yaw, cx, cy);
    double minX = cx[0], maxX = cx[0], minY = cy[0], maxY = cy[0];
    for (int i = 1; i < 4; ++i)
    {
        minX = std::min(minX, cx[i]);
        maxX = std::max(maxX, cx[i]);
        minY = std::min(minY, cy[i]);
        maxY = std::max(maxY, cy[i]);
    }
    const double res = g.resolution();
    const int c0 = int(std::floor((minX - g.originX()) / res)) - 1, c1 = int(std::floor((maxX - g.originX()) / res)) + 1;
    const int v0 = int(std::floor((minY - g.originY()) / res)) - 1, v1 = int(std::floor((maxY - g.originY()) / res)) + 1;
    ambiguous = false;
    bool hit = false;
    const double axes[4][2] = {{1, 0}, {0, 1}, {std::cos(yaw), std::sin(yaw)}, {-std::sin(yaw), std::cos(yaw)}};
    for (int v = v0; v <= v1; ++v)
        for (int c = c0; c <= c1; ++c)
        {
            const int row = g.height() - 1 - v;
            if (!g.isBlocked(c, row)) continue;
            const double sx0 = g.originX() + c * res, sy0 = g.originY() + v * res;
            const double sqx[4] = {sx0, sx0 + res, sx0 + res, sx0}, sqy[4] = {sy0, sy0, sy0 + res, sy0 + res};
            double sep = -1e300;  // largest separation over the four axes (positive = apart)
            for (const auto &a : axes)
            {
                double p0 = 1e300, p1 = -1e300, q0 = 1e300, q1 = -1e300;
                for (int i = 0; i < 4; ++i)
                {
                    const double pr = cx[i] * a[0] + cy[i] * a[1], qr = sqx[i] * a[0] + sqy[i] * a[1];
                    p0 = std::min(p0, pr);
                    p1 = std::max(p1, pr);
                    q0 = std::min(q0, qr);
                    q1 = std::max(q1, qr);
                }
                sep = std::max(sep, std::max(q0 - p1, p0 - q1));
            }
            if (std::abs(sep) <= 1e-9) ambiguous = true;
            if (sep < 0) hit = true;
        }
    return hit;
}

struct Fixture
{
    std::shared_ptr<OccupancyGrid> grid;
    std::shared_ptr<DistanceField> field;
};

Fixture randomBlocks(unsigned seed)
{
    Fixture f;
    f.grid = std::make_shared<OccupancyGrid>(120, 90, 0.25);
    f.grid->setOrigin(-3.0, 5.0);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> cw(0, 119), ch(0, 89), sz(1, 8);
    for (int k = 0; k < 60; ++k)
    {
        const int c = cw(rng), r = ch(rng), w = sz(rng), h = sz(rng);
        for (int rr = r; rr < std::min(90, r + h); ++rr)
            for (int cc = c; cc < std::min(120, c + w); ++cc) f.grid->set(cc, rr, CellState::Occupied);
    }
    f.field = std::make_shared<DistanceField>(*f.grid);
    return f;
}

void compareOnRandomPoses(const FootprintChecker &fc, int n, unsigned seed, int &disagreements, int &ambiguousOnes,
                          int &collisions)
{
    const OccupancyGrid &g = fc.grid();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(g.originX() - 1, g.originX() + g.sizeX() + 1),
        uy(g.originY() - 1, g.originY() + g.sizeY() + 1), uyaw(-M_PI, M_PI);
    for (int i = 0; i < n; ++i)
    {
        const double x = ux(rng), y = uy(rng), yaw = uyaw(rng);
        bool amb;
        // off-map cells are blocked, so the brute force sees the border too
        const bool ref = bruteCollides(fc, x, y, yaw, amb);
        const bool valid = fc.isValid(x, y, yaw);
        const bool exact = fc.isValidExact(x, y, yaw);
        collisions += ref ? 1 : 0;
        if (valid == ref || exact == ref)
        {
            if (amb) ++ambiguousOnes;
            else
            {
                ++disagreements;
                ADD_FAILURE() << "pose " << x << "," << y << "," << yaw << " ref collides=" << ref << " isValid=" << valid
                              << " exact=" << exact;
            }
        }
    }
}
}  // namespace

TEST(VehicleParams, PresetsAndValidation)
{
    const VehicleParams p = VehicleParams::preset("paper-i");
    EXPECT_DOUBLE_EQ(p.wheelbase, 1.56);
    EXPECT_DOUBLE_EQ(p.width, 1.835);
    EXPECT_NEAR(p.maxCurvature(), std::tan(40.0 * M_PI / 180) / 1.56, 1e-12);  // eq. 2: 0.538 1/m
    EXPECT_NEAR(p.minTurningRadius(), 1.859, 1e-3);
    EXPECT_TRUE(VehicleParams::preset("point").isPoint());
    EXPECT_DOUBLE_EQ(VehicleParams::preset("paper-c-car").maxSpeed, 30.0);
    EXPECT_DOUBLE_EQ(VehicleParams::preset("paper-c-robot").cornerSpeed90, 0.2);
    EXPECT_THROW(VehicleParams::preset("tank"), std::invalid_argument);
    VehicleParams bad = p;
    bad.width = std::nan("");
    EXPECT_THROW(bad.validate(), std::invalid_argument);
    bad = p;
    bad.maxSteerDeg = 95;
    EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(VehicleParams, ReadsYamlFile)
{
    const std::string path = test::tmpDir() + "/veh.yaml";
    {
        std::ofstream f(path);
        f << "preset: paper-i\nwidth: 2.0\nmax_speed: 7\n";
    }
    const VehicleParams v = VehicleParams::fromNameOrFile(path);
    EXPECT_DOUBLE_EQ(v.width, 2.0);
    EXPECT_DOUBLE_EQ(v.maxSpeed, 7.0);
    EXPECT_DOUBLE_EQ(v.wheelbase, 1.56);
    {
        std::ofstream f(path);
        f << "width: 2.0\nwheels: 4\n";
    }
    EXPECT_THROW(VehicleParams::fromNameOrFile(path), MapLoadError);
    {
        std::ofstream f(path);
        f << "width: -2.0\n";
    }
    EXPECT_THROW(VehicleParams::fromNameOrFile(path), MapLoadError);
}

TEST(VehicleParams, MissingFileOrDirectoryIsSaidSoNotAnUnknownPreset)
{
    auto message = [](const std::string &arg) {
        try
        {
            VehicleParams::fromNameOrFile(arg);
        }
        catch (const std::exception &e)
        {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    EXPECT_NE(message(test::tmpDir() + "/no-such-car.yaml").find("cannot open the vehicle file"), std::string::npos);
    const std::string presetMap = test::tmpDir() + "/preset-map.yaml";
    std::ofstream(presetMap) << "preset: {a: 1}\n";
    EXPECT_NE(message(presetMap).find("'preset' must be a preset name"), std::string::npos);
    EXPECT_NE(message(test::tmpDir()).find("is a directory"), std::string::npos);
    EXPECT_NE(message("tank").find("unknown vehicle preset 'tank'"), std::string::npos);
    EXPECT_THROW(VehicleParams::fromNameOrFile(test::tmpDir() + "/no-such-car.yaml"), MapLoadError);
    // found by fuzz_vehicle_yaml: a preset name with control bytes was echoed raw
    const std::string tabs = test::tmpDir() + "/tabs.yaml";
    std::ofstream(tabs) << "preset: \"paper-c-\\t\\tcar\"\n";
    const std::string m = message(tabs);
    EXPECT_NE(m.find("paper-c-\\x09\\x09car"), std::string::npos) << m;
    for (unsigned char c : m) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(c) << " in: " << m;
}

TEST(VehicleParams, ScaledKeepsTimingAndAnglesAndReadsFromYaml)
{
    const VehicleParams car = VehicleParams::preset("paper-c-car");
    const VehicleParams s = car.scaled(0.02);
    EXPECT_DOUBLE_EQ(s.maxSpeed, 0.6);  // paper C's robot speed
    EXPECT_DOUBLE_EQ(s.cornerSpeed45, 0.2);
    EXPECT_DOUBLE_EQ(s.acceleration, 0.06);  // 0 -> v_max still takes 10 s
    EXPECT_DOUBLE_EQ(s.length, 0.09);
    EXPECT_DOUBLE_EQ(s.maxSteerDeg, car.maxSteerDeg);
    EXPECT_DOUBLE_EQ(s.friction, car.friction);
    EXPECT_NEAR(s.minTurningRadius(), 0.02 * car.minTurningRadius(), 1e-12);
    EXPECT_NO_THROW(s.validate());
    EXPECT_THROW(car.scaled(0.0), std::invalid_argument);
    EXPECT_THROW(car.scaled(std::nan("")), std::invalid_argument);

    const std::string path = test::tmpDir() + "/veh_scaled.yaml";
    {
        std::ofstream f(path);
        f << "preset: paper-c-car\nscale: 0.02\nmax_speed: 40\n";  // scale applies last
    }
    const VehicleParams y = VehicleParams::fromNameOrFile(path);
    EXPECT_DOUBLE_EQ(y.maxSpeed, 0.8);
    EXPECT_DOUBLE_EQ(y.wheelbase, 0.054);
    {
        std::ofstream f(path);
        f << "preset: paper-c-car\nscale: -1\n";
    }
    EXPECT_THROW(VehicleParams::fromNameOrFile(path), MapLoadError);
}

TEST(FootprintChecker, NeverCallsACollidingPoseFreeOnRandomMaps)
{
    int disagreements = 0, ambiguous = 0, collisions = 0;
    for (unsigned seed : {1u, 2u, 3u})
    {
        Fixture f = randomBlocks(seed);
        for (const char *veh : {"paper-i", "paper-c-robot", "paper-c-car"})
        {
            FootprintChecker fc(f.grid, f.field, VehicleParams::preset(veh));
            compareOnRandomPoses(fc, 1500, seed * 7 + 1, disagreements, ambiguous, collisions);
        }
    }
    EXPECT_EQ(disagreements, 0);
    EXPECT_GT(collisions, 1000);  // the sample really exercises both answers
    RecordProperty("ambiguous_touching_poses", ambiguous);
}

TEST(FootprintChecker, ExactCheckAcrossTheTilesOfItsObstacleBoxes)
{
    // FCL boxes made per 64 x 64 cells on first use: bodies straddling the tile corners
    // (cells 64, 128, 192 across; 64, 128 down) get the brute force's answer
    auto grid = std::make_shared<OccupancyGrid>(256, 200, 0.05);
    grid->setOrigin(1.0, -2.0);
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cw(0, 255), ch(0, 199), sz(1, 12);
    for (int k = 0; k < 400; ++k)
    {
        const int c = cw(rng), r = ch(rng), w = sz(rng), h = sz(rng);
        for (int rr = r; rr < std::min(200, r + h); ++rr)
            for (int cc = c; cc < std::min(256, c + w); ++cc) grid->set(cc, rr, CellState::Occupied);
    }
    auto field = std::make_shared<DistanceField>(*grid);
    FootprintChecker fc(grid, field, VehicleParams::preset("paper-c-robot"));
    std::uniform_real_distribution<double> jitter(-0.4, 0.4), uyaw(-M_PI, M_PI);
    std::uniform_int_distribution<int> corner(1, 3), cornerRow(1, 2);
    int disagreements = 0, collisions = 0, free = 0;
    for (int i = 0; i < 4000; ++i)
    {
        const double x = grid->originX() + 64 * corner(rng) * 0.05 + jitter(rng);
        const double y = grid->originY() + grid->sizeY() - 64 * cornerRow(rng) * 0.05 + jitter(rng);
        const double yaw = uyaw(rng);
        bool amb = false;
        const bool ref = bruteCollides(fc, x, y, yaw, amb);
        const bool exact = fc.isValidExact(x, y, yaw);
        (ref ? collisions : free) += 1;
        if (exact == ref && !amb)
        {
            ++disagreements;
            ADD_FAILURE() << "pose " << x << "," << y << "," << yaw << " ref collides=" << ref;
        }
    }
    EXPECT_EQ(disagreements, 0);
    EXPECT_GT(collisions, 400);  // both answers exercised
    EXPECT_GT(free, 400);
    EXPECT_GT(fc.obstacleBoxCount(), 100u);
}

TEST(FootprintChecker, AgreesWithRasterisationOnRealMaps)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    int disagreements = 0, ambiguous = 0, collisions = 0, total = 0;
    for (const char *m : {"/ros/willow_garage/willow-2010-02-18-0.10.yaml", "/ros/intel_lab/intel.yaml",
                          "/ros/nav2_depot/depot.yaml"})
    {
        auto grid = std::make_shared<OccupancyGrid>(loadRosMap(test::sharedMaps() + m));
        auto field = std::make_shared<DistanceField>(*grid);
        FootprintChecker fc(grid, field, VehicleParams::preset("paper-c-robot"));
        compareOnRandomPoses(fc, 3000, 11, disagreements, ambiguous, collisions);
        total += 3000;
        const auto st = fc.stats();
        EXPECT_GT(st.exact, 0u) << m;  // the exact test (beyond the distance-field shortcuts) really ran
    }
    EXPECT_EQ(disagreements, 0) << "of " << total << " poses (" << ambiguous << " touching within 1e-9)";
    EXPECT_GT(collisions, 100);
    std::printf("real maps: %d poses, %d disagreements, %d touching within 1e-9, %d collisions\n", total,
                disagreements, ambiguous, collisions);
}

TEST(FootprintChecker, FastPathDecidesFarFromObstacles)
{
    Fixture f = randomBlocks(5);
    auto open = std::make_shared<OccupancyGrid>(200, 200, 0.1);
    open->setUnknownIsFree(true);
    auto field = std::make_shared<DistanceField>(*open);
    FootprintChecker fc(open, field, VehicleParams::preset("paper-c-robot"));
    EXPECT_TRUE(fc.isValid(10.0, 10.0, 0.3));
    EXPECT_EQ(fc.stats().fastFree, 1u);
    EXPECT_FALSE(fc.isValid(0.05, 10.0, 0.0));  // sticks out of the map
    EXPECT_FALSE(fc.isValid(std::nan(""), 1.0, 0.0));
    EXPECT_FALSE(fc.isValid(1.0, 1.0, std::numeric_limits<double>::infinity()));
}

TEST(FootprintChecker, SweptMotionCatchesAThinWallBetweenValidPoses)
{
    auto g = std::make_shared<OccupancyGrid>(100, 40, 0.1);
    g->setUnknownIsFree(true);
    for (int r = 0; r < 40; ++r)
        if (r < 5 || r > 34) continue;
        else g->set(50, r, CellState::Occupied);  // a one-cell wall, 3 m tall
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
    const Pose2 a{3.0, 2.0, 0.0}, b{6.5, 2.0, 0.0};
    ASSERT_TRUE(fc.isValid(a));
    ASSERT_TRUE(fc.isValid(b));
    EXPECT_FALSE(fc.isMotionValid(a, b));
    // a spacing of a fraction of the cell: the number of checks grows with the distance
    EXPECT_GE(fc.sweepSteps(a, b), int(3.5 / (0.5 * 0.1)));
    const Pose2 c{3.0, 2.0, 0.0}, d{4.5, 2.0, 0.0};
    EXPECT_TRUE(fc.isMotionValid(c, d));
    // a rotation on the spot sweeps the corners too
    EXPECT_GT(fc.sweepSteps(c, Pose2{3.0, 2.0, M_PI}), 1);
}

TEST(FootprintChecker, ClearanceAndDetectionPoints)
{
    auto g = std::make_shared<OccupancyGrid>(200, 100, 0.1);
    g->setUnknownIsFree(true);
    for (int c = 0; c < 200; ++c) g->set(c, 99, CellState::Occupied);  // wall along the bottom (y in [0, 0.1])
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("paper-i"));
    // car parallel to the wall, its side 1.0 m above the wall's top edge
    const double y = 0.1 + 1.0 + 1.835 / 2;
    const double c = fc.clearance(10.0, y, 0.0);
    EXPECT_NEAR(c, 1.0 + 0.05, 0.1);  // distance to the wall's cell centres, within a cell
    EXPECT_EQ(fc.clearance(10.0, 0.5, 0.0), 0.0);  // in collision
    // detection points at D/2: blind to the car's length, sees its width
    EXPECT_TRUE(fc.isValidDetectionPoints(10.0, 0.1 + 1.0));
    EXPECT_FALSE(fc.isValidDetectionPoints(10.0, 0.1 + 0.8));
}

TEST(FootprintChecker, PointVehicleIsPlainGrid)
{
    auto g = std::make_shared<OccupancyGrid>(3, 3, 1.0);
    g->set(1, 1, CellState::Occupied);
    auto field = std::make_shared<DistanceField>(*g);
    FootprintChecker fc(g, field, VehicleParams::preset("point"));
    EXPECT_TRUE(fc.isValid(0.5, 0.5, 0.0));
    EXPECT_FALSE(fc.isValid(1.5, 1.5, 0.0));
    EXPECT_FALSE(fc.isValid(-0.5, 0.5, 0.0));
}

TEST(FootprintChecker, FreeSlackIsRoomTheBodyCanMoveIn)
{
    // wherever freeSlack() proves room r, the body moved so that no point travels more than r
    // (turned about its reference point and shifted) overlaps no blocked cell
    int proven = 0, moved = 0;
    for (unsigned seed : {1u, 2u, 3u})
    {
        Fixture f = randomBlocks(seed);
        for (const char *veh : {"paper-i", "paper-c-robot", "paper-c-car"})
        {
            FootprintChecker fc(f.grid, f.field, VehicleParams::preset(veh));
            const OccupancyGrid &g = fc.grid();
            std::mt19937 rng(seed * 13 + 5);
            std::uniform_real_distribution<double> ux(g.originX(), g.originX() + g.sizeX()),
                uy(g.originY(), g.originY() + g.sizeY()), uyaw(-M_PI, M_PI), u01(0.0, 1.0);
            for (int i = 0; i < 600; ++i)
            {
                const Pose2 p{ux(rng), uy(rng), uyaw(rng)};
                const double r = fc.freeSlack(p);
                if (!(r > 0)) continue;
                ++proven;
                EXPECT_TRUE(fc.isValidInflated(p, 0.99 * r / M_SQRT2)) << p.x << "," << p.y << "," << p.yaw << " slack " << r;
                for (int k = 0; k < 4; ++k)
                {
                    // half the room to the turn (body points within reach()), half to the shift
                    const double turn = (u01(rng) - 0.5) * 0.99 * r / std::max(fc.reach(), 1e-9), dir = uyaw(rng);
                    const double shift = u01(rng) * 0.495 * r;
                    bool amb = false;
                    const bool hit = bruteCollides(fc, p.x + shift * std::cos(dir), p.y + shift * std::sin(dir), p.yaw + turn, amb);
                    EXPECT_TRUE(!hit || amb) << p.x << "," << p.y << "," << p.yaw << " slack " << r;
                    ++moved;
                }
            }
        }
    }
    EXPECT_GT(proven, 1000);  // the random maps leave room often enough to test it
    // nothing proven for a point vehicle or a pose that is not finite
    Fixture f = randomBlocks(1);
    EXPECT_LE(FootprintChecker(f.grid, f.field, VehicleParams::preset("point")).freeSlack({10.0, 10.0, 0.0}), 0.0);
    EXPECT_LE(FootprintChecker(f.grid, f.field, VehicleParams::preset("paper-i")).freeSlack({std::nan(""), 10.0, 0.0}), 0.0);
    RecordProperty("moved_poses", moved);
}
