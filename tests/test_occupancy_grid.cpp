#include "gridcar/map/OccupancyGrid.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

using namespace gridcar;

TEST(OccupancyGrid, WorldCellRoundTripFollowsRosConvention)
{
    OccupancyGrid g(10, 5, 0.5);
    g.setOrigin(-1.0, 2.0, 0.0);
    // lower-left cell (col 0, row 4) has its centre at origin + half a cell
    EXPECT_DOUBLE_EQ(g.cellCenterX(0), -0.75);
    EXPECT_DOUBLE_EQ(g.cellCenterY(4), 2.25);
    // top row is row 0, at the highest y
    EXPECT_DOUBLE_EQ(g.cellCenterY(0), 2.0 + 4.5 * 0.5);
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 10; ++c)
        {
            const Cell cell = g.worldToCell(g.cellCenterX(c), g.cellCenterY(r));
            EXPECT_EQ(cell.col, c);
            EXPECT_EQ(cell.row, r);
        }
    EXPECT_FALSE(g.inBounds(g.worldToCell(-1.01, 2.1).col, g.worldToCell(-1.01, 2.1).row));
    const Cell nanCell = g.worldToCell(std::nan(""), 0.0);
    EXPECT_FALSE(g.inBounds(nanCell.col, nanCell.row));
}

TEST(OccupancyGrid, UnknownIsBlockedUnlessSaidOtherwise)
{
    OccupancyGrid g(3, 1, 1.0);
    g.set(0, 0, CellState::Free);
    g.set(1, 0, CellState::Unknown);
    g.set(2, 0, CellState::Occupied);
    EXPECT_FALSE(g.isBlocked(0, 0));
    EXPECT_TRUE(g.isBlocked(1, 0));
    EXPECT_TRUE(g.isBlocked(2, 0));
    EXPECT_TRUE(g.isBlocked(-1, 0));
    EXPECT_TRUE(g.isBlocked(3, 0));
    g.setUnknownIsFree(true);
    EXPECT_FALSE(g.isBlocked(1, 0));
    const auto c = g.counts();
    EXPECT_EQ(c.free, 1u);
    EXPECT_EQ(c.unknown, 1u);
    EXPECT_EQ(c.occupied, 1u);
}

TEST(OccupancyGrid, RejectsBadSizes)
{
    EXPECT_THROW(OccupancyGrid(0, 5, 1.0), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(5, -1, 1.0), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(1000000000, 1000000000, 1.0), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(5, 5, 0.0), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(5, 5, -0.1), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(5, 5, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    OccupancyGrid g(2, 2, 1.0);
    EXPECT_THROW(g.setOrigin(std::nan(""), 0, 0), std::invalid_argument);
}

TEST(OccupancyGrid, RejectsAbsurdResolutionsOriginsAndResampling)
{
    EXPECT_THROW(OccupancyGrid(10, 10, 1e155), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(10, 10, 1e-9), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(20000, 1, 1000.0), std::invalid_argument);  // 20 000 km wide
    OccupancyGrid g(10, 10, 0.5);
    EXPECT_THROW(g.setOrigin(1e155, 0, 0), std::invalid_argument);
    EXPECT_NO_THROW(g.setOrigin(-1e6, 1e6, 0));
    // a cell size so small the sizes would overflow an int (undefined behaviour before)
    EXPECT_THROW(g.resampled(1e-300), std::invalid_argument);
    EXPECT_THROW(g.resampled(1e-4), std::invalid_argument) << "50 000 x 50 000 cells is over the limit";
    EXPECT_EQ(g.resampled(1.0).width(), 5);
}

TEST(OccupancyGrid, ResampleIsConservative)
{
    OccupancyGrid g(6, 6, 0.1);
    g.set(5, 5, CellState::Occupied);  // bottom-right cell
    g.set(0, 0, CellState::Unknown);   // top-left cell
    const OccupancyGrid r = g.resampled(0.3);
    ASSERT_EQ(r.width(), 2);
    ASSERT_EQ(r.height(), 2);
    EXPECT_EQ(r.at(1, 1), CellState::Occupied);
    EXPECT_EQ(r.at(0, 0), CellState::Unknown);
    EXPECT_EQ(r.at(1, 0), CellState::Free);
    EXPECT_EQ(r.at(0, 1), CellState::Free);
    EXPECT_DOUBLE_EQ(r.resolution(), 0.3);
}

TEST(OccupancyGrid, CropKeepsWorldCoordinates)
{
    OccupancyGrid g(20, 10, 0.5);
    g.setOrigin(-3.0, 2.0);
    g.set(7, 4, CellState::Occupied);
    const OccupancyGrid c = g.cropped(5, 3, 6, 4);
    EXPECT_EQ(c.width(), 6);
    EXPECT_EQ(c.height(), 4);
    // the same world point is the occupied cell in both
    const double x = g.cellCenterX(7), y = g.cellCenterY(4);
    const Cell in = c.worldToCell(x, y);
    EXPECT_EQ(in.col, 2);
    EXPECT_EQ(in.row, 1);
    EXPECT_TRUE(c.isBlocked(in.col, in.row));
    EXPECT_NEAR(c.cellCenterX(0), g.cellCenterX(5), 1e-12);
    EXPECT_NEAR(c.cellCenterY(0), g.cellCenterY(3), 1e-12);
    EXPECT_EQ(g.cropped(18, 8, 10, 10).width(), 2);  // clipped
    EXPECT_THROW(g.cropped(30, 0, 5, 5), std::invalid_argument);
}

TEST(OccupancyGrid, SameFrameComparesSizeResolutionAndOrigin)
{
    OccupancyGrid a(20, 10, 0.05, CellState::Free);
    a.setOrigin(-1.0, 2.0, 0.0);
    OccupancyGrid b = a;
    b.set(3, 4, CellState::Occupied);  // the cells may differ
    EXPECT_TRUE(a.sameFrame(b));
    OccupancyGrid wider(21, 10, 0.05, CellState::Free), finer(20, 10, 0.025, CellState::Free);
    wider.setOrigin(-1.0, 2.0, 0.0);
    finer.setOrigin(-1.0, 2.0, 0.0);
    EXPECT_FALSE(a.sameFrame(wider));
    EXPECT_FALSE(a.sameFrame(finer));
    for (const auto &o : {std::array<double, 3>{-1.05, 2.0, 0.0}, std::array<double, 3>{-1.0, 2.05, 0.0},
                          std::array<double, 3>{-1.0, 2.0, 0.1}})
    {
        OccupancyGrid moved = a;
        moved.setOrigin(o[0], o[1], o[2]);
        EXPECT_FALSE(a.sameFrame(moved)) << o[0] << ", " << o[1] << ", " << o[2];
    }
}
