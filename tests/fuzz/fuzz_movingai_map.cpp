// Moving AI .map files (loadMovingAiMap).
#include "FuzzUtil.h"

#include "gridcar/map/MapIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string path = gridcar::fuzz::writeFile("x.map", data, size);
    gridcar::fuzz::expectCleanly([&] { (void)gridcar::loadMovingAiMap(path); });
    return 0;
}
