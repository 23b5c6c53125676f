// The map's cost layer: read from map_server scale / raw maps (and Nav2 costmap values),
// carried by crops and resampling, and used by the car-lattice planners when asked
// (`cost_layer_weight`): a costly strip is driven round, not through.
#include "gridcar/query/PlanQuery.h"
#include "gridcar/core/Errors.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/spaces/Setup.h"

#include "TestData.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace gridcar;

namespace
{
std::string writeFile(const std::string &name, const std::string &content)
{
    const std::string path = test::tmpDir() + "/" + name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
}

std::string pgm(int w, int h, const std::vector<int> &values)
{
    std::string s = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    for (int v : values) s += char(v);
    return s;
}

/// 40 m x 30 m at 0.25 m, free; a band of cost 252 across the middle row of the map but for a
/// gap near the right edge: the straight way crosses it, the free way goes round.
std::shared_ptr<OccupancyGrid> costBandMap()
{
    auto g = std::make_shared<OccupancyGrid>(160, 120, 0.25, CellState::Free);
    for (int r = 50; r < 70; ++r)
        for (int c = 0; c < 130; ++c) g->set(c, r, CellState::Free), g->setCost(c, r, 252);
    return g;
}

double meanCostAlong(const OccupancyGrid &g, const std::vector<Pose2> &path)
{
    double sum = 0;
    for (const Pose2 &p : path)
    {
        const Cell c = g.worldToCell(p.x, p.y);
        sum += g.cost(c.col, c.row);
    }
    return path.empty() ? 0 : sum / double(path.size());
}
}  // namespace

TEST(CostLayer, ScaleAndRawModesGiveCostsTrinaryStaysAsItWas)
{
    // p = (255 - v) / 255: v 255 -> 0 free, 0 -> 1 occupied, 128 -> 0.498 between the thresholds
    writeFile("cost.pgm", pgm(3, 1, {255, 0, 128}));
    const OccupancyGrid tri = loadRosMap(writeFile("tri.yaml", "image: cost.pgm\nresolution: 1\norigin: [0, 0, 0]\n"));
    EXPECT_EQ(tri.at(2, 0), CellState::Unknown);
    EXPECT_FALSE(tri.hasCosts());
    const OccupancyGrid sc =
        loadRosMap(writeFile("scale.yaml", "image: cost.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: scale\n"));
    EXPECT_EQ(sc.at(0, 0), CellState::Free);
    EXPECT_EQ(sc.at(1, 0), CellState::Occupied);
    EXPECT_EQ(sc.at(2, 0), CellState::Free);
    ASSERT_TRUE(sc.hasCosts());
    // 252 (0.498 - 0.196) / (0.65 - 0.196) = 167.7
    EXPECT_NEAR(sc.cost(2, 0), 168, 1);
    EXPECT_EQ(sc.cost(0, 0), 0);
    // Nav2 costmap values in raw mode: 0..252 costs, 253-254 lethal, 255 unknown
    writeFile("costmap.pgm", pgm(5, 1, {0, 100, 252, 254, 255}));
    const OccupancyGrid cm = loadRosMap(
        writeFile("costmap.yaml", "image: costmap.pgm\nresolution: 0.5\norigin: [0, 0, 0]\nmode: raw\nvalues: costmap\n"));
    EXPECT_EQ(cm.at(0, 0), CellState::Free);
    EXPECT_EQ(cm.at(1, 0), CellState::Free);
    EXPECT_EQ(cm.cost(1, 0), 100);
    EXPECT_EQ(cm.cost(2, 0), 252);
    EXPECT_EQ(cm.at(3, 0), CellState::Occupied);
    EXPECT_EQ(cm.at(4, 0), CellState::Unknown);
    // values: costmap needs raw; an unknown values word is refused
    EXPECT_THROW(loadRosMap(writeFile("bad1.yaml", "image: costmap.pgm\nresolution: 1\norigin: [0, 0, 0]\nvalues: costmap\n")),
                 MapLoadError);
    EXPECT_THROW(
        loadRosMap(writeFile("bad2.yaml", "image: costmap.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: raw\nvalues: cost\n")),
        MapLoadError);
}

TEST(CostLayer, CropsAndResamplingKeepTheCosts)
{
    OccupancyGrid g(8, 8, 0.5);
    g.setCost(5, 2, 40);
    g.setCost(4, 3, 200);
    const OccupancyGrid crop = g.cropped(4, 2, 3, 3);
    EXPECT_EQ(crop.cost(1, 0), 40);
    EXPECT_EQ(crop.cost(0, 1), 200);
    const OccupancyGrid coarse = g.resampled(1.0);  // the highest cost under each new cell
    const Cell c = coarse.worldToCell(g.cellCenterX(4), g.cellCenterY(3));
    EXPECT_EQ(coarse.cost(c.col, c.row), 200);
    EXPECT_THROW(g.setCost(0, 0, 253), std::invalid_argument);
    EXPECT_THROW(g.setCost(9, 0, 1), std::invalid_argument);
}

TEST(CostLayer, CarLatticePlannersDriveRoundACostlyBandWhenAsked)
{
    auto grid = costBandMap();
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset("paper-c-robot"));
    const Pose2 start{5, 25, -M_PI / 2}, goal{5, 5, -M_PI / 2};
    // improved-astar in integral mode: paper I's own ordering g + h (1 + o) is greedy and goes
    // through (the layer's cost is in g, but h decides)
    for (const std::string name : {"corner-astar", "improved-astar"})
    {
        const PlannerParams base = name == "improved-astar" ? PlannerParams{{"mode", "integral"}} : PlannerParams{};
        PlannerParams withLayer = base;
        withLayer.push_back({"cost_layer_weight", "20"});
        const auto plain = configurePlanner(setup.ss->getSpaceInformation(), {name, base, false, false});
        const QueryResult a = runQuery(setup, plain, start, goal, 10.0, false);
        ASSERT_EQ(a.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << name;
        const auto weighted = configurePlanner(setup.ss->getSpaceInformation(), {name, withLayer, false, false});
        const QueryResult b = runQuery(setup, weighted, start, goal, 10.0, false);
        ASSERT_EQ(b.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << name;
        // without the weight straight through the band; with it round by the gap, longer and cheap
        EXPECT_LT(a.metrics.length, 25.0) << name;
        EXPECT_GT(meanCostAlong(*grid, a.path), 40.0) << name;
        EXPECT_GT(b.metrics.length, 40.0) << name;
        EXPECT_LT(meanCostAlong(*grid, b.path), 5.0) << name;
        EXPECT_TRUE(b.drivability.drivable) << b.drivability.reason;
    }
}

TEST(CostLayer, TheWeightIsACarLatticeParameterInItsRange)
{
    auto grid = costBandMap();
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset("paper-c-robot"));
    EXPECT_THROW(configurePlanner(setup.ss->getSpaceInformation(), {"corner-astar", {{"cost_layer_weight", "-1"}}, false, false}),
                 InputError);
    // on the grid lattice it does not act: not declared there, refused where it is set
    EXPECT_THROW(configurePlanner(setup.ss->getSpaceInformation(), {"corner-astar-grid", {{"cost_layer_weight", "1"}}, false, false}),
                 InputError);
}
