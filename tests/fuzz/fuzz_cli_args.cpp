// The command line's value parsing: each input line is one argument: pose (--start / --goal and
// --start-cell / --goal-cell against a 100 x 80 map), number lists, and --param NAME=VALUE.
#include "FuzzUtil.h"

#include "../../apps/cli/Cli.h"
#include "gridcar/query/PlanQuery.h"

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    using namespace gridcar;
    static const OccupancyGrid grid(100, 80, 0.5);
    std::istringstream in(std::string(reinterpret_cast<const char *>(data), size));
    std::string line;
    while (std::getline(in, line))
    {
        fuzz::expectCleanly([&] {
            bool yaw = false;
            (void)cli::parsePose(line, "", "start", grid, yaw);
        });
        fuzz::expectCleanly([&] {
            bool yaw = false;
            (void)cli::parsePose("", line, "goal", grid, yaw);
        });
        fuzz::expectCleanly([&] { (void)cli::parseNumbers(line, "--numbers", 1, 4); });
        fuzz::expectCleanly([&] { (void)parsePlannerParams({line}); });
    }
    return 0;
}
