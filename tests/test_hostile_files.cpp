// The readers against hostile files: the fuzz targets' findings (tests/fuzz/regressions/),
// each replayed here as a unit test so that the normal and sanitizer runs keep them fixed.
#include "gridcar/image/Image.h"
#include "gridcar/map/MapIO.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
std::string writeFile(const std::string &name, const std::string &content)
{
    const std::string path = test::tmpDir() + "/" + name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

/// @p png written to @p name must be refused by readImage with a MapLoadError saying @p reason.
void expectPngRefused(const std::string &name, const std::vector<std::uint8_t> &png, const std::string &reason)
{
    const std::string path = writeFile(name, std::string(png.begin(), png.end()));
    try
    {
        readImage(path);
        ADD_FAILURE() << name << ": decoded, expected \"" << reason << "\"";
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
}
}  // namespace

TEST(RosMap, ErrorMessagesNeverEchoRawBytes)
{
    // found by fuzz_ros_map: yaml-cpp's message about a bad escape quoted the byte itself
    // (tests/fuzz/regressions/fuzz_ros_map/); every MapLoadError / InputError is printable now
    std::string text = "image: m.pgm\nresolution:";
    text += '\0';
    text += "\x19.5\n";
    const std::string y = writeFile("ctl.yaml", text);
    try
    {
        loadRosMap(y);
        FAIL() << "loaded a map whose YAML has a raw control byte";
    }
    catch (const MapLoadError &e)
    {
        const std::string m = e.what();
        for (unsigned char c : m) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(c) << " in: " << m;
        EXPECT_NE(m.find("ctl.yaml"), std::string::npos) << m;
    }
    const InputError in(std::string("bad \x1b[31mred\x07 value\n"));
    EXPECT_EQ(std::string(in.what()), "bad \\x1b[31mred\\x07 value\\x0a");
}

TEST(ImageReader, PngWhoseDataInflatesPastItsHeaderIsRefusedWithoutAllocating)
{
    // found by fuzz_image (tests/fuzz/regressions/fuzz_image/png-inflation-bomb): a 76-byte PNG
    // declaring 243 x 3 pixels, for which stb_image allocated 1.3 GB: its IDAT chunk declares
    // 1291845651 bytes (first refused by the inflation check, now by the chunk-length check)
    const std::vector<std::uint8_t> png{0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0xf3, 0x00, 0x00, 0x00, 0x03, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x4d, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0xf8, 0xf7, 0x8f, 0x01, 0x88, 0x81, 0xe4, 0x59, 0x20, 0x05, 0x00, 0x3c, 0xcf, 0x08, 0x32, 0x5b, 0xd3, 0xfc, 0xf4, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    expectPngRefused("bomb.png", png, "truncated: chunk 'IDAT' declares 1291845651 bytes");
}

TEST(ImageReader, PngWithASecondHeaderChunkIsReadByItsFirst)
{
    // found by fuzz_ros_map (tests/fuzz/regressions/fuzz_ros_map/png-header-size-overflow): a
    // second IHDR chunk's size overflowed the inflation check (undefined behaviour under the
    // sanitizer run); the first IHDR counts, as for stb_image, and sizes stay in range
    const std::vector<std::uint8_t> png{0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x03, 0x08, 0x00, 0x00, 0x00, 0x00, 0x91, 0x9f, 0xf1, 0x1a, 0x00, 0x00, 0x00, 0x13, 0x49, 0x48, 0x44, 0x52, 0x78, 0xeb, 0x9c, 0x3a, 0x63, 0x00, 0x00, 0x60, 0xc0, 0x00, 0x04, 0xc4, 0x29, 0x60, 0xf8, 0xf7, 0x8f, 0x01, 0x88, 0x81, 0xe4, 0x59, 0x20, 0x08, 0x00, 0x3c, 0xcf, 0x08, 0xfe, 0x5b, 0xd3, 0xfc, 0xf4, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    std::ofstream(gridcar::test::tmpDir() + "/m.png", std::ios::binary)
        .write(reinterpret_cast<const char *>(png.data()), std::streamsize(png.size()));
    const std::string y = writeFile("two-headers.yaml", "image: m.png\nresolution: 1.05\norigin: [0, 0, 0]\nnegata: 1\noccupid_thresh: 0.65\nfr: 0.196\nmode: scale\n");
    try
    {
        const OccupancyGrid g = loadRosMap(y);
        EXPECT_EQ(g.width(), 4);
        EXPECT_EQ(g.height(), 3);
    }
    catch (const MapLoadError &e)
    {
        EXPECT_NE(std::string(e.what()).find("two-headers.yaml"), std::string::npos) << e.what();
    }
}

TEST(ImageReader, PngChunkHeaderInTheLastBytesIsRefusedBeforeAnyAllocation)
{
    // found by fuzz_image (tests/fuzz/regressions/fuzz_image/chunk-header-at-end-of-file): the
    // last 9 bytes of a 107-byte PNG are an IDAT chunk's length (1152270944) and type without
    // data or CRC; the chunk walk stopped 12 bytes before the end and let them through, and
    // stb_image grew its data buffer to 2 GB for that length before finding nothing to read
    const std::vector<std::uint8_t> png{0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xff, 0xd4, 0x9a, 0x73, 0x00, 0x00, 0x00, 0x16, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x60, 0x60, 0xf8, 0xff, 0x00, 0x50, 0x32, 0x0a, 0x34, 0x20, 0x33, 0x0a, 0x50, 0x7e, 0x0a, 0x34, 0x20, 0x00, 0x91, 0x9f, 0xf1, 0x1a, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x44, 0xae, 0x42, 0x0a, 0x34, 0x20, 0x00, 0x91, 0x9f, 0xf1, 0x1a, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x44, 0xae, 0x42, 0x60, 0x49, 0x44, 0x41, 0x54, 0x82};
    expectPngRefused("header-at-end.png", png, "truncated: chunk 'IDAT' declares 1152270944 bytes");
    // the same bytes after IEND are not read (as by stb_image): a valid PNG stays readable
    Image img;
    img.width = 2;
    img.height = 2;
    img.channels = 1;
    img.data = {0, 255, 255, 0};
    const std::string good = gridcar::test::tmpDir() + "/ends-at-iend.png";
    writePng(good, img);
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.append(png.end() - 9, png.end());
    const Image back = readImage(writeFile("tail-after-iend.png", bytes));
    EXPECT_EQ(back.data, img.data);
}

TEST(ImageReader, PngChunkLongerThanTheFileIsRefusedBeforeAnyAllocation)
{
    // found by fuzz_image (tests/fuzz/regressions/fuzz_image/chunk-longer-than-file): an 83-byte
    // PNG whose second IDAT chunk declares 838 MB made stb_image allocate 1 GB for it
    const std::vector<std::uint8_t> png{0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xff, 0xd4, 0x9a, 0x73, 0x00, 0x00, 0x00, 0x16, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60, 0x60, 0x60, 0xf8, 0xff, 0x00, 0x50, 0x32, 0x0a, 0x34, 0x49, 0x48, 0x44, 0x52, 0x35, 0x35, 0x0a, 0x27, 0x20, 0x32, 0x35, 0x34, 0x20, 0x32, 0x00, 0x00, 0x00, 0x49, 0x44, 0x41, 0x54, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    expectPngRefused("long-chunk.png", png, "truncated: chunk 'IDAT' declares 838860800 bytes");
}
