// gridcar's planners plugged into plain OMPL set-ups (no gridcar type but the planner factory):
// OMPL's SE2StateSpace, ReedsSheppStateSpace and DubinsStateSpace with an application's own
// validity checker. Each path is checked independently here: every pose free by the
// application's checker, poses at most 0.1 m apart, turns no tighter than the space's radius,
// the exact goal reached.
#include <gtest/gtest.h>

#include <gridcar/planners/PlannerFactory.h>

#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/SimpleSetup.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace
{
struct Disc
{
    double x, y, r;
};
// a wall across the middle with one gap, and round obstacles: the car must turn through the gap
const std::vector<Disc> kObstacles{{30, 8, 7}, {30, 22, 3}, {30, 52, 14}, {12, 40, 5}, {48, 20, 6}};

/// The application's check: three 1 m discs cover a 4.5 m x 1.8 m car (rear axle 1 m from the back).
bool carIsFree(const ompl::base::State *state)
{
    const auto *s = state->as<ompl::base::SE2StateSpace::StateType>();
    for (double along : {-0.25, 1.25, 2.75})
    {
        const double x = s->getX() + along * std::cos(s->getYaw()), y = s->getY() + along * std::sin(s->getYaw());
        for (const Disc &o : kObstacles)
            if (std::hypot(x - o.x, y - o.y) < o.r + 1.0) return false;
    }
    return true;
}

struct Outcome
{
    ompl::base::PlannerStatus status;
    std::vector<std::array<double, 3>> poses;
};

Outcome solveOn(const ompl::base::StateSpacePtr &space, const std::string &planner,
                const std::vector<std::pair<std::string, std::string>> &params = {})
{
    ompl::base::RealVectorBounds bounds(2);
    bounds.setLow(0.0);
    bounds.setHigh(60.0);
    space->as<ompl::base::SE2StateSpace>()->setBounds(bounds);
    ompl::geometric::SimpleSetup ss(space);
    ss.setStateValidityChecker(carIsFree);
    ompl::base::ScopedState<ompl::base::SE2StateSpace> start(space), goal(space);
    start->setXY(8, 8);
    start->setYaw(0);
    goal->setXY(52, 50);
    goal->setYaw(M_PI / 2);
    ss.setStartAndGoalStates(start, goal);
    auto p = gridcar::makePlanner(ss.getSpaceInformation(), planner);
    p->params().setParam("match_goal_heading", "1");
    for (const auto &kv : params) EXPECT_TRUE(p->params().setParam(kv.first, kv.second)) << kv.first;
    ss.setPlanner(p);
    Outcome out{ss.solve(20.0), {}};
    if (ss.haveSolutionPath())
        for (auto *st : ss.getSolutionPath().getStates())
        {
            const auto *s = st->as<ompl::base::SE2StateSpace::StateType>();
            out.poses.push_back({s->getX(), s->getY(), s->getYaw()});
        }
    return out;
}

/// Independent check of a car-lattice path: free at every pose (the application's own test),
/// dense, curvature within 1 / R, exact goal pose.
void expectDrivable(const Outcome &o, double radius)
{
    ASSERT_EQ(o.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
    ASSERT_GE(o.poses.size(), 2u);
    ompl::base::SE2StateSpace se2;
    auto *st = se2.allocState()->as<ompl::base::SE2StateSpace::StateType>();
    double worstK = 0;
    for (std::size_t i = 0; i < o.poses.size(); ++i)
    {
        st->setXY(o.poses[i][0], o.poses[i][1]);
        st->setYaw(o.poses[i][2]);
        EXPECT_TRUE(carIsFree(st)) << "pose " << i;
        if (i == 0) continue;
        const double d = std::hypot(o.poses[i][0] - o.poses[i - 1][0], o.poses[i][1] - o.poses[i - 1][1]);
        EXPECT_LE(d, 0.1 + 1e-9) << "poses " << i - 1 << " and " << i << " are " << d << " m apart";
        const double turn = std::abs(std::remainder(o.poses[i][2] - o.poses[i - 1][2], 2 * M_PI));
        if (d > 1e-9) worstK = std::max(worstK, turn / d);
    }
    se2.freeState(st);
    EXPECT_LE(worstK, 1.0 / radius + 1e-6);
    EXPECT_NEAR(o.poses.back()[0], 52, 1e-6);
    EXPECT_NEAR(o.poses.back()[1], 50, 1e-6);
    EXPECT_NEAR(std::remainder(o.poses.back()[2] - M_PI / 2, 2 * M_PI), 0.0, 1e-6);
}
}  // namespace

TEST(PlainOmpl, CarLatticePlannersOnReedsSheppAndDubinsSpaces)
{
    for (const std::string planner : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(planner);
        expectDrivable(solveOn(std::make_shared<ompl::base::ReedsSheppStateSpace>(5.0), planner), 5.0);
        expectDrivable(solveOn(std::make_shared<ompl::base::DubinsStateSpace>(4.0), planner), 4.0);
    }
}

TEST(PlainOmpl, CarLatticePlannersOnPlainSE2TakeTheirRadiusFromAParameter)
{
    for (const std::string planner : {"corner-astar", "improved-astar"})
    {
        SCOPED_TRACE(planner);
        expectDrivable(solveOn(std::make_shared<ompl::base::SE2StateSpace>(), planner, {{"turning_radius", "6"}}), 6.0);
    }
}

TEST(PlainOmpl, GridLatticePlannersOnPlainSE2)
{
    // the papers' grid searches: cells of lattice_cell over the space's bounds, moves checked
    // by the application's checker (SpaceInformation::checkMotion)
    for (const auto &[planner, params] :
         std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>>{
             {"astar-euclidean", {{"lattice_cell", "0.5"}}},
             {"dijkstra", {{"lattice_cell", "1"}}},
             {"corner-astar-grid", {{"lattice_cell", "0.5"}}},
             {"improved-astar-grid", {{"lattice_cell", "0.5"}}}})
    {
        SCOPED_TRACE(planner);
        const Outcome o = solveOn(std::make_shared<ompl::base::SE2StateSpace>(), planner, params);
        ASSERT_EQ(o.status, ompl::base::PlannerStatus::EXACT_SOLUTION);
        ompl::base::SE2StateSpace se2;
        auto *st = se2.allocState()->as<ompl::base::SE2StateSpace::StateType>();
        for (const auto &p : o.poses)
        {
            st->setXY(p[0], p[1]);
            st->setYaw(p[2]);
            EXPECT_TRUE(carIsFree(st));
        }
        se2.freeState(st);
        EXPECT_NEAR(o.poses.back()[0], 52, 1e-6);
        EXPECT_NEAR(o.poses.back()[1], 50, 1e-6);
    }
}

TEST(PlainOmpl, MisuseIsAClearError)
{
    // a space that is not SE(2)-derived, and a lattice that would need too many cells
    auto rv = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    rv->setBounds(0, 1);
    auto si = std::make_shared<ompl::base::SpaceInformation>(rv);
    si->setStateValidityChecker([](const ompl::base::State *) { return true; });
    si->setup();
    auto p = gridcar::makePlanner(si, "corner-astar");
    try
    {
        p->setup();
        FAIL() << "setup() accepted a RealVectorStateSpace";
    }
    catch (const ompl::Exception &e)
    {
        EXPECT_NE(std::string(e.what()).find("SE2StateSpace"), std::string::npos) << e.what();
    }
    const Outcome tiny = [] {
        try
        {
            return solveOn(std::make_shared<ompl::base::SE2StateSpace>(), "dijkstra", {{"lattice_cell", "0.001"}});
        }
        catch (const ompl::Exception &e)
        {
            EXPECT_NE(std::string(e.what()).find("raise lattice_cell"), std::string::npos) << e.what();
            return Outcome{ompl::base::PlannerStatus::CRASH, {}};
        }
    }();
    EXPECT_EQ(tiny.status, ompl::base::PlannerStatus::CRASH);
}
