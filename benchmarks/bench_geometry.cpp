// Geometry-core micro-benchmarks (Google Benchmark): distance transform + Voronoi of the
// paper-sized campus map, and footprint checks per second on the fast and the exact path.
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/CampusGenerator.h"

#include <benchmark/benchmark.h>

#include <memory>
#include <random>

using namespace gridcar;

namespace
{
std::shared_ptr<const OccupancyGrid> campus()
{
    static auto g = std::make_shared<const OccupancyGrid>(generateCampus());  // 4846 x 2816
    return g;
}
std::shared_ptr<const DistanceField> campusField()
{
    static auto f = std::make_shared<const DistanceField>(*campus());
    return f;
}

/// Poses whose isValid() answer comes from the fast path (fast = true) or needs the exact test.
std::vector<Pose2> poses(const FootprintChecker &fc, bool fast, std::size_t n)
{
    const OccupancyGrid &g = fc.grid();
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> uc(0, g.width() - 1), ur(0, g.height() - 1);
    std::uniform_real_distribution<double> uy(-M_PI, M_PI);
    std::vector<Pose2> out;
    const double h = g.resolution() * std::sqrt(2.0) / 2;
    const double rOut = fc.vehicle().circumscribedRadius(), rIn = fc.vehicle().inscribedRadius();
    while (out.size() < n)
    {
        const int c = uc(rng), r = ur(rng);
        if (g.isBlocked(c, r)) continue;
        const double yaw = uy(rng);
        const double off = fc.vehicle().centreOffset();
        const double x = g.cellCenterX(c) - off * std::cos(yaw), y = g.cellCenterY(r) - off * std::sin(yaw);
        const double d = fc.field().cellDistance(c, r);
        const bool isFast = d - 2 * h > rOut || d + h < rIn;
        if (isFast == fast) out.push_back({x, y, yaw});
    }
    return out;
}
}  // namespace

static void BM_DistanceFieldCampus(benchmark::State &state)
{
    const auto g = campus();
    for (auto _ : state)
    {
        DistanceField f(*g);
        benchmark::DoNotOptimize(f.maxDistance());
    }
    state.counters["cells"] = double(g->size());
    state.counters["cells_per_s"] = benchmark::Counter(double(g->size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_DistanceFieldCampus)->Unit(benchmark::kMillisecond)->Iterations(3);

static void BM_FootprintCheck(benchmark::State &state)
{
    const bool fast = state.range(0) == 1;
    FootprintChecker fc(campus(), campusField(), VehicleParams::preset("paper-i"));
    const auto ps = poses(fc, fast, 4096);
    std::size_t i = 0, valid = 0;
    for (auto _ : state)
    {
        const Pose2 &p = ps[i++ & 4095];
        valid += fc.isValid(p.x, p.y, p.yaw);
    }
    benchmark::DoNotOptimize(valid);
    state.SetLabel(fast ? "fast path (distance field)" : "exact path (distance-field halving)");
    state.counters["checks_per_s"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FootprintCheck)->Arg(1)->Arg(0);

BENCHMARK_MAIN();
