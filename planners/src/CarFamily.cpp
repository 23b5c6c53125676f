/// @file CarFamily.cpp
/// @brief The car lattice as a search family: set-up, one query, the explored graph.
#include "gridcar/planners/CarFamily.h"

#include "gridcar/planners/search/CarGoal.h"
#include "gridcar/planners/search/CurvatureStep.h"
#include "gridcar/planners/search/PathShortcut.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace gridcar
{
namespace
{
/// The proof a search that runs long asks (CarLatticeSearch::provenUnreachable()), after this
/// many expansions (most queries end before: they never pay for it)
constexpr std::uint64_t kProofAfter = 2000;
/// and within this many cells: a region of up to about half as many shut off round either end
/// is found (the two breadth-first searches run in turns), a room of 18 x 18 m at 0.05 m; on
/// the 24 M-cell map it costs a few ms where the ends are joined
constexpr std::size_t kQuickProofCells = std::size_t(1) << 18;
/// The hybrid fallback is probed when the first search has done this much work, and 4x as
/// much each time after; the probes together do at most an eighth of the first search's work (an
/// expansion, or kBoundStatesPerWork states of a search's 2D and turn bounds: a profile of paper
/// C's robot on the Tsudanuma map gave 13 us an expansion, 0.3 us a bound state). Where the
/// lattice's fixed headings cannot thread a gap the hybrid's free ones can (a lattice turned to
/// a start heading a few degrees off a corridor's walls), the first search would otherwise
/// search out every place it can reach (seconds on a large map) before the fallback ran.
constexpr std::uint64_t kProbeFirst = 50000;
constexpr std::uint64_t kBoundStatesPerWork = 40;
}  // namespace

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
            q.goalPositionTolerance = 0.0;
            break;
        case GoalTarget::Kind::Position:
            q.goalYawTolerance = goal.yawTolerance;
            q.goalPositionTolerance = goal.positionTolerance;
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
    terms.boundsEpoch = ++queries_;  // (its searches run again keep their 2D bounds)
    const CarLatticeQuery q = queryFor(toPose(start), std::move(terms), goal);
    FamilyRun run;
    const auto t0 = std::chrono::steady_clock::now();
    // a goal heading to meet: the primitive set for manoeuvres, where there is one
    CarLatticeSearch *main = q.goalYawTolerance >= 0 && forPoses_ ? forPoses_.get() : search_.get();
    // a goal (or start) shut in a small region is proven cut off once the search has run for
    // kProofAfter expansions, and the search stops there: the approximate answer is the state
    // nearest the goal it has explored, with the reason (as when the proof below answers after
    // the search). The 2D graph of the heuristic may join that region to the rest across a wall
    // thinner than the lattice's cell, and the search would exhaust the start's region first.
    std::string proven;
    bool startShutIn = false, asked = !q.fallbacks;
    std::atomic<std::uint64_t> seen{0};
    CarLatticeResult probe;
    bool probed = false;
    std::uint64_t nextProbe = q.fallbacks && fallback_ && fallback_.get() != main ? kProbeFirst : ~std::uint64_t(0),
                  probeExpanded = 0;
    const std::function<bool()> stop = [&] {
        const std::uint64_t n = seen.load(std::memory_order_relaxed);
        if (progress) progress->store(n + probeExpanded, std::memory_order_relaxed);
        if (!asked && n >= kProofAfter)
        {
            asked = true;
            proven = CarLatticeSearch::provenUnreachable(q, startShutIn, kQuickProofCells);
        }
        const std::uint64_t work = n + main->boundStates() / kBoundStatesPerWork;
        if (proven.empty() && !probed && work >= nextProbe && !cancelled())
        {
            nextProbe = FallbackSchedule::nextBudget(nextProbe);
            probed = probeHybrid(q, cost, work / 8, cancelled, *main, probe, probeExpanded);
        }
        return !proven.empty() || probed || cancelled();
    };
    CarLatticeResult r = main->run(q, cost, stop, &seen);
    if (!proven.empty() && r.outcome == SearchOutcome::Cancelled) r.outcome = SearchOutcome::Exhausted;
    const std::uint64_t firstExpanded = r.expanded;
    if (probed) r = std::move(probe);
    r.expanded = firstExpanded + probeExpanded;
    last_ = probed ? fallback_.get() : main;
    // Where the search from the start ends without the goal (not stopped), the time left goes
    // to the fallback searches (FallbackSchedule: the order and the budgets); an answer is kept
    // if it reaches the goal, or if it ends nearer the goal than the one kept.
    FallbackOptions fo;
    fo.fixedEnds = goal.kind == GoalTarget::Kind::State && q.goalYawTolerance == 0 && !q.freeStartHeading;
    fo.latticeReverses = main->lattice().config().reverse;
    fo.reverseNearEnds = q.reverseWithin >= 0;
    // a start the first search could not leave: its one state expanded, no motion out of it free
    fo.startShut = !probed && !q.freeStartHeading && firstExpanded <= 1 && r.outcome == SearchOutcome::Exhausted;
    fo.hybrid = fallback_ != nullptr;
    fo.hybridReverses = fallback_ && fallback_->lattice().config().reverse;
    fo.fine = fallback_ && fineConfig_.cell >= 0.025;
    const FallbackSchedule schedule(fo);
    auto runStage = [&](const FallbackStage &st, std::uint64_t budget) {
        CarLatticeSearch *search = stageSearch(st.search, main);
        std::atomic<std::uint64_t> count{0};
        const std::function<bool()> stop = [&] { return cancelled() || count.load(std::memory_order_relaxed) >= budget; };
        CarLatticeQuery b = q;
        b.reverseWithin = -1.0;  // the fallbacks reverse wherever they can
        if (st.fromGoal)
        {
            std::swap(b.start, b.goal);
            b.timeReversed = true;
            b.inGoal = nullptr;
        }
        CarLatticeResult h = search->run(b, cost, stop, &count);
        if (progress) *progress += h.expanded;
        if (h.exact && st.fromGoal) std::reverse(h.path.begin(), h.path.end());
        const bool ended = h.outcome != SearchOutcome::Cancelled;
        h.expanded += r.expanded;
        // an approximate answer: the one ending nearer the goal (a search from the goal back
        // has none to give); how the first search ended stays the run's (exhausted: nothing
        // proved the goal unreachable, but the answer was not cut short by the time limit)
        const CarGoal near(q);
        const bool nearer = !st.fromGoal && !r.exact && !h.path.empty() && !r.path.empty() &&
                            near.closeness(h.path.back()) < near.closeness(r.path.back());
        if (h.exact || nearer || r.path.empty())
        {
            const SearchOutcome first = r.outcome;
            r = std::move(h);
            if (nearer) r.outcome = first;
            last_ = search;
        }
        else
            r.expanded = h.expanded;
        return ended;
    };
    // the fallbacks run only where a path may exist (FootprintChecker::reachability())
    if (q.fallbacks && proven.empty() && r.outcome == SearchOutcome::Exhausted && !r.exact && r.unreachable.empty() &&
        !schedule.stages().empty())
        proven = CarLatticeSearch::provenUnreachable(q, startShutIn);
    if (q.fallbacks && r.outcome != SearchOutcome::Cancelled && r.unreachable.empty() && proven.empty())
        schedule.run(runStage, [&] { return r.exact || cancelled(); });
    // what the lattice's few headings and coarse cells leave over, taken off by free curves
    if (r.exact && post.shortcutCurves > 0)
    {
        const ShortcutReport sr = PathShortcut(*last_).apply(r.path, q, cost, cancelled, post.shortcutCurves);
        r.cost += sr.costAfter - sr.costBefore;  // what was taken off, by the same measure
    }
    if (r.exact && post.curvatureRate > 0 && r.path.size() > 2)
        CurvatureStep(*last_, post.maxCurvature, post.curvatureRate).apply(r.path, cancelled);
    run.searchSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.expanded = r.expanded;
    run.cost = r.cost;
    run.end.cancelled = r.outcome == SearchOutcome::Cancelled;
    run.end.reached = r.exact;
    // no path and not stopped: the vehicle fits at no lattice heading at the start
    run.end.noPath = ompl::base::PlannerStatus::INVALID_START;
    run.end.noPathWhy = "the vehicle fits at no lattice heading at the start";
    if (!r.unreachable.empty())
    {
        // (OMPL 1.5 has no status for it: the end whose free space is shut in is invalid)
        run.end.noPath = r.startShutIn ? ompl::base::PlannerStatus::INVALID_START : ompl::base::PlannerStatus::INVALID_GOAL;
        run.end.noPathWhy = "the goal is unreachable: " + r.unreachable;
    }
    if (!proven.empty()) run.end.approximateWhy = "the goal is unreachable: " + proven;
    if (!r.path.empty()) run.end.path = std::make_shared<ompl::geometric::PathGeometric>(toPath(si, r.path));
    return run;
}

bool CarFamily::probeHybrid(const CarLatticeQuery &q, const LatticeCostModel &cost, std::uint64_t budget,
                            const std::function<bool()> &cancelled, CarLatticeSearch &main, CarLatticeResult &out,
                            std::uint64_t &expanded)
{
    // the probes' work so far: their expansions, and the bound states of the hybrid search's
    // 2D bounds, which each probe of the query resumes (CarLatticeQuery::boundsEpoch)
    std::atomic<std::uint64_t> count{0};
    const std::function<bool()> stop = [&] {
        return cancelled() ||
               expanded + count.load(std::memory_order_relaxed) + fallback_->boundStates() / kBoundStatesPerWork >= budget;
    };
    CarLatticeQuery b = q;
    b.reverseWithin = -1.0;  // (as the fallback stages: they reverse wherever they can)
    CarLatticeResult h = fallback_->run(b, cost, stop, &count);
    main.reclaimCollision();
    expanded += h.expanded;
    if (!h.exact) return false;
    out = std::move(h);
    return true;
}

CarLatticeSearch *CarFamily::stageSearch(FallbackSearch which, CarLatticeSearch *main)
{
    switch (which)
    {
        case FallbackSearch::Lattice: return main;
        case FallbackSearch::Hybrid: return fallback_.get();
        case FallbackSearch::FineHybrid:
            if (!fine_) fine_ = std::make_unique<CarLatticeSearch>(collision_, std::make_shared<const CarLattice>(fineConfig_));
            return fine_.get();
    }
    return main;
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
