/// @file CarLatticeMargin.cpp
/// @brief The car lattice planner's hard safety margin: a path that passes nearer an obstacle
/// than the margin is searched again for the body grown by it (CarLatticePlanner::keepMargin()).
#include "gridcar/planners/CarLatticePlanner.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace gridcar
{
namespace
{
/// The grown body's path is kept if it costs at most this times the first one.
constexpr double kMarginCostRatio = 1.05;
/// Its search's expansion budget: this times the first search's, plus kMarginExtraExpansions
/// (the grown searches that reached the goal on the defaults suite's Tsudanuma queries took
/// 0.1-1.5 times the first search's; with 1 x + 10 000 the ones that did not cost paper I's car
/// 60-230 ms each)
constexpr std::uint64_t kMarginBudgetFactor = 2;
constexpr std::uint64_t kMarginExtraExpansions = 2000;
constexpr double kInf = std::numeric_limits<double>::infinity();
/// What a lattice expansion costs in states closed by the heuristic's bounds (2D nodes, turn
/// states): some 13 us against 0.3 us, profiled on paper C's robot on Willow Garage
constexpr std::uint64_t kBoundStatesPerExpansion = 40;
/// safety_margin=auto, m (a quarter of the width if less): the navigation suite's cars drove as
/// long with it as without (with 0.3 m, 5-14 % longer) and paper C's robot arrived where it had
/// threaded a gap of centimetres (docs/planners.md)
constexpr double kAutoMargin = 0.1;

/// True if the body of @p grown fits near @p p: within @p within of its position (in 8
/// directions, at 4 distances) at its heading or 22.5 degrees either side.
bool roomNear(const FootprintChecker &grown, const Pose2 &p, double within)
{
    for (int r = 1; r <= 4; ++r)
        for (int k = 0; k < 8; ++k)
        {
            const double a = k * M_PI / 4, d = within * r / 4;
            for (double dy : {0.0, M_PI / 8, -M_PI / 8})
                if (grown.isValid(p.x + d * std::cos(a), p.y + d * std::sin(a), p.yaw + dy)) return true;
        }
    return false;
}
}  // namespace

double CarLatticePlanner::safetyMargin() const
{
    // the body is grown in the distance field of gridcar's checker, as a rectangle
    if (!checker_ || checker_->vehicle().isPoint() || checker_->vehicle().hasPolygon()) return 0.0;
    if (carSettings().safetyMargin) return *carSettings().safetyMargin;
    return std::min(kAutoMargin, 0.25 * checker_->vehicle().width);
}

const FootprintChecker &CarLatticePlanner::grownChecker(double margin)
{
    if (grown_ && grownBy_ == margin)
    {
        if (grownVersion_ == checker_->mapVersion()) return *grown_;
        // cells changed since: brought up to date in the changed windows, as checker_ was
        if (const auto changes = checker_->changesSince(grownVersion_))
        {
            for (const auto &[cells, field] : *changes) grown_->cellsChanged(cells, field);
            grownVersion_ = checker_->mapVersion();
            grownCollision_->mapChanged();
            return *grown_;
        }
    }
    VehicleParams v = checker_->vehicle();
    v.length += 2 * margin;
    v.width += 2 * margin;
    v.rearOverhang += margin;  // the reference point stays where it is on the body
    grown_ = std::make_unique<FootprintChecker>(checker_->gridPtr(), checker_->fieldPtr(), v);
    grownBy_ = margin;
    grownVersion_ = checker_->mapVersion();
    grownCollision_ = std::make_shared<FootprintCollision>(*grown_);
    return *grown_;
}

void CarLatticePlanner::keepMargin(FamilyRun &run, double margin, const ompl::base::State *start,
                                   const CarLatticeQuery &terms, const CarPostProcessing &post, const GoalTarget &goal,
                                   const LatticeCostModel &cost, const std::function<bool()> &cancelled,
                                   std::atomic<std::uint64_t> *progress)
{
    const std::vector<Pose2> poses = toPoses(*run.end.path);
    const FootprintChecker &grown = grownChecker(margin);
    // where an end leaves the grown body no room, no path keeps the margin there; where every
    // pose does, the path keeps it already
    if (poses.empty() || !grown.isValid(poses.front()) || !grown.isValid(poses.back())) return;
    // where the path passes nearer, the grown body must fit beside it (shifted sideways by up
    // to twice the margin, at its heading): a gap narrower than the grown body (a doorway, a
    // gate) would send the search round by another way, which a path 5 % dearer seldom is
    bool tight = false;
    double since = kInf;  // path length since the last pose tested for room near it
    for (std::size_t i = 0; i < poses.size(); ++i)
    {
        const Pose2 &p = poses[i];
        if (i > 0) since += std::hypot(p.x - poses[i - 1].x, p.y - poses[i - 1].y);
        if (grown.isValid(p)) continue;
        tight = true;
        if (since < 2 * margin) continue;  // (one test per stretch of twice the margin)
        since = 0;
        if (!roomNear(grown, p, 2 * margin)) return;
    }
    if (!tight) return;
    setupCar(grownCar_, grownCollision_, grown.reach());  // (kept while the collision model and lattice stay)
    std::atomic<std::uint64_t> count{0};
    const std::uint64_t budget = kMarginBudgetFactor * run.expanded + kMarginExtraExpansions;
    const std::function<bool()> stop = [&] { return cancelled() || count.load(std::memory_order_relaxed) >= budget; };
    CarLatticeQuery bounded = terms;
    bounded.costBound = kMarginCostRatio * run.cost;  // a dearer path would not be kept
    bounded.fallbacks = false;
    // the first search's bounds hold for the grown body too, weaker than its own: read them
    // where searching them again would cost more than the first search's expansions did
    if (CarLatticeSearch *first = car_.lastSearch(); first && first->boundStates() > kBoundStatesPerExpansion * run.expanded)
        bounded.boundsFrom = first;
    FamilyRun g = grownCar_.solve(si_, start, bounded, post, goal, cost, stop, &count);
    grownSearched_ = true;
    if (progress) *progress += g.expanded;
    run.expanded += g.expanded;
    run.searchSeconds += g.searchSeconds;
    if (!(g.end.reached && g.end.path && g.cost <= kMarginCostRatio * run.cost)) return;
    const std::uint64_t expanded = run.expanded;
    const double seconds = run.searchSeconds;
    run = std::move(g);
    run.expanded = expanded;
    run.searchSeconds = seconds;
    lastGrown_ = true;
}

}  // namespace gridcar
