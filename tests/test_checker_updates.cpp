// Incremental map updates: after cells change, DistanceField::update() and
// FootprintChecker::cellsChanged() leave a checker that answers as one made anew on the
// changed map, its exact check's tiles made before the change included.
#include "gridcar/collision/FootprintChecker.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

using namespace gridcar;

namespace
{
void addBox(OccupancyGrid &g, const CellWindow &w, CellState s)
{
    for (int r = w.row0; r <= w.row1; ++r)
        for (int c = w.col0; c <= w.col1; ++c) g.set(c, r, s);
}
}  // namespace

TEST(CheckerUpdates, AnUpdatedCheckerAnswersAsANewOne)
{
    for (const auto &[vehicle, res] : {std::pair<const char *, double>{"paper-c-robot", 0.05}, {"paper-i", 0.15}})
    {
        SCOPED_TRACE(vehicle);
        auto grid = std::make_shared<OccupancyGrid>(300, 220, res);
        grid->setOrigin(-3.0, 2.0);
        std::mt19937 rng(11);
        std::uniform_int_distribution<int> cw(0, 299), ch(0, 219), sz(1, 30);
        const auto randomWindow = [&] {
            const int c = cw(rng), r = ch(rng);
            return CellWindow{c, r, std::min(299, c + sz(rng)), std::min(219, r + sz(rng))};
        };
        for (int k = 0; k < 40; ++k) addBox(*grid, randomWindow(), CellState::Occupied);
        auto field = std::make_shared<DistanceField>(*grid);
        field->prepareUpdates(*grid);
        FootprintChecker fc(grid, field, VehicleParams::preset(vehicle));
        std::uniform_real_distribution<double> ux(grid->originX(), grid->originX() + grid->sizeX()),
            uy(grid->originY(), grid->originY() + grid->sizeY()), uyaw(-M_PI, M_PI);
        for (int i = 0; i < 3000; ++i) fc.isValidExact(ux(rng), uy(rng), uyaw(rng));  // tiles made before the edits
        for (int edit = 0; edit < 8; ++edit)
        {
            const CellWindow w = randomWindow();
            addBox(*grid, w, edit % 2 ? CellState::Free : CellState::Occupied);
            fc.cellsChanged(w, field->update(*grid, w));
            const auto fresh = std::make_shared<DistanceField>(*grid);
            const FootprintChecker anew(std::make_shared<OccupancyGrid>(*grid), fresh, VehicleParams::preset(vehicle));
            int blocked = 0;
            for (int i = 0; i < 1500; ++i)
            {
                // half the poses within 60 cells of the edit
                const bool near = i % 2 == 0;
                std::uniform_real_distribution<double> around(-60 * res, 60 * res);
                const double x = near ? grid->cellCenterX(w.col0) + around(rng) : ux(rng);
                const double y = near ? grid->cellCenterY(w.row0) + around(rng) : uy(rng);
                const double yaw = uyaw(rng);
                const bool valid = fc.isValid(x, y, yaw);
                ASSERT_EQ(valid, anew.isValid(x, y, yaw)) << "edit " << edit << " pose " << x << "," << y << "," << yaw;
                ASSERT_EQ(fc.isValidExact(x, y, yaw), anew.isValidExact(x, y, yaw)) << "edit " << edit;
                ASSERT_EQ(fc.provenBlocked({x, y, yaw}), anew.provenBlocked({x, y, yaw})) << "edit " << edit;
                ASSERT_EQ(fc.discsClearAtEveryYawAt(x, y), anew.discsClearAtEveryYawAt(x, y)) << "edit " << edit;
                blocked += valid ? 0 : 1;
            }
            EXPECT_GT(blocked, 50);  // both answers exercised
            EXPECT_LT(blocked, 1450);
        }
    }
}

TEST(CheckerUpdates, AnotherCheckerCatchesUpFromTheChangesKept)
{
    // a second checker on the same grid and field (a body grown by 0.3 m, as the safety
    // margin's) left behind by 5 edits, brought up to date from changesSince()
    auto grid = std::make_shared<OccupancyGrid>(300, 220, 0.05);
    auto field = std::make_shared<DistanceField>(*grid);
    field->prepareUpdates(*grid);
    VehicleParams grownBody = VehicleParams::preset("paper-c-robot");
    grownBody.length += 0.6;
    grownBody.width += 0.6;
    FootprintChecker fc(grid, field, VehicleParams::preset("paper-c-robot"));
    FootprintChecker grown(grid, field, grownBody);
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cw(0, 289), ch(0, 209);
    for (int edit = 0; edit < 5; ++edit)
    {
        const int c = cw(rng), r = ch(rng);
        const CellWindow w{c, r, c + 10, r + 10};
        addBox(*grid, w, CellState::Occupied);
        fc.cellsChanged(w, field->update(*grid, w));
    }
    const auto changes = fc.changesSince(0);
    ASSERT_TRUE(changes.has_value());
    EXPECT_EQ(changes->size(), 5u);
    EXPECT_EQ(fc.changesSince(3)->size(), 2u);
    EXPECT_TRUE(fc.changesSince(5)->empty());
    EXPECT_FALSE(fc.changesSince(6).has_value());  // a version it never had
    for (const auto &[cells, moved] : *changes) grown.cellsChanged(cells, moved);
    const FootprintChecker anew(std::make_shared<OccupancyGrid>(*grid), std::make_shared<DistanceField>(*grid),
                                grownBody);
    std::uniform_real_distribution<double> ux(0.0, grid->sizeX()), uy(0.0, grid->sizeY()), uyaw(-M_PI, M_PI);
    int blocked = 0;
    for (int i = 0; i < 3000; ++i)
    {
        const double x = ux(rng), y = uy(rng), yaw = uyaw(rng);
        const bool valid = grown.isValid(x, y, yaw);
        ASSERT_EQ(valid, anew.isValid(x, y, yaw)) << x << "," << y << "," << yaw;
        ASSERT_EQ(grown.discsClearAtEveryYawAt(x, y), anew.discsClearAtEveryYawAt(x, y));
        blocked += valid ? 0 : 1;
    }
    EXPECT_GT(blocked, 50);
    // only the last 64 changes are kept: older versions cannot be caught up from
    for (int edit = 0; edit < 70; ++edit) fc.cellsChanged({0, 0, 0, 0}, {0, 0, 0, 0});
    EXPECT_FALSE(fc.changesSince(0).has_value());
    EXPECT_EQ(fc.changesSince(fc.mapVersion() - 64)->size(), 64u);
}
