// Vehicle YAML files (VehicleParams::fromNameOrFile), then what the planners derive from one.
#include "FuzzUtil.h"

#include "gridcar/planners/CornerWeights.h"
#include "gridcar/vehicle/Dynamics.h"
#include "gridcar/vehicle/VehicleParams.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string path = gridcar::fuzz::writeFile("vehicle.yaml", data, size);
    gridcar::fuzz::expectCleanly([&] {
        const gridcar::VehicleParams v = gridcar::VehicleParams::fromNameOrFile(path);
        (void)gridcar::physicsCornerWeights(v);
        (void)gridcar::drivingTime({{0, 0, 0}, {10, 0, 0}, {10, 10, 1.5}}, v);
    });
    return 0;
}
