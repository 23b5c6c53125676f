// Every real map in ../shared/maps loads (skipped with a message when ../shared is absent).
#include "gridcar/map/MapIO.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

using namespace gridcar;
namespace fs = std::filesystem;


// ---------------------------------------------------------------- the real maps in ../shared
TEST(RealMaps, EveryRosMapLoadsWithItsHeaderDimensions)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    int n = 0;
    for (const auto &dir : fs::directory_iterator(test::sharedMaps() + "/ros"))
        for (const auto &f : fs::directory_iterator(dir.path()))
        {
            if (f.path().extension() != ".yaml") continue;
            RosMapMeta meta;
            const OccupancyGrid g = loadRosMap(f.path().string(), &meta);
            const Image img = readImage(meta.imagePath);  // the image header's dimensions
            EXPECT_EQ(g.width(), img.width) << f.path();
            EXPECT_EQ(g.height(), img.height) << f.path();
            const auto c = g.counts();
            EXPECT_GT(c.free, 0u) << f.path();
            EXPECT_GT(c.occupied, 0u) << f.path();
            ++n;
        }
    EXPECT_GE(n, 10);
}

TEST(RealMaps, KnownSizes)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    const OccupancyGrid t = loadRosMap(test::sharedMaps() + "/ros/tsudanuma_campus/tsudanuma_all.yaml");
    EXPECT_EQ(t.width(), 5500);
    EXPECT_EQ(t.height(), 4416);
    EXPECT_DOUBLE_EQ(t.originX(), -100.0);
    const OccupancyGrid l = loadRosMap(test::sharedMaps() + "/ros/f1tenth_levinelobby/levinelobby.yaml");  // ASCII P2
    EXPECT_EQ(l.width(), 692);
    EXPECT_EQ(l.height(), 836);
    const OccupancyGrid b = loadMovingAiMap(test::sharedMaps() + "/movingai/brc202d.map");
    EXPECT_EQ(b.width(), 530);
    EXPECT_EQ(b.height(), 481);
}

TEST(RealMaps, EveryMovingAiMapAndScenarioLoads)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    int n = 0;
    for (const auto &f : fs::directory_iterator(test::sharedMaps() + "/movingai"))
    {
        if (f.path().extension() != ".map") continue;
        // the header's height / width lines
        std::ifstream in(f.path());
        std::string line;
        int hh = -1, ww = -1;
        while (std::getline(in, line) && line.rfind("map", 0) != 0)
        {
            if (line.rfind("height", 0) == 0) hh = std::stoi(line.substr(7));
            if (line.rfind("width", 0) == 0) ww = std::stoi(line.substr(6));
        }
        const OccupancyGrid g = loadMovingAiMap(f.path().string());
        EXPECT_EQ(g.width(), ww) << f.path();
        EXPECT_EQ(g.height(), hh) << f.path();
        const auto scen = loadScenario(f.path().string() + ".scen");
        ASSERT_FALSE(scen.empty()) << f.path();
        for (const auto &e : scen)
        {
            ASSERT_EQ(e.mapWidth, g.width());
            ASSERT_EQ(e.mapHeight, g.height());
            ASSERT_FALSE(g.isBlocked(e.startX, e.startY)) << f.path();
            ASSERT_FALSE(g.isBlocked(e.goalX, e.goalY)) << f.path();
        }
        ++n;
    }
    EXPECT_EQ(n, 10);
}

TEST(RealMaps, OmplPpmMapsLoad)
{
    GRIDCAR_REQUIRE_SHARED_MAPS();
    for (const char *name : {"big.ppm", "normal.ppm", "thick.ppm"})
    {
        const OccupancyGrid g = loadMap(test::sharedMaps() + "/ompl/" + name);
        EXPECT_EQ(g.width(), 450);
        EXPECT_EQ(g.height(), 450);
        const auto c = g.counts();
        EXPECT_GT(c.occupied, 1000u) << name;
        EXPECT_GT(c.free, 1000u) << name;
    }
}
