// Path files (readPath: CSV, YAML, JSON; the first byte picks the extension), then a path read
// is written back in every format and must read back with as many poses.
#include "FuzzUtil.h"

#include "gridcar/path/PathIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0) return 0;
    static const char *ext[3] = {"csv", "yaml", "json"};
    const std::string path = gridcar::fuzz::writeFile(std::string("path.") + ext[data[0] % 3], data + 1, size - 1);
    gridcar::fuzz::expectCleanly([&] {
        const std::vector<gridcar::Pose2> p = gridcar::readPath(path);
        for (const char *e : ext)
        {
            const std::string back = gridcar::fuzz::workDir() + "/back." + e;
            gridcar::writePath(back, p, gridcar::AngleUnit::Radians);
            if (gridcar::readPath(back).size() != p.size()) gridcar::fuzz::finding("round trip lost poses", back);
        }
    });
    return 0;
}
