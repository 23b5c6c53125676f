// The README's "Use from an OMPL application" example, compiled and run as a test.
// tests/readme_sync.cmake checks that README.md shows exactly the lines between the markers.
#include <gtest/gtest.h>

// README-EXAMPLE-BEGIN
#include <gridcar/map/CampusGenerator.h>
#include <gridcar/spaces/Setup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

bool planOnCampus()
{
    gridcar::CampusParams params;  // a small campus: 300 m x 200 m at 0.5 m/cell
    params.width = 600;
    params.height = 400;
    params.resolution = 0.5;
    auto grid = std::make_shared<const gridcar::OccupancyGrid>(gridcar::generateCampus(params));

    // distance field + FCL footprint checker + grid SE(2) space + SimpleSetup in one call
    gridcar::GridSetup setup = gridcar::makeGridSetup(grid, gridcar::VehicleParams::preset("paper-c-robot"));

    // any free start / goal: here, the free cells nearest the map's lower-left and upper-right
    gridcar::Pose2 start{}, goal{};
    bool haveStart = false;
    for (int r = grid->height() - 1; r >= 0; --r)
        for (int c = 0; c < grid->width(); ++c)
        {
            const double x = grid->cellCenterX(c), y = grid->cellCenterY(r);
            if (!setup.checker->isValid(x, y, 0.0) || setup.field->cellDistance(c, r) < 1.0) continue;
            if (!haveStart) { start = {x, y, 0.0}; haveStart = true; }
            goal = {x, y, 0.0};
        }
    setup.setStartAndGoal(start, goal);
    setup.ss->setPlanner(std::make_shared<ompl::geometric::RRTConnect>(setup.ss->getSpaceInformation()));
    return setup.ss->solve(10.0) == ompl::base::PlannerStatus::EXACT_SOLUTION;
}
// README-EXAMPLE-END

TEST(ReadmeExample, PlansOnTheCampus) { EXPECT_TRUE(planOnCampus()); }
