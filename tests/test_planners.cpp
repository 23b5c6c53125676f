#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/GridAStar.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"
#include "TestData.h"

#include <gtest/gtest.h>

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <chrono>
#include <filesystem>
#include <queue>
#include <random>

using namespace gridcar;
namespace ob = ompl::base;
namespace og = ompl::geometric;
using namespace gridcar::test;

namespace
{
class Conformance : public ::testing::TestWithParam<std::string>
{
protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};
}  // namespace

TEST_P(Conformance, SolveClearSolveGivesTheSameAnswer)
{
    GridSetup s = testSetup();
    s.setStartAndGoal(cellPose(*s.grid, 5, 30), cellPose(*s.grid, 50, 30));
    s.ss->setPlanner(makePlanner(s.ss->getSpaceInformation(), GetParam()));
    s.ss->setup();
    // optimizing sampling planners use their whole time: give them 1 s
    const double limit = isGrid(GetParam()) ? 5.0 : 1.0;
    ASSERT_EQ(s.ss->solve(limit), ob::PlannerStatus::EXACT_SOLUTION);
    const og::PathGeometric p1 = s.ss->getSolutionPath();
    EXPECT_TRUE(p1.check());
    s.ss->clear();
    ASSERT_EQ(s.ss->solve(limit), ob::PlannerStatus::EXACT_SOLUTION);
    const og::PathGeometric p2 = s.ss->getSolutionPath();
    if (isGrid(GetParam()))
    {
        ASSERT_EQ(p1.getStateCount(), p2.getStateCount());
        for (std::size_t i = 0; i < p1.getStateCount(); ++i)
            EXPECT_TRUE(s.space->equalStates(p1.getState(i), p2.getState(i)));
    }
}

TEST_P(Conformance, InvalidStartAndGoal)
{
    // Grid planners report INVALID_START / INVALID_GOAL. OMPL's sampling planners do not all
    // check the goal (RRT returns an approximate solution, RRTConnect and BIT* time out), so
    // for them the fixture asserts only that no exact solution comes back; gridcar's own entry
    // points (CLI, benchmark) check start and goal before calling any planner.
    const bool grid = isGrid(GetParam());
    GridSetup s = testSetup();
    s.ss->setPlanner(makePlanner(s.ss->getSpaceInformation(), GetParam()));
    const double limit = grid ? 1.0 : 0.3;
    // start on the wall
    s.setStartAndGoal(cellPose(*s.grid, 30, 5), cellPose(*s.grid, 50, 30));
    ob::PlannerStatus st = s.ss->solve(limit);
    if (grid) EXPECT_EQ(st, ob::PlannerStatus::INVALID_START);
    else EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION);
    s.ss->clear();
    // goal off the map
    s.setStartAndGoal(cellPose(*s.grid, 5, 30), Pose2{-10.0, 3.0, 0.0});
    st = s.ss->solve(limit);
    if (grid) EXPECT_EQ(st, ob::PlannerStatus::INVALID_GOAL);
    else EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION);
    s.ss->clear();
    // goal in collision
    s.setStartAndGoal(cellPose(*s.grid, 5, 30), cellPose(*s.grid, 30, 0));
    st = s.ss->solve(limit);
    if (grid) EXPECT_EQ(st, ob::PlannerStatus::INVALID_GOAL);
    else EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION);
}

TEST_P(Conformance, UnreachableGoalIsNotAnExactSolution)
{
    GridSetup s = testSetup();
    s.ss->setPlanner(makePlanner(s.ss->getSpaceInformation(), GetParam()));
    s.setStartAndGoal(cellPose(*s.grid, 5, 30), cellPose(*s.grid, 50, 6));  // inside the closed room
    // the grid planners stop when the reachable states are exhausted (the car lattice's 38 k
    // states take 0.07 s, 0.3 s under the sanitizers, but once 10 s in a CI sanitizer run that
    // shared the machine with the command-line tests): a limit they do not reach
    const ob::PlannerStatus st = s.ss->solve(isGrid(GetParam()) ? 60.0 : 0.5);
    EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION);
    if (isGrid(GetParam())) EXPECT_EQ(st, ob::PlannerStatus::APPROXIMATE_SOLUTION);
}

TEST_P(Conformance, TimeLimitIsHonoured)
{
    // the paper-sized campus with the car: a search across it cannot finish in 50 ms
    static GridSetup s = [] {
        auto g = std::make_shared<const OccupancyGrid>(generateCampus());
        return makeGridSetup(g, VehicleParams::preset("paper-i"));
    }();
    s.ss->clear();
    s.ss->setPlanner(makePlanner(s.ss->getSpaceInformation(), GetParam()));
    // free poses near opposite corners, found by scanning
    auto freeNear = [&](int c0, int r0, int dc, int dr) {
        for (int k = 0; k < 2000; ++k)
        {
            const int c = c0 + dc * k, r = r0 + dr * k;
            for (int a = 0; a < 8; ++a)
                if (s.checker->isValid(s.grid->cellCenterX(c), s.grid->cellCenterY(r), a * M_PI / 4))
                    return cellPose(*s.grid, c, r, a * M_PI / 4);
        }
        return Pose2{};
    };
    s.setStartAndGoal(freeNear(0, s.grid->height() - 1, 1, -1), freeNear(s.grid->width() - 1, 0, -1, 1));
    s.ss->setup();
    const double limit = 0.05;
    const auto t0 = std::chrono::steady_clock::now();
    const ob::PlannerStatus st = s.ss->solve(limit);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: solve(%.2f) returned after %.3f s (%s)\n", GetParam().c_str(), limit, took, st.asString().c_str());
    // 0.3 s of slack: on a loaded 2-core machine OMPL's LazyPRM* once returned 0.15 s late (it
    // returns at 0.052 s alone); a planner that ignored the limit would search the campus on
    EXPECT_LT(took, limit + 0.3) << GetParam() << " status " << st.asString();
    EXPECT_NE(st, ob::PlannerStatus::EXACT_SOLUTION) << "the search should not finish in 50 ms";
}

INSTANTIATE_TEST_SUITE_P(AllPlanners, Conformance, ::testing::ValuesIn(plannerNames()),
                         [](const ::testing::TestParamInfo<std::string> &i) {
                             std::string n = i.param;
                             for (char &ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

TEST(Planners, FactoryRejectsUnknownNames)
{
    GridSetup s = testSetup();
    try
    {
        makePlanner(s.ss->getSpaceInformation(), "rrt-sharp");
        FAIL();
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("corner-astar"), std::string::npos);
    }
}

TEST(Planners, GridPlannersFillSpecsParamsAndPlannerData)
{
    GridSetup s = testSetup();
    auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
    EXPECT_TRUE(p->getSpecs().approximateSolutions);
    EXPECT_TRUE(p->params().hasParam("corner_weight_90"));
    EXPECT_TRUE(p->params().hasParam("weights"));
    EXPECT_TRUE(p->params().setParam("corner_weight_90", "9.5"));
    EXPECT_EQ(p->params().getParam("corner_weight_90")->getValue(), "9.5");
    // a rejected value: the setter throws std::invalid_argument, OMPL's setParam() returns false
    EXPECT_FALSE(p->params().setParam("corner_weight_90", "-1"));
    EXPECT_FALSE(p->params().setParam("weights", "bogus"));
    EXPECT_EQ(p->params().getParam("corner_weight_90")->getValue(), "9.5");
    EXPECT_EQ(p->getPlannerProgressProperties().count("expanded nodes INTEGER"), 1u);
    s.ss->setPlanner(p);
    s.setStartAndGoal(cellPose(*s.grid, 5, 30), cellPose(*s.grid, 50, 30));
    ASSERT_EQ(s.ss->solve(2.0), ob::PlannerStatus::EXACT_SOLUTION);
    ob::PlannerData data(s.ss->getSpaceInformation());
    p->getPlannerData(data);
    auto *gp = dynamic_cast<GridPlanner *>(p.get());
    ASSERT_NE(gp, nullptr);
    EXPECT_GT(data.numVertices(), 10u);
    EXPECT_GT(data.numEdges(), 10u);
    EXPECT_EQ(std::stoull(p->getPlannerProgressProperties().at("expanded nodes INTEGER")()), gp->expandedNodes());
}

namespace
{
/// A goal region: a disc of radius r around (x, y).
class DiscGoal : public ob::GoalRegion
{
public:
    DiscGoal(const ob::SpaceInformationPtr &si, double x, double y, double r) : ob::GoalRegion(si), x_(x), y_(y)
    {
        setThreshold(r);
    }
    double distanceGoal(const ob::State *st) const override
    {
        const auto *s = st->as<ob::SE2StateSpace::StateType>();
        return std::max(0.0, std::hypot(s->getX() - x_, s->getY() - y_));
    }

private:
    double x_, y_;
};
}  // namespace

TEST(Planners, GridPlannersWorkWithAnyGoalRegion)
{
    for (const auto &name : gridPlannerNames())
    {
        GridSetup s = testSetup();
        s.ss->setPlanner(makePlanner(s.ss->getSpaceInformation(), name));
        ob::ScopedState<ob::SE2StateSpace> start(s.space);
        start->setXY(s.grid->cellCenterX(5), s.grid->cellCenterY(30));
        start->setYaw(0.0);
        s.ss->setStartState(start);
        s.ss->setGoal(std::make_shared<DiscGoal>(s.ss->getSpaceInformation(), s.grid->cellCenterX(50),
                                                 s.grid->cellCenterY(30), 2.0));
        ASSERT_EQ(s.ss->solve(2.0), ob::PlannerStatus::EXACT_SOLUTION) << name;
        const auto &path = s.ss->getSolutionPath();
        double d = 0;
        EXPECT_TRUE(s.ss->getGoal()->isSatisfied(path.getState(path.getStateCount() - 1), &d)) << name;
    }
}



// ---------------------------------------------------------------- NAME+smooth

TEST(Planners, SmoothSuffixWrapsAnyPlannerInPaperIsPostProcessing)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto g = std::make_shared<OccupancyGrid>(80, 60, 0.25);
    for (int r = 0; r < 40; ++r) g->set(40, r, CellState::Occupied);  // a wall to go round
    GridSetup s = makeGridSetup(g, VehicleParams::preset("paper-c-robot"));
    for (const std::string name : {"astar-euclidean+smooth", "rrtconnect+smooth"})
    {
        auto p = makePlanner(s.ss->getSpaceInformation(), name);
        auto *sp = dynamic_cast<SmoothedPlanner *>(p.get());
        ASSERT_NE(sp, nullptr) << name;
        EXPECT_EQ(p->getName(), name);
        s.ss->clear();
        s.ss->setPlanner(p);
        s.setStartAndGoal(cellPose(*g, 10, 10), cellPose(*g, 70, 10));
        // exact when the smoothed path is drivable, else approximate with the reason
        const ob::PlannerStatus st = s.ss->solve(5.0);
        if (st == ob::PlannerStatus::APPROXIMATE_SOLUTION)
        {
            // a smoothed path that clips an obstacle or turns too tight: said, not returned as exact
            EXPECT_NE(sp->lastSmoothing().notDrivable, "") << name << ": approximate without the reason";
            continue;
        }
        ASSERT_EQ(st, ob::PlannerStatus::EXACT_SOLUTION) << name;
        const auto &path = s.ss->getSolutionPath();
        ASSERT_EQ(path.getStateCount(), sp->lastSmoothing().path.size()) << name;
        EXPECT_TRUE(path.check()) << name;
        for (std::size_t i = 1; i < sp->lastSmoothing().path.size(); ++i)
            EXPECT_TRUE(s.checker->isMotionValid(sp->lastSmoothing().path[i - 1], sp->lastSmoothing().path[i]));
        if (sp->lastSmoothing().adjustFailures + sp->lastSmoothing().bezierFallbacks == 0)
            EXPECT_LE(sp->lastSmoothing().maxCurvature, s.checker->vehicle().maxCurvature() * 1.001) << name;
    }
    // parameters are the inner planner's
    auto c = makePlanner(s.ss->getSpaceInformation(), "corner-astar+smooth");
    EXPECT_TRUE(c->params().setParam("corner_weight_90", "3.5"));
    EXPECT_EQ(dynamic_cast<SmoothedPlanner *>(c.get())->inner()->params().getParam("corner_weight_90")->getValue(), "3.5");
    EXPECT_THROW(makePlanner(s.ss->getSpaceInformation(), "nothing+smooth"), std::invalid_argument);
}


TEST(Planners, BitStarHasNoProgressPropertyThatRacesItsPruning)
{
    // ompl/ompl issue #779: OMPL 1.5.2's Benchmark reads these from another thread during
    // solve() and BIT* crashes; the factory's BIT* leaves them out and keeps the rest
    GridSetup s = testSetup();
    const auto p = makePlanner(s.ss->getSpaceInformation(), "bitstar");
    const auto &props = p->getPlannerProgressProperties();
    EXPECT_EQ(props.count("current free states INTEGER"), 0u);
    EXPECT_EQ(props.count("current graph vertices INTEGER"), 0u);
    EXPECT_GT(props.count("best cost DOUBLE") + props.count("best cost REAL"), 0u);
}
