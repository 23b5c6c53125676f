/// @file CarFamily.cpp
/// @brief The car lattice as a search family: set-up, one query, the explored graph.
#include "gridcar/planners/CarFamily.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/geometric/PathGeometric.h>

#include <chrono>

namespace gridcar
{
void CarFamily::setup(const CarLatticeConfig &cfg, std::shared_ptr<CarCollision> collision, const CarLatticeConfig *fallback)
{
    last_ = nullptr;
    const bool same = collision == collision_ && search_ && search_->lattice().config() == cfg;
    const bool sameFallback = fallback ? fallback_ && fallback_->lattice().config() == *fallback : !fallback_;
    if (same && sameFallback) return;
    collision_ = std::move(collision);
    if (!same) search_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(cfg));
    fallback_.reset();
    if (fallback) fallback_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(*fallback));
}

FamilyRun CarFamily::solve(const ompl::base::SpaceInformationPtr &si, const ompl::base::State *start,
                           bool freeStartHeading, const CarSearchOptions &options, const GoalTarget &goal,
                           const LatticeCostModel &cost,
                           const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    CarLatticeQuery q;
    q.start = toPose(start);
    q.freeStartHeading = freeStartHeading;
    q.weight = options.weight;
    q.reversePenalty = options.reversePenalty;
    q.cuspPenalty = options.cuspPenalty;
    q.curveWithin = options.curveWithin;
    q.layer = options.layer;
    q.layerWeight = options.layerWeight;
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
            break;
    }
    FamilyRun run;
    const auto t0 = std::chrono::steady_clock::now();
    CarLatticeResult r = search_->run(q, cost, cancelled, progress);
    last_ = search_.get();
    if (fallback_ && !r.exact && r.outcome != SearchOutcome::Cancelled && !cancelled())
    {
        // the lattice's nodes could not make it (a tight spot): Hybrid A*'s finer manoeuvres,
        // in the time that is left; its answer is kept if it reaches the goal
        CarLatticeResult h = fallback_->run(q, cost, cancelled, progress);
        h.expanded += r.expanded;
        if (h.exact || r.path.empty())
        {
            r = std::move(h);
            last_ = fallback_.get();
        }
        else
            r.expanded = h.expanded;
    }
    if (r.exact && options.curvatureRate > 0 && r.path.size() > 2) smooth(options, r.path, cancelled);
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

void CarFamily::smooth(const CarSearchOptions &options, std::vector<Pose2> &path, const std::function<bool()> &cancelled)
{
    // poses no farther apart than lets a body point move the lattice's spacing, so that the
    // search's own swept-motion test certifies each replacement
    const CarLatticeConfig &cfg = last_->lattice().config();
    CurvatureSmoothingOptions o;
    o.maxCurvature = options.maxCurvature;
    o.maxCurvatureRate = options.curvatureRate;
    o.step = cfg.spacing / (1.0 + cfg.reach * options.maxCurvature);
    o.reversing = true;
    o.cancelled = cancelled;
    o.free = [this](const std::vector<Pose2> &poses) {
        return last_->curveFree(poses[0], int(poses.size()) - 1, [&poses](int i) { return poses[std::size_t(i)]; });
    };
    CurvatureSmoothing s = smoothCurvature(path, o);
    if (!s.cancelled) path = std::move(s.path);
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
