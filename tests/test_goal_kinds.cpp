// Every registered planner against every kind of OMPL goal, on maps whose origin is not zero
// and not on the cell lattice, at two resolutions: the same scene moved by its origin gives the
// same answer moved (status for every planner; for gridcar's deterministic planners the same
// path to 1e-6), an exact answer ends in the goal, and an approximate one of gridcar's ends at
// the explored state nearest the goal. GRIDCAR_GOAL_KINDS_CELLS=0.5 runs one cell size only.
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"

#include "gridcar/planners/GridPlanner.h"

#include <gtest/gtest.h>

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gridcar;
using namespace gridcar::test;
namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace
{
/// A disc of positions at any heading; sampleable (its centre at the first free heading of
/// 72) or not. Not a PositionGoal: the planners see a region of the application's own.
class DiscRegion : public ob::GoalSampleableRegion
{
public:
    DiscRegion(const ob::SpaceInformationPtr &si, double x, double y, double radius, bool sampleable)
      : ob::GoalSampleableRegion(si), x_(x), y_(y), sampleable_(sampleable)
    {
        setThreshold(radius);
    }
    double distanceGoal(const ob::State *st) const override
    {
        const Pose2 p = toPose(st);
        return std::hypot(p.x - x_, p.y - y_);
    }
    void sampleGoal(ob::State *st) const override
    {
        for (int k = 0; k < 72; ++k)
        {
            setPose(st, {x_, y_, wrapYaw(k * M_PI / 36)});
            if (si_->isValid(st)) return;
        }
    }
    unsigned int maxSampleCount() const override { return sampleable_ ? 1u : 0u; }
    bool couldSample() const override { return sampleable_; }

private:
    double x_, y_;
    bool sampleable_;
};

/// 30 m x 20 m at @p res with its lower-left corner at (ox, oy): a wall up from the bottom at
/// x = 10 m, one down from the top at x = 20 m (an S-shaped route), and a closed room (walls
/// 1 m thick) in the lower right. The walls are laid in the map's own frame, so every origin
/// gives the same cells.
std::shared_ptr<const OccupancyGrid> sceneMap(double res, double ox, double oy)
{
    const int W = int(std::lround(30.0 / res)), H = int(std::lround(20.0 / res));
    auto g = std::make_shared<OccupancyGrid>(W, H, res, CellState::Free);
    g->setOrigin(ox, oy);
    auto in = [](double v, double lo, double hi) { return v >= lo && v < hi; };
    for (int r = 0; r < H; ++r)
        for (int c = 0; c < W; ++c)
        {
            const double x = (c + 0.5) * res, y = (H - r - 0.5) * res;
            const bool wallA = in(x, 9.5, 10.5) && in(y, 0.0, 13.0);
            const bool wallB = in(x, 19.5, 20.5) && in(y, 7.0, 20.0);
            const bool room = in(x, 23.0, 29.5) && in(y, 0.5, 7.0) && !(in(x, 24.0, 28.5) && in(y, 1.5, 6.0));
            if (wallA || wallB || room) g->set(c, r, CellState::Occupied);
        }
    return g;
}

enum class GoalKind
{
    StateMatched,   ///< GoalState, match_goal_heading=1
    StateAnyYaw,    ///< GoalState, match_goal_heading=0 (gridcar's planners only)
    Position,       ///< PositionGoal, any heading, within 1 micrometre
    SampledRegion,  ///< a sampleable disc of 0.3 m
    Region          ///< a disc of 0.6 m that cannot be sampled
};
const char *kindName(GoalKind k)
{
    switch (k)
    {
        case GoalKind::StateMatched: return "GoalState, heading matched";
        case GoalKind::StateAnyYaw: return "GoalState, any heading";
        case GoalKind::Position: return "PositionGoal";
        case GoalKind::SampledRegion: return "sampleable region";
        default: return "region";
    }
}
const GoalKind kKinds[] = {GoalKind::StateMatched, GoalKind::StateAnyYaw, GoalKind::Position, GoalKind::SampledRegion,
                           GoalKind::Region};

/// One solve of @p planner from @p start to @p goal (both in the map's own frame) on the scene
/// at origin (ox, oy).
struct Answer
{
    ob::PlannerStatus status;
    std::vector<Pose2> path;  ///< in the map's own frame
    double length{0.0};
    bool valid{false};        ///< og::PathGeometric::check()
    bool endsInGoal{false};
    double endDistance{0.0};  ///< position of the last state from the goal's centre
    double nearestExplored{std::numeric_limits<double>::infinity()};  ///< of PlannerData's vertices
    std::string stopReason;   ///< a gridcar planner's GridPlanner::lastStopReason()
};

Answer solve(const std::string &planner, GoalKind kind, double res, double ox, double oy, const Pose2 &start, const Pose2 &goal,
             const std::map<std::string, std::string> &params = {})
{
    GridSetup s = makeGridSetup(sceneMap(res, ox, oy), VehicleParams::preset("paper-c-robot"));
    const Pose2 a{start.x + ox, start.y + oy, start.yaw}, b{goal.x + ox, goal.y + oy, goal.yaw};
    const ob::SpaceInformationPtr &si = s.ss->getSpaceInformation();
    switch (kind)
    {
        case GoalKind::StateMatched:
        case GoalKind::StateAnyYaw: s.setStartAndGoal(a, b); break;
        default:
        {
            s.setStartAndGoal(a, b);  // the start
            ob::GoalPtr g;
            if (kind == GoalKind::Position) g = std::make_shared<PositionGoal>(si, b.x, b.y, 1e-6);
            else g = std::make_shared<DiscRegion>(si, b.x, b.y, kind == GoalKind::Region ? 0.6 : 0.3, kind == GoalKind::SampledRegion);
            s.ss->setGoal(g);
        }
    }
    ob::PlannerPtr p = makePlanner(si, planner);
    if (isGrid(planner)) p->params().setParam("match_goal_heading", kind == GoalKind::StateAnyYaw ? "0" : "1");
    for (const auto &[name, value] : params)
        if (!p->params().setParam(name, value)) throw std::invalid_argument("parameter " + name);
    s.ss->setPlanner(p);
    // the sampling planners stop at their first exact solution (the optimizing ones once any
    // cost satisfies the objective), mostly in milliseconds on this map; gridcar's searches end
    // by themselves (the limit is for a sanitizer build on a busy machine)
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
    objective->setCostThreshold(ob::Cost(std::numeric_limits<double>::infinity()));
    s.ss->setOptimizationObjective(objective);
    const ob::PlannerTerminationCondition ptc = ob::plannerOrTerminationCondition(
        ob::timedPlannerTerminationCondition(isGrid(planner) ? 60.0 : 5.0),
        ob::exactSolnPlannerTerminationCondition(s.ss->getProblemDefinition()));
    Answer out;
    try
    {
        out.status = s.ss->solve(ptc);
    }
    catch (const ompl::Exception &)
    {
        // OMPL's informed samplers refuse a goal they cannot sample (a plain region) this way;
        // gridcar's entry points never give one
        out.status = ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    }
    if (auto grid = std::dynamic_pointer_cast<GridPlanner>(p)) out.stopReason = grid->lastStopReason();
    auto local = [&](const Pose2 &p) { return Pose2{p.x - ox, p.y - oy, p.yaw}; };
    if (s.ss->haveSolutionPath())
    {
        og::PathGeometric path = s.ss->getSolutionPath();
        out.length = path.length();
        out.valid = path.check();
        for (const Pose2 &q : toPoses(path)) out.path.push_back(local(q));
        out.endsInGoal = s.ss->getGoal()->isSatisfied(path.getStates().back());
        out.endDistance = std::hypot(out.path.back().x - goal.x, out.path.back().y - goal.y);
    }
    ob::PlannerData data(si);
    s.ss->getPlannerData(data);
    for (unsigned i = 0; i < data.numVertices(); ++i)
    {
        const Pose2 q = local(toPose(data.getVertex(i).getState()));
        out.nearestExplored = std::min(out.nearestExplored, std::hypot(q.x - goal.x, q.y - goal.y));
    }
    return out;
}

class GoalKinds : public ::testing::TestWithParam<std::string>
{
protected:
    void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
    void TearDown() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};

/// The cell sizes of the scenes: 0.2 and 0.5 m, or the list in GRIDCAR_GOAL_KINDS_CELLS (the
/// sanitizer run of scripts/test.sh takes 0.5 m alone: the same code paths at a seventh of the
/// searching, which there is some 40 times slower)
std::vector<double> cellSizes()
{
    const char *env = std::getenv("GRIDCAR_GOAL_KINDS_CELLS");
    if (!env || !*env) return {0.2, 0.5};
    std::vector<double> out;
    std::stringstream in(env);
    for (std::string item; std::getline(in, item, ',');)
        out.push_back(std::stod(item));
    return out;
}

// the origins: a corner of a real map's kind (ROS origins are negative) off the cell lattice
constexpr double kOx = -37.131, kOy = 12.0707;
const Pose2 kStart{2.37, 3.13, 0.3};
const Pose2 kGoal{26.71, 15.43, 1.2};  // round both walls
const Pose2 kShut{26.23, 3.81, 0.4};   // inside the closed room
}  // namespace

TEST_P(GoalKinds, EveryGoalKindIsReachedAndMovingTheOriginMovesTheAnswer)
{
    const std::string planner = GetParam();
    const bool ours = isGrid(planner);
    for (double res : cellSizes())
        for (GoalKind kind : kKinds)
        {
            if (!ours && kind == GoalKind::StateAnyYaw) continue;  // OMPL's planners have no such setting
            SCOPED_TRACE(planner + ", " + kindName(kind) + ", " + std::to_string(res) + " m cells");
            const Answer a = solve(planner, kind, res, 0.0, 0.0, kStart, kGoal);
            const Answer b = solve(planner, kind, res, kOx, kOy, kStart, kGoal);
            auto refused = [](const Answer &x) {
                return x.status == ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE || x.status == ob::PlannerStatus::INVALID_GOAL ||
                       x.status == ob::PlannerStatus::INVALID_START;
            };
            // a sampling planner's run depends on its random samples (OMPL 1.5.2's BIT* now and
            // then misses a goal pose for the whole limit): only whether it takes the goal
            if (ours)
                EXPECT_EQ(ob::PlannerStatus::StatusType(a.status), ob::PlannerStatus::StatusType(b.status))
                    << a.status.asString() << " at origin 0, " << b.status.asString() << " moved";
            else
                EXPECT_EQ(refused(a), refused(b)) << a.status.asString() << " at origin 0, " << b.status.asString() << " moved";
            for (const Answer *x : {&a, &b})
                if (x->status == ob::PlannerStatus::EXACT_SOLUTION)
                {
                    // match_goal_heading=0: a GoalState's position is the goal, not its heading
                    if (kind == GoalKind::StateAnyYaw) EXPECT_LT(x->endDistance, 1e-6);
                    else EXPECT_TRUE(x->endsInGoal) << "an exact path ends " << x->endDistance << " m from the goal";
                    EXPECT_TRUE(x->valid);
                }
            if (!ours)
            {
                // OMPL's planners need a goal they can sample for some kinds; every other kind
                // they take
                if (kind != GoalKind::Region) EXPECT_FALSE(refused(a)) << a.status.asString();
                continue;
            }
            // paper I's published search and smoothing makes no promise of drivability: where
            // its smoothed path turns tighter than K_max the answer is approximate (the one
            // rule for smoothed paths), but it still ends at the goal's position
            if (planner != "improved-astar-grid" || a.status != ob::PlannerStatus::APPROXIMATE_SOLUTION)
                EXPECT_EQ(a.status, ob::PlannerStatus::EXACT_SOLUTION) << a.status.asString();
            ASSERT_FALSE(a.path.empty());
            EXPECT_NEAR(a.length, b.length, 1e-6);
            ASSERT_EQ(a.path.size(), b.path.size());
            for (std::size_t i = 0; i < a.path.size(); ++i)
                ASSERT_LT(poseError(a.path[i], b.path[i]), 1e-6) << "pose " << i;
            if (kind == GoalKind::StateMatched && a.status == ob::PlannerStatus::EXACT_SOLUTION)
                EXPECT_LT(poseError(a.path.back(), kGoal), 1e-9);
            if (kind == GoalKind::StateMatched || kind == GoalKind::Position || kind == GoalKind::StateAnyYaw)
                EXPECT_LT(a.endDistance, 1e-6);
        }
}

// gridcar's planners (OMPL's keep their own nearest state, by the goal's distanceGoal)
class ApproximateAnswers : public GoalKinds
{
};

TEST_P(ApproximateAnswers, EndAtTheExploredStateNearestTheGoal)
{
    const std::string planner = GetParam();
    for (double res : cellSizes())
        for (GoalKind kind : kKinds)
        {
            SCOPED_TRACE(planner + ", " + kindName(kind) + ", " + std::to_string(res) + " m cells");
            // the car lattice's search alone: its fallback searches (the hybrid set, at half its
            // cell) would spend some 15 s each exhausting the map around the shut room first,
            // and keep this answer (an answer is kept if it reaches the goal or there is none)
            std::map<std::string, std::string> params;
            if (planner == "corner-astar" || planner == "improved-astar") params["primitives"] = "lattice";
            const Answer a = solve(planner, kind, res, kOx, kOy, kStart, kShut, params);
            if ((planner == "corner-astar" || planner == "improved-astar") &&
                (kind == GoalKind::StateMatched || kind == GoalKind::StateAnyYaw || kind == GoalKind::Position))
            {
                // one goal position on gridcar's checker (a pose, or a PositionGoal within a
                // micrometre): proven unreachable (fast failure), the goal's shut room named; at
                // once, nothing searched, where the 2D relaxation already parts the ends, else
                // once the first search has run a while, which stops there (no fallback run)
                EXPECT_NE(a.stopReason.find("unreachable"), std::string::npos) << a.stopReason;
                EXPECT_NE(a.stopReason.find("round the goal"), std::string::npos) << a.stopReason;
                if (a.status == ob::PlannerStatus::INVALID_GOAL)
                {
                    EXPECT_TRUE(a.path.empty());
                    continue;
                }
            }
            ASSERT_EQ(a.status, ob::PlannerStatus::APPROXIMATE_SOLUTION) << a.status.asString();
            ASSERT_FALSE(a.path.empty());
            // the room's wall is 1 m thick: nothing outside comes nearer than 0.9 m or so
            EXPECT_GT(a.endDistance, 0.5);
            EXPECT_LE(a.endDistance, a.nearestExplored + 1e-9);
            // not the start: states much nearer were explored (where the proof stopped the
            // search, on its way round the S: nearer than the start)
            const bool stopped = a.stopReason.find("unreachable") != std::string::npos;
            EXPECT_LT(a.endDistance, (stopped ? 0.9 : 0.5) * std::hypot(kShut.x - kStart.x, kShut.y - kStart.y));
        }
}

namespace
{
std::string testName(const ::testing::TestParamInfo<std::string> &info)
{
    std::string n = info.param;
    for (char &c : n)
        if (c == '-') c = '_';
    return n;
}
}  // namespace

INSTANTIATE_TEST_SUITE_P(AllPlanners, GoalKinds, ::testing::ValuesIn(plannerNames()), testName);
INSTANTIATE_TEST_SUITE_P(GridcarPlanners, ApproximateAnswers, ::testing::ValuesIn(gridPlannerNames()), testName);
