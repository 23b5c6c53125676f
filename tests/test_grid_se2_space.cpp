#include "gridcar/spaces/GridSE2StateSpace.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"

#include <gtest/gtest.h>

#include <ompl/base/ScopedState.h>

using namespace gridcar;
namespace ob = ompl::base;

TEST(GridSE2StateSpace, BoundsAndLatticeRoundTrip)
{
    OccupancyGrid g(40, 30, 0.5);
    g.setOrigin(-5.0, 2.0);
    auto space = std::make_shared<GridSE2StateSpace>(g, 16);
    const auto &b = space->getBounds();
    EXPECT_DOUBLE_EQ(b.low[0], -5.0);
    EXPECT_DOUBLE_EQ(b.high[0], 15.0);
    EXPECT_DOUBLE_EQ(b.low[1], 2.0);
    EXPECT_DOUBLE_EQ(b.high[1], 17.0);
    ob::ScopedState<ob::SE2StateSpace> s(space);
    for (int h = 0; h < 16; ++h)
        for (int row : {0, 7, 29})
            for (int col : {0, 13, 39})
            {
                const LatticeState l{col, row, h};
                space->fromLattice(l, s.get());
                EXPECT_EQ(space->toLattice(s.get()), l);
                EXPECT_TRUE(space->satisfiesBounds(s.get()));
            }
    // heading rounding: nearest bin, half-way rounds up, negative yaw wraps
    EXPECT_EQ(space->headingBin(0.0), 0);
    EXPECT_EQ(space->headingBin(-M_PI / 16 + 1e-9), 0);
    EXPECT_EQ(space->headingBin(M_PI / 16), 1);
    EXPECT_EQ(space->headingBin(-M_PI / 2), 12);
    EXPECT_EQ(space->headingBin(M_PI), 8);
    EXPECT_EQ(space->headingBin(-M_PI), 8);
    // row 0 is the top: the highest y
    EXPECT_EQ(space->toLattice(0.0, 16.9, 0.0).row, 0);
    EXPECT_EQ(space->toLattice(0.0, 2.1, 0.0).row, 29);
    EXPECT_THROW(GridSE2StateSpace(g, 12), std::invalid_argument);
}

TEST(GridSE2StateSpace, SetupWiresValidityAndMotionChecks)
{
    CampusParams p;
    p.width = 600;
    p.height = 400;
    p.resolution = 0.5;
    auto grid = std::make_shared<const OccupancyGrid>(generateCampus(p));
    GridSetup setup = makeGridSetup(grid, VehicleParams::preset("paper-c-robot"));
    const auto si = setup.ss->getSpaceInformation();
    ob::ScopedState<ob::SE2StateSpace> s(setup.space);
    // pick a free pose and a blocked one
    bool sawValid = false, sawInvalid = false;
    for (int r = 0; r < grid->height() && !(sawValid && sawInvalid); r += 7)
        for (int c = 0; c < grid->width(); c += 7)
        {
            s->setXY(grid->cellCenterX(c), grid->cellCenterY(r));
            s->setYaw(0.0);
            const bool v = si->isValid(s.get());
            EXPECT_EQ(v, setup.checker->isValid(s->getX(), s->getY(), 0.0));
            sawValid |= v;
            sawInvalid |= !v;
        }
    EXPECT_TRUE(sawValid);
    EXPECT_TRUE(sawInvalid);
    EXPECT_NE(dynamic_cast<const FootprintMotionValidator *>(si->getMotionValidator().get()), nullptr);
    EXPECT_GT(si->getStateValidityCheckingResolution(), 0.0);
}
