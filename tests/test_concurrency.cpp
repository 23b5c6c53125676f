// What may be shared between threads (docs/reliability.md, "Thread safety"), each claim tested
// here and run under ThreadSanitizer by the test command (scripts/tsan.sh):
// - one map, distance field and footprint checker shared by planners in several threads,
//   each thread with its own SimpleSetup and planner: the same answers as one thread alone;
// - a planner's progress properties read from another thread while it solves (what
//   ompl::tools::Benchmark's progress thread does), and a whole Benchmark run with progress
//   sampling on, for our planners beside OMPL's;
// - a distance field's Voronoi diagram, built on first use, asked for by threads at once.
#include "gridcar/distance/DistanceField.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <random>
#include <thread>

using namespace gridcar;
using namespace gridcar::test;
namespace ob = ompl::base;

namespace
{
std::shared_ptr<const OccupancyGrid> wallsMap() { return twoWallsMap(200, 160); }

/// A set-up of its own (SimpleSetup, SpaceInformation) on the shared checker.
GridSetup setupOn(const std::shared_ptr<const OccupancyGrid> &grid, const std::shared_ptr<const DistanceField> &field,
                  const std::shared_ptr<FootprintChecker> &checker)
{
    GridSetup s = makeGridSetup(grid, checker->vehicle(), SetupOptions(), field);
    const auto &si = s.ss->getSpaceInformation();
    si->setStateValidityChecker(std::make_shared<FootprintValidityChecker>(si, checker));
    si->setMotionValidator(std::make_shared<FootprintMotionValidator>(si, checker));
    s.checker = checker;
    return s;
}

/// Seeded free start / goal poses.
std::vector<std::pair<Pose2, Pose2>> queries(const FootprintChecker &fc, int n)
{
    std::mt19937 rng(5);
    const OccupancyGrid &g = fc.grid();
    std::uniform_int_distribution<int> col(4, g.width() - 5), row(4, g.height() - 5);
    std::vector<std::pair<Pose2, Pose2>> out;
    while (int(out.size()) < n)
    {
        const Pose2 a{g.cellCenterX(col(rng)), g.cellCenterY(row(rng)), 0.0}, b{g.cellCenterX(col(rng)), g.cellCenterY(row(rng)), 0.0};
        if (fc.isValid(a) && fc.isValid(b) && fc.field().distance(a.x, a.y) > 1.0 && fc.field().distance(b.x, b.y) > 1.0)
            out.push_back({a, b});
    }
    return out;
}

/// The path lengths one planner gives for every query, on its own set-up.
std::vector<double> lengths(GridSetup &s, const std::string &planner, const std::vector<std::pair<Pose2, Pose2>> &qs)
{
    std::vector<double> out;
    auto p = configurePlanner(s.ss->getSpaceInformation(), {planner, {}, false, false});
    for (const auto &[a, b] : qs)
    {
        const QueryResult q = runQuery(s, p, a, b, 10.0);
        out.push_back(q.status == ob::PlannerStatus::EXACT_SOLUTION ? q.metrics.length : -1.0);
    }
    return out;
}
}  // namespace

TEST(Concurrency, OneCheckerSharedByPlannersInFourThreadsGivesTheSerialAnswers)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const auto grid = wallsMap();
    const auto field = std::make_shared<const DistanceField>(*grid);
    const auto checker = std::make_shared<FootprintChecker>(grid, field, VehicleParams::preset("paper-c-robot"));
    const auto qs = queries(*checker, 12);
    const std::vector<std::string> planners{"corner-astar", "improved-astar", "astar-euclidean", "corner-astar"};
    std::vector<std::vector<double>> serial, parallel(planners.size());
    for (const auto &name : planners)
    {
        GridSetup s = setupOn(grid, field, checker);
        serial.push_back(lengths(s, name, qs));
    }
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < planners.size(); ++t)
        threads.emplace_back([&, t] {
            GridSetup s = setupOn(grid, field, checker);
            parallel[t] = lengths(s, planners[t], qs);
        });
    for (auto &th : threads) th.join();
    int solved = 0;
    for (std::size_t t = 0; t < planners.size(); ++t)
        for (std::size_t i = 0; i < qs.size(); ++i)
        {
            EXPECT_EQ(parallel[t][i], serial[t][i]) << planners[t] << " query " << i;
            solved += serial[t][i] > 0;
        }
    EXPECT_GE(solved, int(planners.size() * qs.size()) / 2);
}

// The distance field's Voronoi diagram is built on first use: threads that ask for it at once
// on a shared field see one diagram, the one a field built alone gives.
TEST(Concurrency, TheVoronoiDiagramBuiltOnFirstUseIsOneForEveryThread)
{
    OccupancyGrid g(120, 80, 0.1);
    for (int c = 10; c < 110; ++c)
    {
        g.set(c, 20, CellState::Occupied);
        g.set(c, 60, CellState::Occupied);
    }
    const DistanceField alone(g);
    const std::size_t expected = alone.voronoiCellCount();
    const double expectedAt = alone.cellVoronoiDistance(60, 30);
    const DistanceField shared(g);
    std::vector<std::size_t> counts(4);
    std::vector<double> at(4);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
        threads.emplace_back([&, t] {
            at[std::size_t(t)] = shared.cellVoronoiDistance(60, 30);
            counts[std::size_t(t)] = shared.voronoiCellCount();
        });
    for (auto &th : threads) th.join();
    ASSERT_GT(expected, 0u);
    for (int t = 0; t < 4; ++t)
    {
        EXPECT_EQ(counts[std::size_t(t)], expected);
        EXPECT_EQ(at[std::size_t(t)], expectedAt);
    }
}

TEST(Concurrency, ProgressPropertiesMayBeReadWhileThePlannerSolves)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const char *name : {"corner-astar", "improved-astar", "astar-euclidean", "corner-astar+smooth"})
    {
        SCOPED_TRACE(name);
        GridSetup s = testSetup("paper-c-robot");
        const OccupancyGrid &g = *s.grid;
        auto planner = configurePlanner(s.ss->getSpaceInformation(), {name, {{"lattice_cell", "0.5"}}, false, false});
        s.ss->setPlanner(planner);
        s.setStartAndGoal(cellPose(g, 2, 20), cellPose(g, 50, 6));  // the goal in the closed room
        std::atomic<bool> done{false};
        std::atomic<int> reads{0};
        std::thread reader([&] {
            const auto props = planner->getPlannerProgressProperties();
            do
                for (const auto &kv : props)
                {
                    const std::string v = kv.second();
                    EXPECT_FALSE(v.empty()) << kv.first;
                    ++reads;
                }
            while (!done);
        });
        s.ss->solve(0.3);
        done = true;
        reader.join();
        EXPECT_GT(reads.load(), 0);
    }
}

TEST(Concurrency, OmplBenchmarkSamplesProgressOfOurPlannersAndOmpls)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = testSetup("paper-c-robot");
    const OccupancyGrid &g = *s.grid;
    s.setStartAndGoal(cellPose(g, 2, 20), cellPose(g, 50, 6));  // unreachable: every run to the limit
    ompl::tools::Benchmark b(*s.ss, "concurrency");
    for (const char *name : {"corner-astar", "improved-astar", "astar-octile", "rrtconnect"})
        b.addPlanner(configurePlanner(s.ss->getSpaceInformation(), {name, {}, false, false}));
    ompl::tools::Benchmark::Request req(0.2, 4096.0, 2, /*timeBetweenUpdates=*/0.01, false, false, false);
    b.benchmark(req);
    const auto &exp = b.getRecordedExperimentData();
    ASSERT_EQ(exp.planners.size(), 4u);
    for (const auto &p : exp.planners)
    {
        EXPECT_EQ(p.runs.size(), 2u) << p.name;
        if (p.name.find("RRTConnect") != std::string::npos) continue;
        EXPECT_NE(std::find(p.progressPropertyNames.begin(), p.progressPropertyNames.end(), "expanded nodes INTEGER"),
                  p.progressPropertyNames.end())
            << p.name;
    }
}
