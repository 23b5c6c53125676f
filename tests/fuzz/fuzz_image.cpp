// PGM / PPM / PNG decoding (readImage through loadImageMap): the first byte picks the file's
// extension, the rest is its content.
#include "FuzzUtil.h"

#include "gridcar/map/MapIO.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size < 1) return 0;
    static const char *ext[] = {".pgm", ".ppm", ".png"};
    const std::string path = gridcar::fuzz::writeFile(std::string("image") + ext[data[0] % 3], data + 1, size - 1);
    gridcar::fuzz::expectCleanly([&] { (void)gridcar::loadImageMap(path, 0.5); });
    return 0;
}
