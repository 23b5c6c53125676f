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

// README-PLUGIN-BEGIN
#include <gridcar/planners/PlannerFactory.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>

// the application's own validity check: three 1 m discs cover its car; two round obstacles
bool carIsFree(const ompl::base::State *state)
{
    const auto *s = state->as<ompl::base::SE2StateSpace::StateType>();
    for (double along : {-0.25, 1.25, 2.75})
    {
        const double x = s->getX() + along * std::cos(s->getYaw()), y = s->getY() + along * std::sin(s->getYaw());
        if (std::hypot(x - 25, y - 20) < 9.0 || std::hypot(x - 45, y - 45) < 8.0) return false;
    }
    return true;
}

bool planWithCornerAStar()
{
    auto space = std::make_shared<ompl::base::ReedsSheppStateSpace>(5.0);  // 5 m turning radius
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(0.0);
    bounds.setHigh(60.0);
    space->setBounds(bounds);
    ompl::geometric::SimpleSetup ss(space);
    ss.setStateValidityChecker(carIsFree);
    ompl::base::ScopedState<ompl::base::SE2StateSpace> start(space), goal(space);
    start->setXY(5, 5);
    start->setYaw(0);
    goal->setXY(55, 30);
    goal->setYaw(M_PI / 2);
    ss.setStartAndGoalStates(start, goal);
    // gridcar's planner on the application's space and checker: a car lattice with the
    // space's turning radius, every pose checked by carIsFree
    ompl::base::PlannerPtr planner = gridcar::makePlanner(ss.getSpaceInformation(), "corner-astar");
    planner->params().setParam("match_goal_heading", "1");
    ss.setPlanner(planner);
    return ss.solve(5.0) == ompl::base::PlannerStatus::EXACT_SOLUTION;
}
// README-PLUGIN-END

TEST(ReadmeExample, PlugsCornerAStarIntoAPlainOmplSetup) { EXPECT_TRUE(planWithCornerAStar()); }
