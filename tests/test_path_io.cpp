// Path files: CSV, YAML and JSON round trips in both angle units, the older CSV forms, and
// malformed files reported with the file and the reason.
#include "gridcar/core/Errors.h"
#include "gridcar/path/PathIO.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace gridcar;

namespace
{
std::string writeFile(const std::string &name, const std::string &content)
{
    const std::string path = test::tmpDir() + "/" + name;
    std::ofstream f(path, std::ios::binary);
    f << content;
    return path;
}

std::string readAll(const std::string &file)
{
    std::ifstream f(file);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

std::vector<Pose2> randomPath(unsigned seed, int n)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> xy(-500, 500), yaw(-M_PI, M_PI);
    std::vector<Pose2> p;
    for (int i = 0; i < n; ++i) p.push_back({xy(rng), xy(rng), yaw(rng)});
    return p;
}

void expectError(const std::string &file, const std::string &reason)
{
    try
    {
        readPath(file);
        ADD_FAILURE() << file << ": no error, expected '" << reason << "'";
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
}
}  // namespace

TEST(PathIO, EveryFormatAndUnitReadsBackWhatWasWritten)
{
    const std::vector<Pose2> path = randomPath(3, 200);
    for (const std::string ext : {"csv", "yaml", "yml", "json"})
        for (AngleUnit unit : {AngleUnit::Degrees, AngleUnit::Radians})
        {
            const std::string file = test::tmpDir() + "/round." + ext;
            writePath(file, path, unit);
            const std::vector<Pose2> back = readPath(file);
            ASSERT_EQ(back.size(), path.size()) << file;
            for (std::size_t i = 0; i < path.size(); ++i)
            {
                EXPECT_NEAR(back[i].x, path[i].x, 1e-6) << file << " pose " << i;
                EXPECT_NEAR(back[i].y, path[i].y, 1e-6) << file << " pose " << i;
                EXPECT_NEAR(std::remainder(back[i].yaw - path[i].yaw, 2 * M_PI), 0.0, 1e-8) << file << " pose " << i;
            }
            // the unit is named in the file
            const std::string text = readAll(file);
            const bool deg = unit == AngleUnit::Degrees;
            if (ext == "csv")
                EXPECT_EQ(text.substr(0, 12), deg ? "x,y,yaw_deg\n" : "x,y,yaw_rad\n");
            else
                EXPECT_NE(text.find(deg ? "deg" : "rad"), std::string::npos) << text.substr(0, 100);
        }
}

TEST(PathIO, DegreesAreDegreesInTheFile)
{
    const std::string file = test::tmpDir() + "/deg.yaml";
    writePath(file, {{0, 0, M_PI / 2}, {1, 0, -M_PI / 4}});
    const std::string text = readAll(file);
    EXPECT_NE(text.find("yaw: 90}"), std::string::npos) << text;
    EXPECT_NE(text.find("yaw: -45}"), std::string::npos) << text;
    EXPECT_NE(text.find("frame_id: map"), std::string::npos) << text;
}

TEST(PathIO, OlderAndHandWrittenCsvForms)
{
    // the header of earlier versions: yaw in radians
    auto p = readPath(writeFile("old.csv", "x,y,yaw\n1,2,1.5\n3,4,-1\n"));
    ASSERT_EQ(p.size(), 2u);
    EXPECT_DOUBLE_EQ(p[0].yaw, 1.5);
    // degrees by name, columns in another order, no header, no yaw
    p = readPath(writeFile("deg.csv", "yaw_deg, y, x\n90, 2, 1\n-90, 4, 3\n"));
    ASSERT_EQ(p.size(), 2u);
    EXPECT_DOUBLE_EQ(p[0].x, 1);
    EXPECT_DOUBLE_EQ(p[0].y, 2);
    EXPECT_NEAR(p[0].yaw, M_PI / 2, 1e-12);
    p = readPath(writeFile("bare.csv", "1,2\n3,4\n5,6\n"));
    ASSERT_EQ(p.size(), 3u);
    EXPECT_DOUBLE_EQ(p[2].x, 5);
    EXPECT_DOUBLE_EQ(p[2].yaw, 0);
    // JSON with radians, a yaw left out
    p = readPath(writeFile("r.json", R"({"angle_unit": "rad", "poses": [{"x": 1, "y": 2, "yaw": 3}, {"x": 2, "y": 2}]})"));
    ASSERT_EQ(p.size(), 2u);
    EXPECT_DOUBLE_EQ(p[0].yaw, 3);
    EXPECT_DOUBLE_EQ(p[1].yaw, 0);
}

TEST(PathIO, MalformedFilesNameTheFileAndTheReason)
{
    expectError(writeFile("e1.csv", "x,y,yaw\n1,2,abc\n3,4,5\n"), "line 2: 'abc' is not a number");
    expectError(writeFile("e2.csv", "x,y,yaw\n1,2,nan\n3,4,5\n"), "line 2: values must be finite");
    expectError(writeFile("e3.csv", "x,y,yaw\n1,2,3\n"), "at least two poses");
    expectError(writeFile("e4.csv", "a,b,c\n1,2,3\n"), "names no x and y columns");
    expectError(writeFile("e5.csv", "x,y,yaw\n1,2,3,4,5\n"), "line 2: expected");
    expectError(writeFile("e6.yaml", "poses: [{x: 1, y: 2}, {x: 2, y: 3}]\n"), "angle_unit (deg or rad) is missing");
    expectError(writeFile("e7.yaml", "angle_unit: grad\nposes: [{x: 1, y: 2}, {x: 2, y: 3}]\n"), "angle_unit must be deg or rad");
    expectError(writeFile("e8.yaml", "angle_unit: deg\nposes: [{x: 1, y: 2}, {y: 3}]\n"), "pose 2 x is missing");
    expectError(writeFile("e9.json", "{\"angle_unit\": \"deg\", \"poses\": [{\"x\": 1, \"y\": .inf}, {\"x\": 1, \"y\": 2}]}"),
                "pose 1 y must be finite");
    expectError(writeFile("e10.yaml", "angle_unit: deg\nposes: {x: 1}\n"), "'poses' must be a list");
    expectError(writeFile("e11.yaml", "[unclosed\n"), "not valid YAML");
    expectError(test::tmpDir() + "/no-such-path.csv", "no-such-path.csv");
    expectError(test::tmpDir(), "is a directory");
}

TEST(PathIO, FormatsComeFromTheExtension)
{
    EXPECT_EQ(pathFormatOf("a/b.CSV"), "csv");
    EXPECT_EQ(pathFormatOf("b.yml"), "yaml");
    EXPECT_EQ(pathFormatOf("b.Json"), "json");
    EXPECT_EQ(pathFormatOf("b.txt"), "");
    EXPECT_EQ(pathFormatOf("dir.csv/b"), "");
    EXPECT_THROW(writePath(test::tmpDir() + "/x.txt", {{0, 0, 0}, {1, 0, 0}}), std::invalid_argument);
    EXPECT_THROW(writePath("/nonexistent-dir/x.csv", {{0, 0, 0}, {1, 0, 0}}), MapLoadError);
}
