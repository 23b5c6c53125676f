// CurvatureStep: the car lattice's continuous-curvature post-processor on paths the search
// found (arcs: curvature jumps at every primitive's ends) on seeded random maps.
#include "PlannerTestUtil.h"

#include "gridcar/core/Cusps.h"
#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/path/Drivability.h"
#include "gridcar/planners/search/CurvatureStep.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

using namespace gridcar;
using test::randomBlocks;
using test::randomFree;

// The step's contract: the ends, the cusps and the guarantees kept (every pose free, curvature
// within K_max); each stretch that changes curvature too fast replaced where a free G2 stretch
// fits, the rest kept as they were; the largest rate never higher.
TEST(CurvatureStep, SearchedPathsKeepTheirEndsCuspsAndGuaranteesAndLoseTheirCurvatureJumps)
{
    int paths = 0, stretches = 0, replaced = 0, withinRate = 0, cancelled = 0;
    for (unsigned seed = 1; seed <= 4; ++seed)
    {
        auto g = randomBlocks(seed, 150, 150, 0.1, 12, 9);  // 15 m x 15 m, a few blocks
        auto field = std::make_shared<DistanceField>(*g);
        FootprintChecker fc(g, field, VehicleParams::preset("paper-c-robot"));
        const double rate = fc.vehicle().curvatureRateLimit();
        for (const bool reverse : {false, true})
        {
            auto lattice = std::make_shared<const CarLattice>(test::randomBlocksLattice(fc, reverse));
            CarLatticeSearch search(fc, lattice);
            const double kmax = 1.0 / lattice->config().turnRadius;
            const CurvatureStep step(search, kmax, rate);
            std::mt19937 rng(seed * 7 + (reverse ? 1u : 0u));
            for (int k = 0; k < 3; ++k)
            {
                CarLatticeQuery q;
                q.start = randomFree(fc, rng);
                q.goal = randomFree(fc, rng);
                q.goalYawTolerance = 0;
                LengthCost cost;
                const CarLatticeResult r = search.run(q, cost, [] { return false; });
                if (!r.exact || r.path.size() < 3) continue;
                const std::string at = "seed " + std::to_string(seed) + " reverse " + std::to_string(reverse) + " query " + std::to_string(k);
                std::vector<Pose2> p = r.path;
                // stopped at once (polled between stretches): the path as it was
                if (step.apply(p, [] { return true; }).cancelled)
                {
                    ASSERT_EQ(p.size(), r.path.size()) << at;
                    for (std::size_t i = 0; i < p.size(); ++i) ASSERT_TRUE(p[i].x == r.path[i].x && p[i].y == r.path[i].y) << at;
                    ++cancelled;
                }
                const CurvatureStepReport rep = step.apply(p, [] { return false; });
                ++paths;
                stretches += rep.stretches;
                replaced += rep.replaced;
                EXPECT_EQ(p.front().x, r.path.front().x) << at;
                EXPECT_EQ(p.back().x, r.path.back().x) << at;
                EXPECT_EQ(p.back().y, r.path.back().y) << at;
                EXPECT_EQ(p.back().yaw, r.path.back().yaw) << at;
                EXPECT_EQ(splitAtCusps(p).size(), splitAtCusps(r.path).size()) << at;
                DrivabilityOptions o;
                o.reversing = true;
                const Drivability d = checkDrivable(p, fc, o);
                EXPECT_TRUE(d.drivable) << at << ": " << d.reason;
                EXPECT_LE(d.maxCurvatureRate, checkDrivable(r.path, fc, o).maxCurvatureRate * (1 + 1e-9)) << at;
                if (rep.replaced == rep.stretches)
                {
                    o.maxCurvatureRate = rate;
                    const Drivability dr = checkDrivable(p, fc, o);
                    EXPECT_TRUE(dr.drivable) << at << ": every stretch replaced, yet " << dr.reason;
                    ++withinRate;
                }
            }
        }
    }
    EXPECT_GE(paths, 10);
    EXPECT_GT(cancelled, 0);
    // arcs jump at the primitives' ends: the step finds them and replaces many (a tight spot
    // leaves no room for some)
    EXPECT_GT(stretches, paths);
    EXPECT_GT(replaced, stretches / 4);
    EXPECT_GT(withinRate, 0);
    std::printf("curvature step: %d paths, %d stretches, %d replaced, %d paths within the rate\n", paths, stretches, replaced,
                withinRate);
}
