/// @file CarFamily.cpp
/// @brief The car lattice as a search family: set-up, one query, the explored graph.
#include "gridcar/planners/CarFamily.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <utility>
#include <vector>

namespace gridcar
{
void CarFamily::setup(const CarLatticeConfig &cfg, std::shared_ptr<CarCollision> collision, const CarLatticeConfig *fallback,
                      const CarLatticeConfig *forPoses)
{
    last_ = nullptr;
    const bool same = collision == collision_ && search_ && search_->lattice().config() == cfg;
    const bool sameFallback = fallback ? fallback_ && fallback_->lattice().config() == *fallback : !fallback_;
    const bool samePoses = forPoses ? forPoses_ && forPoses_->lattice().config() == *forPoses : !forPoses_;
    if (same && sameFallback && samePoses) return;
    collision_ = std::move(collision);
    if (!same) search_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(cfg));
    forPoses_.reset();
    if (forPoses) forPoses_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(*forPoses));
    fallback_.reset();
    fine_.reset();
    if (!fallback) return;
    fallback_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(*fallback));
    // the hybrid nodes halved (a gap the fallback's cells are too coarse for), down to 2.5 cm;
    // built when a query first needs it (its primitives cost a set-up the others should not pay)
    fineConfig_ = *fallback;
    fineConfig_.cell = fallback->cell / 2;
    fineConfig_.spacing = std::min(fineConfig_.spacing, fineConfig_.cell / 2);
}

namespace
{
/// @p terms aimed from @p start at the goal target.
CarLatticeQuery queryFor(const Pose2 &start, CarLatticeQuery q, const GoalTarget &goal)
{
    q.start = start;
    q.goal = goal.pose;
    switch (goal.kind)
    {
        case GoalTarget::Kind::State:  // a node at the goal pose, or the analytic expansion
            q.goalYawTolerance = goal.yawTolerance;
            break;
        case GoalTarget::Kind::Position:
            q.goalYawTolerance = goal.yawTolerance;
            q.inGoal = goal.satisfied;
            break;
        case GoalTarget::Kind::SampledRegion:  // aimed at; the region decides
            q.shoot = false;
            q.inGoal = goal.satisfied;
            break;
        case GoalTarget::Kind::Region:  // nothing to aim at: Dijkstra order until a node satisfies it
            q.aim = false;
            q.shoot = false;
            q.inGoal = goal.satisfied;
            q.goalDistance = goal.distance;
            break;
    }
    return q;
}
}  // namespace

FamilyRun CarFamily::solve(const ompl::base::SpaceInformationPtr &si, const ompl::base::State *start,
                           CarLatticeQuery terms, const CarPostProcessing &post, const GoalTarget &goal,
                           const LatticeCostModel &cost,
                           const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    const CarLatticeQuery q = queryFor(toPose(start), std::move(terms), goal);
    FamilyRun run;
    const auto t0 = std::chrono::steady_clock::now();
    // a goal heading to meet: the primitive set for manoeuvres, where there is one
    CarLatticeSearch *main = q.goalYawTolerance >= 0 && forPoses_ ? forPoses_.get() : search_.get();
    CarLatticeResult r = main->run(q, cost, cancelled, progress);
    last_ = main;
    // Where the search from the start ends without the goal (not stopped), the next searches
    // in the time that is left: Hybrid A*'s finer manoeuvres (the lattice's nodes could not make
    // it: a tight spot); and for a goal pose to be met exactly from a start pose, with
    // reversing, each search also from the goal back to the start (CarLatticeQuery::
    // timeReversed: leaving a slot is found where entering it is not). Those several run in
    // turns on expansion budgets that grow fourfold a round (deterministic, and at most about
    // 4/3 of each one's own expansions repeated), until one reaches the goal or all ran out;
    // an answer is kept if it reaches the goal, or if there is none yet.
    const bool fixedEnds = goal.kind == GoalTarget::Kind::State && q.goalYawTolerance == 0 && !q.freeStartHeading;
    struct Stage
    {
        CarLatticeSearch *search;
        bool reversed;
        bool done{false};
    };
    std::vector<Stage> stages;
    if (fixedEnds && main->lattice().config().reverse) stages.push_back({main, true});
    if (fallback_)
    {
        stages.push_back({fallback_.get(), false});
        if (fixedEnds && fallback_->lattice().config().reverse) stages.push_back({fallback_.get(), true});
    }
    const bool fine = fallback_ && fineConfig_.cell >= 0.025;
    if (fine)
    {
        stages.push_back({nullptr, false});
        if (fixedEnds && fineConfig_.reverse) stages.push_back({nullptr, true});
    }
    const bool turns = stages.size() > 1;
    std::uint64_t budget = turns ? 2000 : std::numeric_limits<std::uint64_t>::max();
    auto pending = [&stages] {
        return std::any_of(stages.begin(), stages.end(), [](const Stage &st) { return !st.done; });
    };
    while (!r.exact && r.outcome != SearchOutcome::Cancelled && !cancelled() && pending())
    {
        for (Stage &st : stages)
        {
            if (st.done || r.exact || cancelled()) continue;
            if (!st.search)
            {
                if (!fine_) fine_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(fineConfig_));
                st.search = fine_.get();
            }
            std::atomic<std::uint64_t> count{0};
            const std::function<bool()> stop = [&] { return cancelled() || count.load(std::memory_order_relaxed) >= budget; };
            CarLatticeQuery b = q;
            if (st.reversed)
            {
                std::swap(b.start, b.goal);
                b.timeReversed = true;
                b.inGoal = nullptr;
            }
            CarLatticeResult h = st.search->run(b, cost, stop, &count);
            if (progress) *progress += h.expanded;
            if (h.exact && st.reversed) std::reverse(h.path.begin(), h.path.end());
            // found or ran out: another round would repeat it
            st.done = h.outcome != SearchOutcome::Cancelled || !turns;
            h.expanded += r.expanded;
            if (h.exact || r.path.empty())
            {
                r = std::move(h);
                last_ = st.search;
            }
            else
                r.expanded = h.expanded;
        }
        budget = budget > std::numeric_limits<std::uint64_t>::max() / 4 ? budget : 4 * budget;
    }
    // what the lattice's few headings and coarse cells leave over, taken off by free curves
    if (r.exact && post.shortcutCurves > 0)
    {
        const ShortcutReport sr = last_->shortcut(r.path, q, cost, cancelled, post.shortcutCurves);
        r.cost += sr.costAfter - sr.costBefore;  // what was taken off, by the same measure
    }
    if (r.exact && post.curvatureRate > 0 && r.path.size() > 2) smooth(post, r.path, cancelled);
    run.searchSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.expanded = r.expanded;
    run.cost = r.cost;
    run.end.cancelled = r.outcome == SearchOutcome::Cancelled;
    run.end.reached = r.exact;
    // no path and not stopped: the vehicle fits at no lattice heading at the start
    run.end.noPath = ompl::base::PlannerStatus::INVALID_START;
    run.end.noPathWhy = "the vehicle fits at no lattice heading at the start";
    if (!r.path.empty()) run.end.path = std::make_shared<ompl::geometric::PathGeometric>(toPath(si, r.path));
    return run;
}

void CarFamily::smooth(const CarPostProcessing &post, std::vector<Pose2> &path, const std::function<bool()> &cancelled)
{
    // poses no farther apart than lets a body point move the lattice's spacing, so that the
    // search's own swept-motion test certifies each replacement
    const CarLatticeConfig &cfg = last_->lattice().config();
    CurvatureSmoothingOptions o;
    o.maxCurvature = post.maxCurvature;
    o.maxCurvatureRate = post.curvatureRate;
    o.step = cfg.spacing / (1.0 + cfg.reach * post.maxCurvature);
    o.reversing = true;
    o.cancelled = cancelled;
    o.free = [this](const std::vector<Pose2> &poses) {
        return last_->curveFree(poses[0], int(poses.size()) - 1, [&poses](int i) { return poses[std::size_t(i)]; });
    };
    CurvatureSmoothing s = smoothCurvature(path, o);
    if (!s.cancelled) path = std::move(s.path);
    // clothoid turns keep the rate but turn at full lock: wider where the map leaves room, with
    // 5 cm more room than the search's margin (as the shortcut: for the follower)
    if (!s.cancelled && cfg.curvatureRate > 0)
    {
        o.free = [this](const std::vector<Pose2> &poses) {
            return last_->curveFree(poses[0], int(poses.size()) - 1, [&poses](int i) { return poses[std::size_t(i)]; }, 0.05);
        };
        CurvatureSmoothing w = widenTurns(path, o);
        if (!w.cancelled) path = std::move(w.path);
    }
}

void CarFamily::plannerData(ompl::base::PlannerData &data, PlannerDataStates &states) const
{
    if (!search()) return;
    search()->forEachExpanded([&](const Pose2 &node, const Pose2 &parent) {
        if (node.x == parent.x && node.y == parent.y && node.yaw == parent.yaw)
            data.addStartVertex(ompl::base::PlannerDataVertex(states.at(0, node)));
        else
            data.addEdge(ompl::base::PlannerDataVertex(states.at(0, parent)), ompl::base::PlannerDataVertex(states.at(0, node)));
    });
}

}  // namespace gridcar
