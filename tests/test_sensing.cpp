#include "gridcar/sim/Sensing.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridcar;

namespace
{
/// A 20 x 20 m room at 0.1 m cells, walls round it.
std::shared_ptr<OccupancyGrid> room()
{
    auto g = std::make_shared<OccupancyGrid>(200, 200, 0.1);
    for (int i = 0; i < 200; ++i)
    {
        g->set(i, 0, CellState::Occupied), g->set(i, 199, CellState::Occupied);
        g->set(0, i, CellState::Occupied), g->set(199, i, CellState::Occupied);
    }
    return g;
}

MovingObstacle box(double x, double y, double sx, double sy)
{
    MovingObstacle o;
    o.shape = MovingObstacle::Shape::Box;
    o.sizeX = sx, o.sizeY = sy;
    o.waypoints = {{x, y}};
    o.speed = 0.0;
    return o;
}

bool occupiedAt(const OccupancyGrid &g, double x, double y)
{
    const Cell c = g.worldToCell(x, y);
    return g.at(c.col, c.row) == CellState::Occupied;
}

/// The cell at (x, y) or the one before it along x (a face on a cell boundary).
bool faceAt(const OccupancyGrid &g, double x, double y) { return occupiedAt(g, x, y) || occupiedAt(g, x - 0.1, y); }
}  // namespace

// A standing box is put into the working map where the beams hit it, and only its side facing
// the sensor (line of sight); a pedestrian walking by is not.
TEST(Sensing, AStandingObstacleIsMappedWhereSeenAndAWalkingOneIsNot)
{
    const auto truth = room();
    WorkingMap wm(std::make_shared<OccupancyGrid>(*truth));
    Scenario sc;
    sc.obstacles.push_back(box(10.0, 5.0, 1.0, 1.0));
    MovingObstacle walker;
    walker.radius = 0.3;
    walker.waypoints = {{5.0, 2.0}, {5.0, 18.0}};
    walker.speed = 1.2;
    sc.obstacles.push_back(walker);
    const CellWindow w = wm.scan(*truth, sc, 5.0, 5.0, 5.03, RangeSensorParams());  // the walker at (5, 8)
    ASSERT_FALSE(w.empty());
    EXPECT_TRUE(faceAt(wm.grid(), 9.55, 5.03));   // the near face
    EXPECT_FALSE(occupiedAt(wm.grid(), 10.45, 5.03));  // the far face, behind it
    EXPECT_FALSE(occupiedAt(wm.grid(), 5.0, 7.75));   // the walker's near side
    EXPECT_GT(wm.sensedCells(), 5u);
    const auto inWindow = [&](double x) {
        const Cell c = wm.grid().worldToCell(x, 5.03);
        return c.col >= w.col0 && c.col <= w.col1 && c.row >= w.row0 && c.row <= w.row1;
    };
    EXPECT_TRUE(inWindow(9.55) || inWindow(9.45));
    // a second scan from the same place changes nothing
    EXPECT_TRUE(wm.scan(*truth, sc, 5.2, 5.0, 5.03, RangeSensorParams()).empty());
}

// A box that drives away is seen through later: its cells are free again, the map's own walls
// stay; beyond the range nothing is seen.
TEST(Sensing, AnObstacleThatLeavesIsClearedAndTheMapStays)
{
    const auto truth = room();
    WorkingMap wm(std::make_shared<OccupancyGrid>(*truth));
    Scenario sc;
    MovingObstacle b = box(8.0, 5.0, 1.0, 2.0);
    b.waypoints.push_back({17.0, 17.0});
    b.speed = 2.0;
    b.startTime = 10.0;
    sc.obstacles.push_back(b);
    RangeSensorParams p;
    p.range = 6.0;
    ASSERT_FALSE(wm.scan(*truth, sc, 0.0, 5.0, 5.03, p).empty());
    EXPECT_TRUE(faceAt(wm.grid(), 7.55, 5.03));
    const CellWindow w = wm.scan(*truth, sc, 30.0, 5.0, 5.03, p);  // the box at (17, 17), 17 m away
    ASSERT_FALSE(w.empty());
    EXPECT_FALSE(faceAt(wm.grid(), 7.55, 5.03));
    EXPECT_EQ(wm.sensedCells(), 0u);
    EXPECT_TRUE(occupiedAt(wm.grid(), 0.05, 5.0));  // a wall of the map, 5 m away: seen, kept
    EXPECT_EQ(wm.grid().counts().occupied, truth->counts().occupied);
}

// What the map did not show in its own cells (a true map with a wall more) is mapped too.
TEST(Sensing, ATrueMapWallTheGivenMapLacksIsMappedAndAMismatchedMapRefused)
{
    const auto given = room();
    auto truth = std::make_shared<OccupancyGrid>(*given);
    for (int r = 40; r < 60; ++r) truth->set(80, r, CellState::Occupied);  // x 8.0-8.1, y 14-16
    WorkingMap wm(std::make_shared<OccupancyGrid>(*given));
    ASSERT_FALSE(wm.scan(*truth, Scenario(), 0.0, 5.0, 15.0, RangeSensorParams()).empty());
    EXPECT_TRUE(occupiedAt(wm.grid(), 8.05, 15.0));
    OccupancyGrid other(100, 100, 0.1);
    EXPECT_THROW(wm.scan(other, Scenario(), 0.0, 5.0, 5.0, RangeSensorParams()), std::invalid_argument);
    RangeSensorParams bad;
    bad.range = 0.0;
    EXPECT_THROW(wm.scan(*truth, Scenario(), 0.0, 5.0, 5.0, bad), std::invalid_argument);
}

// Footprint clearing: a cell the vehicle's body overlaps is not marked (a box 2 cm beside the
// body shares a cell with it), and one marked before is given back when the body covers it.
TEST(Sensing, CellsTheBodyOverlapsAreKeptClear)
{
    const auto truth = room();
    Scenario sc;
    sc.obstacles.push_back(box(5.54, 5.0, 1.0, 1.0));  // x 5.04-6.04: its face in the cell 5.0-5.1
    const std::vector<std::array<double, 2>> body{{4.0, 4.8}, {5.02, 4.8}, {5.02, 5.2}, {4.0, 5.2}};
    WorkingMap without(std::make_shared<OccupancyGrid>(*truth));
    without.scan(*truth, sc, 0.0, 4.5, 5.03, RangeSensorParams());
    ASSERT_TRUE(occupiedAt(without.grid(), 5.05, 5.03));  // marked where the body is not said
    WorkingMap with(std::make_shared<OccupancyGrid>(*truth));
    with.scan(*truth, sc, 0.0, 4.5, 5.03, RangeSensorParams(), &body);
    EXPECT_FALSE(occupiedAt(with.grid(), 5.05, 5.03));
    EXPECT_FALSE(occupiedAt(with.grid(), 5.05, 4.85));
    EXPECT_TRUE(occupiedAt(with.grid(), 5.05, 5.35));  // above the body: marked
    EXPECT_GT(with.sensedCells(), 0u);
    // the cell marked by the scan without the body is cleared by one with it, in the window
    const Cell c = without.grid().worldToCell(5.05, 5.03);
    const CellWindow w = without.scan(*truth, sc, 0.2, 4.5, 5.03, RangeSensorParams(), &body);
    EXPECT_FALSE(occupiedAt(without.grid(), 5.05, 5.03));
    EXPECT_TRUE(c.col >= w.col0 && c.col <= w.col1 && c.row >= w.row0 && c.row <= w.row1);
    EXPECT_EQ(without.sensedCells(), with.sensedCells());
}
