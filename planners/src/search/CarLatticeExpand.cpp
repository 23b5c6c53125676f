/// @file CarLatticeExpand.cpp
/// @brief CarLatticeSearch::run(): the expander the search core drives (its goal questions
/// answered by CarGoal, its shot by AnalyticExpansion) and the path out of the search tree.
#include "gridcar/planners/search/CarLatticeSearch.h"

#include "gridcar/core/Angles.h"
#include "gridcar/planners/search/CarHeuristics.h"
#include "gridcar/planners/search/CurveTable.h"
#include "gridcar/planners/search/LazyAStar.h"

#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gridcar
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
}

/// Successors of a car-lattice state: its heading's primitives whose grown footprint is free.
struct CarExpander
{
    CarLatticeSearch &S;
    const LatticeCostModel &cost;
    std::uint64_t expansions{0};
    std::vector<Pose2> samples;  ///< reused for every primitive
    /// stepCost() per heading and primitive, where the cost model says it depends on the
    /// primitive's shape alone (NaN: not computed yet)
    std::vector<std::vector<double>> shapeCost;

    Pose2 poseOf(std::uint32_t s) const { return S.statePose(s); }
    const CarGoal goal;   ///< the goal manager: the search's questions about the goal
    CarHeuristic bounds;  ///< the lower bounds (search/CarHeuristics.h); all zero when not aiming
    CurveTableBound table;  ///< the curve bound read from the lattice's CurveTable (inactive: not asked for)

    CarExpander(CarLatticeSearch &search, const LatticeCostModel &c) : S(search), cost(c), goal(search.query_)
    {
        bounds.euclidean = {goal.pose(), cost.minCostPerMetre()};
        // a hybrid state lies up to half a cell's diagonal from the node its 2D distance is read at
        const double slack = S.lattice_->hybrid() ? S.lattice_->cell() * M_SQRT1_2 : 0.0;
        // the 2D search's distances are metres unless it weighs its edges by the model: in
        // seconds under a driving-time cost they were read as metres, a bound V times too high
        bounds.obstacle = {S.ratio_, (S.seedRadius_ + slack) * cost.minCostPerMetre(),
                           cost.weighted() ? 1.0 : cost.minCostPerMetre()};
        bounds.turn = {goal.pose(), cost.minTurnCostPerRad()};
        // a goal heading to match: the Reeds-Shepp / Dubins length to the goal pose, within
        // the query's distance of the goal
        if (goal.exactHeading() && goal.shootable() && S.query_.curveWithin > 0)
        {
            const double R = S.lattice_->config().turnRadius;
            if (!S.query_.curveTable())
                bounds.curve = {goal.pose(), R, S.lattice_->config().reverse, cost.minCostPerMetre(), S.query_.curveWithin};
            else if (const CurveTable *t = S.curveTable())
                table = CurveTableBound(*t, S.latticePose(goal.pose()));
        }
        bounds.useObstacle = S.use2d_;
        bounds.weight = S.query_.settings.heuristicWeight;
    }
    double hNode(int i, int j) const
    {
        if (!goal.aimed()) return 0.0;
        return bounds.position(S.nodePose(i, j, 0), S.use2d_ ? S.h2d_->distance(i, j) : -1.0);
    }
    /// The heuristic at lattice-frame pose @p lat of node (i, j) at heading h (a node's pose, or
    /// a hybrid state's).
    double hAt(const Pose2 &lat, int i, int j, int h) const { return hWith(lat, i, j, h, false); }
    /// hAt(), or with @p below a lower bound of it that resumes no search: the 2D distance's
    /// ObstacleHeuristic::lowerBound() in place of its distance (the bounds grow with it).
    double hWith(const Pose2 &lat, int i, int j, int h, bool below) const
    {
        if (!goal.aimed()) return 0.0;
        const Pose2 p = S.worldPose(lat);
        const double tb = table.active() ? cost.minCostPerMetre() * table(i, j, h) : 0.0;
        const double d2 = !S.use2d_ ? -1.0 : below ? S.h2d_->lowerBound(i, j) : S.h2d_->distance(i, j);
        const double hp = bounds.position(p, d2, tb);
        if (hp == kInf || !S.useTurn_ || below) return hp == kInf ? hp : hp + bounds.turning(p);
        const double t = S.turn_->distance(i, j, h);  // length and turning: bounds both terms
        if (t == kInf) return t;
        return std::max(hp + bounds.turning(p), t < 0 ? 0.0 : bounds.weight * bounds.obstacle(t));
    }
    double heuristic(std::uint32_t s)
    {
        const bool keep = s < hKept.size();  // (lazyAstar()'s states: their h kept)
        if (keep && !std::isnan(hKept[s])) return hKept[s];
        const auto k = S.unpack(S.states_.key(s));
        const double h = hAt(S.pose_[s], k.i, k.j, k.h);
        if (keep) hKept[s] = h;
        return h;
    }
    /// Nearest the goal, for the approximate answer (CarGoal::closeness()).
    double closeness(std::uint32_t s) const { return goal.closeness(poseOf(s)); }
    bool isGoal(std::uint32_t s)
    {
        ++expansions;
        return goal.reached(poseOf(s));
    }
    /// The analytic expansion step: a curve from the state to the exact goal pose.
    bool analyticExpansion(std::uint32_t s) { return goal.shootable() && S.tryShot(s, cost, expansions); }
    /// The cached stepCost() of primitive @p p of heading @p h (NaN until computed), or null
    /// where the cost model's stepCost() depends on more than the primitive's shape.
    double *shapeSlot(int h, std::size_t p)
    {
        if (!cost.shapeOnly()) return nullptr;
        if (shapeCost.empty()) shapeCost.resize(std::size_t(S.lattice_->hybrid() ? 1 : S.lattice_->headings()));
        std::vector<double> &c = shapeCost[std::size_t(h)];
        if (c.empty()) c.assign(S.lattice_->primitives(h).size(), std::numeric_limits<double>::quiet_NaN());
        return &c[p];
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit)
    {
        generate<false>(s, emit);
    }
    /// lazyAstar()'s: the motions unchecked, @p edge the primitive's index.
    template <class Emit>
    void lazySuccessors(std::uint32_t s, Emit &&emit)
    {
        generate<true>(s, emit);
    }
    bool edgeFree(std::uint32_t parent, std::uint32_t next, std::uint32_t edge) const
    {
        (void)next;
        const auto k = S.unpack(S.states_.key(parent));
        const Pose2 &at = S.pose_[parent];
        return S.primitiveFree(at, S.worldPose(at), S.lattice_->primitives(k.h)[edge]);
    }
    void accept(std::uint32_t next, std::uint32_t parent, std::uint32_t edge)
    {
        const auto k = S.unpack(S.states_.key(parent));
        S.prim_[next] = std::int16_t(edge);
        S.gear_[next] = S.lattice_->primitives(k.h)[edge].reverse ? -1 : 1;
    }
    /// The heuristic of each state, kept (lazyAstar() asks it for every motion into a state).
    std::vector<double> hKept;
    /// A state at cost @p g with heuristic @p h (weighted) lies on no path within the query's costBound.
    bool beyondBound(double g, double h) const { return g + h / bounds.weight > S.query_.costBound; }
    /// Successors of @p s: with Lazy, unchecked (a node lattice's states have their node's
    /// pose, whichever motion reaches them, so nothing but the primitive is recorded).
    template <bool Lazy, class Emit>
    void generate(std::uint32_t s, Emit &emit)
    {
        const auto k = S.unpack(S.states_.key(s));
        const Pose2 at = S.pose_[s];  // a copy: intern() below may grow pose_
        const Pose2 from = S.worldPose(at);
        const auto &prims = S.lattice_->primitives(k.h);
        const bool hybrid = S.lattice_->hybrid();
        const double c = S.lattice_->cell(), ca = std::cos(at.yaw), sa = std::sin(at.yaw);
        const double gs = S.space_.g(s);
        const bool mapped = S.query_.mapCosts();
        const bool mayReverse = S.query_.mayReverseAt(from);
        for (std::size_t p = 0; p < prims.size(); ++p)
        {
            const LatticePrimitive &prim = prims[p];
            int ni = k.i + prim.di, nj = k.j + prim.dj, nh = prim.to;
            Pose2 end{ni * c, nj * c, S.lattice_->yaw(nh)};
            if (hybrid)
            {
                // the arc from the state's own pose; its bin is the successor
                const Pose2 &q = prim.samples.back();
                end = {at.x + ca * q.x - sa * q.y, at.y + sa * q.x + ca * q.y, wrapYaw(at.yaw + q.yaw)};
                ni = int(std::lround(end.x / c));
                nj = int(std::lround(end.y / c));
                nh = S.lattice_->nearestHeading(end.yaw);
                if (ni == k.i && nj == k.j && nh == k.h) continue;  // still in its own bin
            }
            if (!S.h2d_->inBox(ni, nj)) continue;  // off the map's box
            const std::int8_t gear = prim.reverse ? -1 : 1;
            const bool backwards = prim.reverse != S.query_.timeReversed;
            if (backwards && !mayReverse) continue;  // reversing only where manoeuvres are
            const bool cusp = S.gear_[s] != 0 && S.gear_[s] != gear;
            const auto stepOf = [&](double base) {
                return (backwards ? base * S.query_.settings.reversePenalty : base) + (cusp ? S.query_.cuspPenalty : 0.0);
            };
            // a motion to a state it would not improve, or to one expanded already (the search
            // never reopens one: run() passes reopen=false), is dropped by the search: not
            // checked. A cost that needs the motion's samples is computed only for a free motion
            // that its lower bound (least cost per metre, no cost layer) lets improve.
            double *cached = shapeSlot(hybrid ? 0 : k.h, p);
            const bool sampled = mapped || !cached || std::isnan(*cached);
            const std::uint32_t seen = S.known(ni, nj, nh);
            const double gSeen = seen != StateInterner::kNone ? S.space_.g(seen) : kInf;
            if (seen != StateInterner::kNone && S.space_.closed(seen)) continue;
            double step = cached && !sampled ? stepOf(*cached) : stepOf(cost.minCostPerMetre() * prim.length);
            if (!(gs + step < gSeen)) continue;
            if constexpr (!Lazy)
                if (!S.primitiveFree(at, from, prim)) continue;
            if (sampled)
            {
                // the world samples are made only where the cost needs them (the motion check
                // computes the few poses it looks at itself)
                S.worldSamples(at, prim, samples);
                if (cached && std::isnan(*cached)) *cached = cost.stepCost(from, samples, prim.length, std::abs(prim.turn));
                double base = cached ? *cached : cost.stepCost(from, samples, prim.length, std::abs(prim.turn));
                if (mapped) base += S.query_.mapCost(samples, prim.length) * cost.costPerMetreOfPenalty();
                step = stepOf(base);
                if (!(gs + step < gSeen)) continue;
            }
            if constexpr (Lazy)
            {
                const std::uint32_t id = seen != StateInterner::kNone ? seen : S.intern(ni, nj, nh);
                if (hKept.size() <= id) hKept.resize(std::max<std::size_t>(2 * hKept.size(), id + 1), std::nan(""));
                // the exact h if known, else a bound that costs no 2D search (lazyAstar()
                // computes the exact one when the entry comes up)
                const double hn = std::isnan(hKept[id]) ? hWith(end, ni, nj, nh, true) : hKept[id];
                if (hn == kInf || beyondBound(gs + step, hn)) continue;
                emit(id, step, hn, std::uint32_t(p));
            }
            else
            {
                const double hn = hAt(end, ni, nj, nh);
                if (hn == kInf || beyondBound(gs + step, hn)) continue;
                const std::uint32_t id = seen != StateInterner::kNone ? seen : S.intern(ni, nj, nh);
                emit(id, step, [this, id, p, hn, gear, end] {
                    S.prim_[id] = std::int16_t(p);
                    S.gear_[id] = gear;
                    S.pose_[id] = end;
                    return hn;
                });
            }
        }
    }
};

namespace
{
/// Paper I's ordering (LatticeCostModel::customPriority()).
struct PriorityExpander : CarExpander
{
    double priority(double g, double h, std::uint32_t s) const { return cost.priority(g, h, poseOf(s)); }
};
}  // namespace

std::vector<Pose2> CarLatticeSearch::buildPath(std::uint32_t end) const
{
    std::vector<std::uint32_t> chain;
    for (std::uint32_t s = end; s != SearchSpace::kNoParent; s = space_.parent(s)) chain.push_back(s);
    std::reverse(chain.begin(), chain.end());
    Pose2 start = statePose(chain.front());
    start.x = query_.start.x;
    start.y = query_.start.y;
    std::vector<Pose2> path{start};
    for (std::size_t n = 1; n < chain.size(); ++n)
    {
        const auto kp = unpack(states_.key(chain[n - 1]));
        const LatticePrimitive &p = lattice_->primitives(kp.h)[std::size_t(prim_[chain[n]])];
        std::vector<Pose2> w;
        worldSamples(pose_[chain[n - 1]], p, w);
        for (Pose2 q : w)
        {
            q.yaw = wrapYaw(q.yaw);
            path.push_back(q);
        }
    }
    if (shotFrom_ == end) path.insert(path.end(), shot_.begin(), shot_.end());
    return path;
}

CarLatticeResult CarLatticeSearch::run(const CarLatticeQuery &q, const LatticeCostModel &cost,
                                       const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    // run again in one family query (a probe, a fallback round): its 2D bounds resume
    const bool again = setFrame(q);
    CarLatticeResult out;
    const double c = lattice_->cell();
    const int H = lattice_->neighbourCount();  // the 2D graph's steps (the lattice's headings)
    // (the safety margin's search reads its first search's bounds: borrowBounds())
    const bool borrowed = borrowBounds(q, cost, cancelled);
    if (!borrowed && !ownH2d_)
    {
        // made once, its node storage reused by every run (ObstacleHeuristic::reset)
        std::vector<std::array<int, 2>> steps;
        for (int h = 0; h < H; ++h) steps.push_back({lattice_->vi(h), lattice_->vj(h)});
        ownH2d_ = std::make_unique<ObstacleHeuristic>(steps, c, [this](int i, int j) { return fitsAtNode(i, j); });
        // a step along heading k is lined up with axis k mod (H / 2): the car fits there at
        // that heading or its reverse
        std::vector<int> axis;
        for (int h = 0; h < H; ++h) axis.push_back(h % (H / 2));
        ownH2d_->setAxisTest(axis, [this, H](int i, int j) {
            const std::array<double, 2> p = nodeXY(i, j);  // (the axes' yaws are the collision model's)
            return std::uint16_t(col_->axesStanding(p[0], p[1], H / 2));
        });
    }
    const bool kept = again && !borrowed && h2d_ == ownH2d_.get() && !cost.weighted();
    if (!borrowed) h2d_ = ownH2d_.get();
    h2d_->setCancel(cancelled);
    cancelled_ = &cancelled;
    reclaimCollision();
    if (cost.weighted())
        h2d_->setWeight([this, &cost](int i, int j) { return cost.nodeWeight(nodePose(i, j, 0)); });
    else
        h2d_->setWeight(nullptr);
    // seeds: the nodes round the goal, at their straight-line distance
    const double gx = cphi_ * (q.goal.x - ox_) + sphi_ * (q.goal.y - oy_), gy = -sphi_ * (q.goal.x - ox_) + cphi_ * (q.goal.y - oy_);
    seedRadius_ = 1.5 * c;
    std::vector<std::pair<std::array<int, 2>, double>> seeds;
    for (int i = int(std::floor(gx / c)) - 1; i <= int(std::ceil(gx / c)) + 1; ++i)
        for (int j = int(std::floor(gy / c)) - 1; j <= int(std::ceil(gy / c)) + 1; ++j)
        {
            const double d = std::hypot(i * c - gx, j * c - gy);
            if (d <= seedRadius_) seeds.push_back({{i, j}, d});
        }
    if (!borrowed)
    {
        if (!kept) h2d_->reset(i0_, j0_, ni_, nj_, seeds, 0, 0);
        use2d_ = q.aim;
        useTurn_ = false;
    }
    if (use2d_ && h2d_->distance(0, 0) == kInf)
    {
        use2d_ = false;
        out.unreachable = provenUnreachable(q, out.startShutIn);
        if (!out.unreachable.empty()) return out;
    }
    // the turn bound costs a search of its own over 8 axes a node: worth it where the search
    // without it runs long (corners it does not see), not on the many queries it ends quickly;
    // progress counts both searches' expansions (a fallback stage's budget reads it)
    const bool turnWanted = !useTurn_ && turnBoundApplies(q, cost);  // (not when one is borrowed)
    const bool turnLater = turnWanted && q.turnBoundAfter > 0;
    if (turnWanted && !turnLater) setUpTurnHeuristic(cost, seeds, cancelled);
    std::atomic<std::uint64_t> count{0};
    std::uint64_t before = 0;
    bool restarted = false;
    const std::function<bool()> stop = [&] {
        const std::uint64_t n = before + count.load(std::memory_order_relaxed);
        if (progress) progress->store(n, std::memory_order_relaxed);
        return (turnLater && !restarted && n >= q.turnBoundAfter) || cancelled();
    };
    SearchResult res = searchOnce(q, cost, stop, &count);
    if (turnLater && res.outcome == SearchOutcome::Cancelled && !cancelled())
    {
        restarted = true;
        before = res.expanded;
        count.store(0);
        setUpTurnHeuristic(cost, seeds, cancelled);  // (too large a box: the same search again)
        res = searchOnce(q, cost, stop, &count);
        res.expanded += before;
    }
    cancelled_ = nullptr;
    out.outcome = res.outcome;
    out.expanded = res.expanded;
    out.states = states_.size();
    out.heuristicNodes = h2d_->closedCount();
    out.turnBoundStates = useTurn_ ? turn_->closedCount() : 0;
    out.shotsTried = shotsTried_;
    const std::uint32_t end = res.outcome == SearchOutcome::Found ? res.goal : res.closest;
    if (end == SearchSpace::kNoParent) return out;
    out.exact = res.outcome == SearchOutcome::Found;
    out.path = buildPath(end);
    out.cost = space_.g(end) + (shotFrom_ == end ? shotCost_ : 0.0);
    return out;
}

SearchResult CarLatticeSearch::searchOnce(const CarLatticeQuery &q, const LatticeCostModel &cost,
                                          const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    states_.clear();
    prim_.clear();
    gear_.clear();
    pose_.clear();
    shotFrom_ = SearchSpace::kNoParent;
    shot_.clear();
    shotCost_ = 0;
    shotsTried_ = 0;
    std::vector<std::uint32_t> starts;
    for (int h = 0; h < lattice_->headings(); ++h)
        if (q.freeStartHeading ? col_->poseFree(nodePose(0, 0, h)) : h == 0) starts.push_back(intern(0, 0, h));
    // motions checked when used (lazyAstar()) where that changes nothing but the work: on a
    // node lattice (a state's pose is its node's) with costs known before the check
    const bool lazy = q.lazyChecks && !cost.customPriority() && !lattice_->hybrid() && cost.shapeOnly() && !q.mapCosts();
    SearchResult res;
    if (cost.customPriority())
    {
        PriorityExpander ex{CarExpander(*this, cost)};
        res = astar(space_, starts, ex, cancelled, progress, /*reopen=*/false, 15u);
    }
    else if (lazy)
    {
        CarExpander ex(*this, cost);
        res = lazyAstar(space_, starts, ex, cancelled, progress, 15u);
    }
    else
    {
        CarExpander ex(*this, cost);
        res = astar(space_, starts, ex, cancelled, progress, /*reopen=*/false, 15u);
    }
    return res;
}

double CarLatticeSearch::heuristicAt(int i, int j)
{
    LengthCost len;
    CarExpander ex(*this, len);
    return ex.hNode(i, j);
}

}  // namespace gridcar
