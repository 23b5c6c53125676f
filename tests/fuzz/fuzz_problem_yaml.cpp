// `gridcar bench` problem files (readProblem), and every query's poses read against a small map;
// the same bytes as a `--params-file` (readParamsFile), applied to the problem when both read.
#include "FuzzUtil.h"

#include "gridcar/bench/ParamsFile.h"
#include "gridcar/bench/Problem.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    using namespace gridcar;
    const std::string path = fuzz::writeFile("problem.yaml", data, size);
    static const OccupancyGrid grid(100, 80, 0.5);
    fuzz::expectCleanly([&] {
        bool skip = false;
        std::string why;
        const bench::Problem p = bench::readProblem(path, fuzz::workDir() + "/shared", skip, why);
        if (skip) return;
        for (std::size_t i = 0; i < p.queries.size(); ++i)
        {
            bool yaw = false;
            (void)bench::readPose(p, p.queries[i], "start", grid, yaw, i);
            (void)bench::readPose(p, p.queries[i], "goal", grid, yaw, i);
        }
    });
    fuzz::expectCleanly([&] {
        const bench::ParamsFile pf = bench::readParamsFile(path);
        bool skip = false;
        std::string why;
        bench::Problem p = bench::readProblem(path, fuzz::workDir() + "/shared", skip, why);
        if (!skip) bench::applyParamsFile(p, pf);
    });
    return 0;
}
