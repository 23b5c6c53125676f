#include "gridcar/map/MapIO.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

using namespace gridcar;
namespace fs = std::filesystem;

namespace
{
std::string writeFile(const std::string &name, const std::string &content)
{
    const std::string path = test::tmpDir() + "/" + name;
    std::ofstream f(path, std::ios::binary);
    f << content;
    return path;
}

/// Expects @p fn to throw MapLoadError whose message names @p file and contains @p reason.
template <class Fn>
void expectLoadError(Fn fn, const std::string &file, const std::string &reason)
{
    try
    {
        fn();
        ADD_FAILURE() << "no error for " << file << " (expected: " << reason << ")";
    }
    catch (const MapLoadError &e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(file), std::string::npos) << msg;
        EXPECT_NE(msg.find(reason), std::string::npos) << "message '" << msg << "' lacks '" << reason << "'";
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "message must be one line: " << msg;
    }
}

std::string pgm(int w, int h, const std::vector<int> &px, bool ascii = false)
{
    std::string s = std::string(ascii ? "P2" : "P5") + "\n# comment\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    for (int v : px)
    {
        if (ascii) s += std::to_string(v) + " ";
        else s.push_back(char(v));
    }
    return s;
}
}  // namespace

TEST(RosMap, ReadsPgmWithMapServerSemantics)
{
    // 3 x 2: values 0 (occupied), 254 (free), 205 (unknown); row 0 is the top
    writeFile("ok.pgm", pgm(3, 2, {0, 254, 205, 254, 254, 0}));
    const std::string y = writeFile("ok.yaml", "image: ok.pgm\nresolution: 0.25\norigin: [1.0, -2.0, 0.0]\n"
                                               "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    RosMapMeta meta;
    const OccupancyGrid g = loadRosMap(y, &meta);
    ASSERT_EQ(g.width(), 3);
    ASSERT_EQ(g.height(), 2);
    EXPECT_DOUBLE_EQ(g.resolution(), 0.25);
    EXPECT_DOUBLE_EQ(g.originX(), 1.0);
    EXPECT_DOUBLE_EQ(g.originY(), -2.0);
    EXPECT_EQ(g.at(0, 0), CellState::Occupied);
    EXPECT_EQ(g.at(1, 0), CellState::Free);
    EXPECT_EQ(g.at(2, 0), CellState::Unknown);
    EXPECT_EQ(g.at(2, 1), CellState::Occupied);
    // the image path is resolved relative to the yaml
    EXPECT_EQ(meta.imagePath, test::tmpDir() + "/ok.pgm");
    // world: top-left cell centre is at (origin.x + res/2, origin.y + (h - 0.5) res)
    const Cell c = g.worldToCell(1.0 + 0.125, -2.0 + 1.5 * 0.25);
    EXPECT_EQ(c.col, 0);
    EXPECT_EQ(c.row, 0);
}

TEST(RosMap, NegateAsciiAndRawModes)
{
    writeFile("neg.pgm", pgm(2, 1, {0, 255}, true));
    const OccupancyGrid g =
        loadRosMap(writeFile("neg.yaml", "image: neg.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 1\n"));
    EXPECT_EQ(g.at(0, 0), CellState::Free);      // v=0 negated -> 255 -> p=0
    EXPECT_EQ(g.at(1, 0), CellState::Occupied);  // v=255 negated -> 0 -> p=1
    writeFile("raw.pgm", pgm(3, 1, {0, 100, 255}));
    const OccupancyGrid r =
        loadRosMap(writeFile("raw.yaml", "image: raw.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: raw\n"));
    EXPECT_EQ(r.at(0, 0), CellState::Free);
    EXPECT_EQ(r.at(1, 0), CellState::Occupied);
    EXPECT_EQ(r.at(2, 0), CellState::Unknown);
}

TEST(RosMap, ReadsPngGrayAlphaAndRgb)
{
    Image ga;
    ga.width = 3;
    ga.height = 1;
    ga.channels = 2;
    ga.data = {0, 255, 254, 255, 254, 0};  // occupied, free, transparent -> unknown
    writePng(test::tmpDir() + "/ga.png", ga);
    const OccupancyGrid g = loadRosMap(writeFile("ga.yaml", "image: ga.png\nresolution: 0.1\norigin: [0, 0, 0]\n"));
    EXPECT_EQ(g.at(0, 0), CellState::Occupied);
    EXPECT_EQ(g.at(1, 0), CellState::Free);
    EXPECT_EQ(g.at(2, 0), CellState::Unknown);
    Image rgb;
    rgb.width = 2;
    rgb.height = 1;
    rgb.channels = 3;
    rgb.data = {255, 255, 255, 10, 20, 30};
    writePng(test::tmpDir() + "/rgb.png", rgb);
    const OccupancyGrid h = loadRosMap(writeFile("rgb.yaml", "image: rgb.png\nresolution: 0.1\norigin: [0, 0, 0]\n"));
    EXPECT_EQ(h.at(0, 0), CellState::Free);
    EXPECT_EQ(h.at(1, 0), CellState::Occupied);
}

TEST(RosMap, MalformedYamlGivesFileAndReason)
{
    writeFile("img.pgm", pgm(2, 2, {0, 0, 0, 0}));
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"image: img.pgm\nresolution: [1\n", "YAML syntax error"},
        {"- just\n- a list\n", "expected a YAML mapping"},
        {"resolution: 1\norigin: [0, 0, 0]\n", "missing required key 'image'"},
        {"image: img.pgm\norigin: [0, 0, 0]\n", "missing required key 'resolution'"},
        {"image: img.pgm\nresolution: 1\n", "missing required key 'origin'"},
        {"image: img.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n", "resolution must be positive"},
        {"image: img.pgm\nresolution: 0\norigin: [0, 0, 0]\n", "resolution must be positive"},
        {"image: img.pgm\nresolution: abc\norigin: [0, 0, 0]\n", "'resolution' must be a number"},
        // finite but absurd: once accepted, they overflowed FCL's boxes (a crash in plan / drive)
        {"image: img.pgm\nresolution: 1e155\norigin: [0, 0, 0]\n", "between 0.0001 and 1000 m per cell"},
        {"image: img.pgm\nresolution: 1e-9\norigin: [0, 0, 0]\n", "between 0.0001 and 1000 m per cell"},
        {"image: img.pgm\nresolution: 1\norigin: [1e155, 0, 0]\n", "more than 10000 km from 0"},
        {"image: img.pgm\nresolution: 1\norigin: [0, -2e7, 0]\n", "more than 10000 km from 0"},
        {"image: img.pgm\nresolution: 1\norigin: [0, 0]\n", "'origin' must be a list [x, y, yaw]"},
        {"image: img.pgm\nresolution: 1\norigin: [0, .nan, 0]\n", "must be finite"},
        {"image: nothere.pgm\nresolution: 1\norigin: [0, 0, 0]\n", "cannot open the image file"},
        {"image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: fancy\n", "unknown mode 'fancy'"},
        {"image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n", "must lie in [0, 1]"},
        {"image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: 0.9\noccupied_thresh: 0.5\n",
         "free_thresh must not exceed occupied_thresh"},
        {"image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 2\n", "'negate' must be 0 or 1"},
        {"image: ''\nresolution: 1\norigin: [0, 0, 0]\n", "'image' is empty"},
    };
    int k = 0;
    for (const auto &c : cases)
    {
        const std::string name = "bad" + std::to_string(k++) + ".yaml";
        const std::string path = writeFile(name, c.first);
        expectLoadError([&] { loadRosMap(path); }, name, c.second);
    }
    expectLoadError([&] { loadRosMap(test::tmpDir() + "/no-such.yaml"); }, "no-such.yaml", "cannot open the map file");
    expectLoadError([&] { loadRosMap(test::tmpDir()); }, test::tmpDir(), "is a directory");
}

TEST(ImageReader, MalformedPnmAndPng)
{
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "file is empty"},
        {"GIF89a....", "unsupported image format"},
        {"P4\n2 2\n", "unsupported Netpbm type P4"},
        {"P5\n2", "truncated"},
        {"P5\n2 2\n255\n\x01\x02", "truncated pixel data"},
        {"P5\n1000000000 1000000000\n255\n", "exceed the limit"},
        // tiny files declaring big images: refused from the header, before any allocation
        {"P6\n16384 16384\n255\n", "the header declares 16384 x 16384 pixels"},
        {"P3\n16384 16384\n255\n1 2 3\n", "the header declares 16384 x 16384 pixels"},
        {"P5\n20000 20000\n255\n", "exceed the limit"},
        {"P5\n0 5\n255\n", "dimensions must be positive"},
        {"P5\n2 2\n0\n....", "maxval must be in 1..65535"},
        {"P5\n2 2\n70000\n", "maxval must be in 1..65535"},
        {"P2\n2 1\n255\n12 300\n", "exceeds maxval"},
        {"P2\n2 x\n255\n", "bad header field height"},
        {"P2\n2 2\n255\n1 2 3\n", "truncated pixel data"},
        {"P6\n2 2\n255\n\x01\x02\x03", "truncated pixel data"},
        {std::string("\x89PNG\r\n\x1a\n", 8), "bad PNG header"},
    };
    int k = 0;
    for (const auto &c : cases)
    {
        const std::string name = "bad" + std::to_string(k++) + ".img";
        const std::string path = writeFile(name, c.first);
        expectLoadError([&] { readImage(path); }, name, c.second);
    }
    // a PNG whose IHDR claims 10^9 x 10^9 pixels is refused before decoding
    std::string png("\x89PNG\r\n\x1a\n", 8);
    png += std::string("\x00\x00\x00\x0dIHDR", 8);
    png += std::string("\x3b\x9a\xca\x00\x3b\x9a\xca\x00\x08\x00\x00\x00\x00", 13);
    png += std::string("\x00\x00\x00\x00", 4);
    const std::string hp = writeFile("huge.png", png);
    try
    {
        readImage(hp);
        ADD_FAILURE() << "huge PNG accepted";
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find("huge.png"), std::string::npos);
    }
}

TEST(ImageReader, ZeroLengthIdatChunkIsSkipped)
{
    // legal PNG, but stb_image's inflater did null-pointer arithmetic on it (undefined
    // behaviour; the sanitizer run of the tests would stop here)
    Image img;
    img.width = 3;
    img.height = 2;
    img.channels = 1;
    img.data = {0, 50, 100, 150, 200, 250};
    const std::string good = test::tmpDir() + "/idat.png";
    writePng(good, img);
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t idat = bytes.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    bytes.insert(idat - 4, std::string("\0\0\0\0IDAT\x35\xaf\x06\x1e", 12));
    const std::string bad = writeFile("idat-empty.png", bytes);
    const Image back = readImage(bad);
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.data, img.data);
}

TEST(ImageReader, SixteenBitAndCommentsAreRead)
{
    const std::string p = writeFile("s16.pgm", std::string("P5\n# a\n# b\n2 1\n65535\n") + std::string("\xff\xff\x00\x00", 4));
    const Image img = readImage(p);
    ASSERT_EQ(img.width, 2);
    EXPECT_EQ(img.data[0], 255);
    EXPECT_EQ(img.data[1], 0);
}

TEST(MovingAi, ReadsMapWithCrlf)
{
    const std::string p = writeFile("t.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.@T\r\nGS.");
    const OccupancyGrid g = loadMovingAiMap(p);
    ASSERT_EQ(g.width(), 3);
    ASSERT_EQ(g.height(), 2);
    EXPECT_DOUBLE_EQ(g.resolution(), 1.0);
    EXPECT_EQ(g.at(0, 0), CellState::Free);
    EXPECT_EQ(g.at(1, 0), CellState::Occupied);
    EXPECT_EQ(g.at(2, 0), CellState::Occupied);
    EXPECT_EQ(g.at(0, 1), CellState::Free);
    EXPECT_EQ(g.at(1, 1), CellState::Free);
}

TEST(MovingAi, MalformedMaps)
{
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"height 1\nwidth 1\nmap\n.\n", "missing header line 'type octile'"},
        {"type tile\nheight 1\nwidth 1\nmap\n.\n", "unsupported map type"},
        {"type octile\nwidth 1\nmap\n.\n", "missing 'height' or 'width'"},
        {"type octile\nheight x\nwidth 1\nmap\n.\n", "'height' needs an integer"},
        {"type octile\nheight 1\nwidth 1\n", "missing 'map' line"},
        {"type octile\nheight 1000000000\nwidth 1000000000\nmap\n", "absurd map size"},
        {"type octile\nheight 0\nwidth 4\nmap\n", "absurd map size"},
        {"type octile\nheight 1\nwidth 3\nmap\n..\n", "has 2 characters, expected 3"},
        {"type octile\nheight 1\nwidth 3\nmap\n....\n", "has 4 characters, expected 3"},
        {"type octile\nheight 1\nwidth 3\nmap\n.x.\n", "invalid map character 'x'"},
        {"type octile\nheight 1\nwidth 3\nmap\n.\x01.\n", "invalid map character '\\x01'"},  // no raw bytes echoed
        {"type octile\nheight 16384\nwidth 16384\nmap\n" + std::string(16000, '.'), "the header declares 16384 x 16384 cells"},
        {"type octile\nheight 3\nwidth 1\nmap\n.\n", "truncated: the header declares 1 x 3 cells"},
        {"type octile\nheight 1\nwidth 1\nmap\n.\n.\n", "more rows than the header's height"},
        {"type octile\nfoo 3\nheight 1\nwidth 1\nmap\n.\n", "unexpected header line"},
    };
    int k = 0;
    for (const auto &c : cases)
    {
        const std::string name = "bad" + std::to_string(k++) + ".map";
        const std::string path = writeFile(name, c.first);
        expectLoadError([&] { loadMovingAiMap(path); }, name, c.second);
    }
    expectLoadError([&] { loadMovingAiMap(test::tmpDir() + "/none.map"); }, "none.map", "cannot open the Moving AI map");
    expectLoadError([&] { loadMovingAiMap(test::tmpDir()); }, test::tmpDir(), "is a directory, not a Moving AI map");
    expectLoadError([&] { loadScenario(test::tmpDir()); }, test::tmpDir(), "is a directory, not a Moving AI scenario file");
}

TEST(MovingAi, ScenarioReader)
{
    const std::string p = writeFile("t.scen", "version 1\r\n0\tt.map\t3\t2\t0\t0\t2\t1\t2.41421356\r\n\r\n");
    const auto s = loadScenario(p);
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s[0].map, "t.map");
    EXPECT_EQ(s[0].mapWidth, 3);
    EXPECT_EQ(s[0].goalX, 2);
    EXPECT_EQ(s[0].goalY, 1);
    EXPECT_NEAR(s[0].optimalLength, 2.41421356, 1e-12);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "empty scenario file"},
        {"0\tm\t3\t2\t0\t0\t2\t1\t2.4\n", "expected 'version 1'"},
        {"version 2\n", "unsupported scenario version"},
        {"version 1\n0\tm\t3\t2\t0\t0\t2\t1\n", "expected 9 columns, found 8"},
        {"version 1\n0\tm\t3\t2\t0\t0\t2\t1\t2\t9\n", "expected 9 columns, found 10"},
        {"version 1\n0\tm\t3\t2\tx\t0\t2\t1\t2.4\n", "malformed number"},
        {"version 1\n0\tm\t3\t2\t-1\t0\t2\t1\t2.4\n", "malformed number"},
        {"version 1\n0\tm\t3\t2\t0\t0\t5\t1\t2.4\n", "outside the stated map size"},
        {"version 1\n0\tm\t3\t2\t0\t0\t2\t1\tnan\n", "malformed number"},
        {"version 1\n0\tm\t3\t2\t0\t0\t2\t1\t2.4abc\n", "malformed number"},
        {"version 1\n0\tm\t3\t2\t0\t0\t2\t1\t-2\n", "malformed number"},
    };
    int k = 0;
    for (const auto &c : cases)
    {
        const std::string name = "bad" + std::to_string(k++) + ".scen";
        const std::string path = writeFile(name, c.first);
        expectLoadError([&] { loadScenario(path); }, name, c.second);
    }
}

TEST(ImageMap, PpmDarkIsOccupiedAndMalformedFilesFail)
{
    std::string ppm = "P6\n2 1\n255\n";
    ppm += std::string("\x00\x00\x00\xff\x00\x00", 6);  // black, red
    const OccupancyGrid g = loadImageMap(writeFile("t.ppm", ppm));
    EXPECT_EQ(g.at(0, 0), CellState::Occupied);
    EXPECT_EQ(g.at(1, 0), CellState::Free);  // OMPL's red start marker is not a wall
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "file is empty"},
        {"P6\n", "truncated"},
        {"P6\n2 2\n255\n\x01", "truncated pixel data"},
        {"P6\n-2 2\n255\n", "bad header field width"},
        {"P6\n99999999 99999999\n255\n", "exceed the limit"},
        {"P6\n2 2\n0\n", "maxval must be in 1..65535"},
        {"P7\n2 2\n255\n", "unsupported Netpbm type P7"},
        {"P3\n1 1\n255\n1 2\n", "truncated pixel data"},
        {"P3\n1 1\n255\n1 2 999\n", "exceeds maxval"},
        {"XX", "unsupported image format"},
    };
    int k = 0;
    for (const auto &c : cases)
    {
        const std::string name = "bad" + std::to_string(k++) + ".ppm";
        const std::string path = writeFile(name, c.first);
        expectLoadError([&] { loadImageMap(path); }, name, c.second);
    }
    expectLoadError([&] { loadMap(writeFile("x.tiff", "II*")); }, "x.tiff", "unknown map format");
}

TEST(RosMap, WriteThenReadRoundTrip)
{
    OccupancyGrid g(5, 4, 0.2);
    g.setOrigin(3.0, -1.5, 0.0);
    g.set(1, 2, CellState::Occupied);
    g.set(4, 0, CellState::Unknown);
    for (const char *fmt : {"rt.pgm", "rt.png"})
    {
        const std::string yaml = test::tmpDir() + "/" + std::string(fmt) + ".yaml";
        saveRosMap(g, yaml, fmt);
        const OccupancyGrid h = loadRosMap(yaml);
        ASSERT_EQ(h.width(), 5);
        EXPECT_DOUBLE_EQ(h.originX(), 3.0);
        EXPECT_DOUBLE_EQ(h.resolution(), 0.2);
        EXPECT_EQ(h.cells(), g.cells()) << fmt;
    }
}

