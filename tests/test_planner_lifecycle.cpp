// A planner's life in an OMPL application (planners/GridPlanner.h): solve() again without
// clear() answers the problem again; a new validity checker (a changed map) or motion validator
// set on the same SpaceInformation is noticed by the next solve(), with or without setup(), and
// the old map may then be freed (run under AddressSanitizer in the test command).
#include "gridcar/path/Drivability.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>

#include <memory>

using namespace gridcar;
using namespace gridcar::test;
namespace ob = ompl::base;

namespace
{
/// Our planners: every name of the registry's gridcar part (the papers' searches included).
std::vector<NamedConfiguration> ourConfigurations()
{
    std::vector<NamedConfiguration> out;
    for (const auto &n : gridPlannerNames()) out.push_back({n, {}});
    return out;
}

/// 40 m x 30 m at 0.25 m, free; with @p wall, a wall at x = 20 m from y = 0 to y = 20 m.
std::shared_ptr<const OccupancyGrid> openMap(bool wall)
{
    auto g = std::make_shared<OccupancyGrid>(160, 120, 0.25, CellState::Free);
    if (wall)
        for (int r = 40; r < 120; ++r)
            for (int c = 79; c < 82; ++c) g->set(c, r, CellState::Occupied);
    return g;
}

/// The poses of the set-up's solution (densified along the curves of a car space).
std::vector<Pose2> solutionOf(const GridSetup &s) { return toPoses(s.ss->getSolutionPath()); }
}  // namespace

TEST(PlannerLifecycle, SolveAgainWithoutClearAnswersTheProblem)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    for (const auto &c : ourConfigurations())
    {
        SCOPED_TRACE(configurationLabel(c));
        GridSetup s = makeGridSetup(openMap(false), VehicleParams::preset("paper-c-robot"));
        s.ss->setPlanner(configurePlanner(s.ss->getSpaceInformation(), {c.first, c.second, false, false}));
        s.setStartAndGoal({5, 5, 0}, {35, 25, 0});
        ASSERT_EQ(s.ss->solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
        const double first = s.ss->getSolutionPath().length();
        // OMPL's planners answer a second solve() of the same problem; ours did "Invalid start"
        ASSERT_EQ(s.ss->getPlanner()->solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
        EXPECT_NEAR(s.ss->getProblemDefinition()->getSolutionPath()->length(), first, 1e-9);
    }
}

TEST(PlannerLifecycle, ANewMapSetOnTheSpaceInformationIsNoticed)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    const VehicleParams car = VehicleParams::preset("paper-c-robot");
    for (const auto &c : ourConfigurations())
        for (bool callSetup : {false, true})
        {
            SCOPED_TRACE(configurationLabel(c) + (callSetup ? " with setup()" : " without setup()"));
            GridSetup s = makeGridSetup(openMap(false), car);
            const auto &si = s.ss->getSpaceInformation();
            s.ss->setPlanner(configurePlanner(si, {c.first, c.second, false, false}));
            s.setStartAndGoal({5, 5, 0}, {35, 5, 0});
            ASSERT_EQ(s.ss->solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
            {
                // the application's map changes: a wall across the straight route; its checker
                // is the only owner of the new map, and the old map is gone when `s` lets go
                auto grid = openMap(true);
                auto checker = std::make_shared<FootprintChecker>(grid, std::make_shared<const DistanceField>(*grid), car);
                si->setStateValidityChecker(std::make_shared<FootprintValidityChecker>(si, checker));
                si->setMotionValidator(std::make_shared<FootprintMotionValidator>(si, checker));
                s.checker = checker;
                s.grid = grid;
                s.field.reset();
            }
            s.ss->getProblemDefinition()->clearSolutionPaths();
            if (callSetup) s.ss->setup();
            ASSERT_EQ(s.ss->solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
            const std::vector<Pose2> path = solutionOf(s);
            // the new path goes round the wall: every pose free on the new map
            for (const Pose2 &p : path)
                if (!s.checker->isValid(p))
                {
                    ADD_FAILURE() << "pose (" << p.x << ", " << p.y << ") is in the new wall";
                    break;
                }
            double top = 0;
            for (const Pose2 &p : path) top = std::max(top, p.y);
            EXPECT_GT(top, 20.0) << "the path must pass above the wall's end";
        }
}

TEST(PlannerLifecycle, AnApplicationsOwnCheckerSwappedIsNoticed)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    // plain SE(2) and the application's own validity function, swapped for one with a wall
    auto space = plainSpace(60.0);
    for (const char *name : {"corner-astar", "improved-astar", "astar-euclidean"})
    {
        SCOPED_TRACE(name);
        ompl::geometric::SimpleSetup ss(space);
        ss.setStateValidityChecker([](const ob::State *) { return true; });
        setPlainQuery(ss, 5, 30, 55, 30);
        ob::PlannerPtr planner = makePlanner(ss.getSpaceInformation(), name);
        planner->params().setParam("turning_radius", "3");
        planner->params().setParam("lattice_cell", "1");
        ss.setPlanner(planner);
        ASSERT_EQ(ss.solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
        auto wall = [](const ob::State *st) {
            const auto *s = st->as<ob::SE2StateSpace::StateType>();
            return !(std::abs(s->getX() - 30) < 1.5 && s->getY() < 45);
        };
        ss.setStateValidityChecker(wall);
        ss.getProblemDefinition()->clearSolutionPaths();
        ASSERT_EQ(ss.solve(10.0), ob::PlannerStatus::EXACT_SOLUTION);
        const auto &path = ss.getSolutionPath();
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
            ASSERT_TRUE(wall(path.getState(i))) << "state " << i << " is in the new wall";
    }
}
