// ROS map_server pair: the YAML, then "\n---IMAGE---\n", then the image bytes (written both as
// m.pgm and m.png, the names the seed YAML files use). A map that loads and is small enough is
// then used as the program would: distance field, footprint checker, one footprint test.
#include "FuzzUtil.h"

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/MapIO.h"

#include <memory>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    using namespace gridcar;
    std::string yaml, image;
    fuzz::split(data, size, "\n---IMAGE---\n", yaml, image);
    const auto *img = reinterpret_cast<const std::uint8_t *>(image.data());
    fuzz::writeFile("m.pgm", img, image.size());
    fuzz::writeFile("m.png", img, image.size());
    const std::string path = fuzz::writeFile("m.yaml", reinterpret_cast<const std::uint8_t *>(yaml.data()), yaml.size());
    fuzz::expectCleanly([&] {
        auto grid = std::make_shared<const OccupancyGrid>(loadRosMap(path));
        if (std::size_t(grid->width()) * std::size_t(grid->height()) > 65536) return;
        auto field = std::make_shared<const DistanceField>(*grid);
        FootprintChecker checker(grid, field, VehicleParams::preset("paper-i"));
        const double x = grid->originX() + grid->sizeX() / 2, y = grid->originY() + grid->sizeY() / 2;
        (void)checker.isValid(x, y, 0.3);
        (void)checker.clearance(x, y, 0.3);
    });
    return 0;
}
