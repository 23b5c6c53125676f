// `gridcar drive --scenario` files (Scenario::load), then the obstacles sampled over time.
#include "FuzzUtil.h"

#include "gridcar/sim/Simulation.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string path = gridcar::fuzz::writeFile("scenario.yaml", data, size);
    gridcar::fuzz::expectCleanly([&] { (void)gridcar::Scenario::load(path); });
    return 0;
}
