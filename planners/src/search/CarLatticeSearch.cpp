#include "gridcar/planners/search/CarLatticeSearch.h"

#include "gridcar/core/Angles.h"


#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <queue>

namespace gridcar
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
}

CarLatticeSearch::CarLatticeSearch(const FootprintChecker &checker, std::shared_ptr<const CarLattice> lattice)
  : CarLatticeSearch(std::make_shared<FootprintCollision>(checker), std::move(lattice))
{
}


CarLatticeSearch::CarLatticeSearch(std::shared_ptr<CarCollision> collision, std::shared_ptr<const CarLattice> lattice)
  : col_(std::move(collision)), lattice_(std::move(lattice))
{
    fc_ = dynamic_cast<const FootprintCollision *>(col_.get());
    ratio_ = measureRatio();
    analytic_ = std::make_unique<AnalyticExpansion>(*col_, *lattice_);
}

CarLatticeSearch::~CarLatticeSearch() = default;

double CarLatticeSearch::measureRatio() const
{
    // open-space distances of the 2D graph (the headings' vectors both ways) from the origin
    const CarLattice &L = *lattice_;
    int W = L.hybrid() ? 24 : 1;
    for (int h = 0; h < L.headings(); ++h)
        for (const auto &p : L.primitives(h)) W = std::max({W, std::abs(p.di), std::abs(p.dj)});
    W += 3;
    const int n = 2 * W + 1;
    std::vector<double> dist(std::size_t(n) * n, kInf);
    using E = std::pair<double, int>;
    std::priority_queue<E, std::vector<E>, std::greater<E>> pq;
    dist[std::size_t(W) * n + W] = 0;
    pq.push({0.0, W * n + W});
    while (!pq.empty())
    {
        const auto [d, k] = pq.top();
        pq.pop();
        if (d > dist[std::size_t(k)]) continue;
        const int x = k % n, y = k / n;
        for (int h = 0; h < L.neighbourCount(); ++h)
        {
            const int a = x + L.vi(h), b = y + L.vj(h);
            if (a < 0 || b < 0 || a >= n || b >= n) continue;
            const double nd = d + L.cell() * std::hypot(double(L.vi(h)), double(L.vj(h)));
            if (nd < dist[std::size_t(b) * n + a])
            {
                dist[std::size_t(b) * n + a] = nd;
                pq.push({nd, b * n + a});
            }
        }
    }
    double ratio = 1.0;
    if (L.hybrid())
    {
        // hybrid primitives end between nodes: the graph's detour over the straight line, on
        // every node of a ring far enough out that the graph's own steps fit
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a)
            {
                const double e = L.cell() * std::hypot(double(a - W), double(b - W));
                if (e >= L.cell() * (W - 5) && e <= L.cell() * (W - 3)) ratio = std::max(ratio, dist[std::size_t(b) * n + a] / e);
            }
        return ratio;
    }
    for (int h = 0; h < L.headings(); ++h)
        for (const auto &p : L.primitives(h))
            ratio = std::max(ratio, dist[std::size_t(p.dj + W) * n + (p.di + W)] / p.length);
    return ratio;
}

std::uint64_t CarLatticeSearch::pack(int i, int j, int h) const
{
    return (std::uint64_t(i - i0_) * std::uint64_t(nj_) + std::uint64_t(j - j0_)) * std::uint64_t(lattice_->headings()) +
           std::uint64_t(h);
}

CarLatticeSearch::Key CarLatticeSearch::unpack(std::uint64_t k) const
{
    const auto H = std::uint64_t(lattice_->headings());
    const int h = int(k % H);
    const std::uint64_t ij = k / H;
    return {int(ij / std::uint64_t(nj_)) + i0_, int(ij % std::uint64_t(nj_)) + j0_, h};
}

std::uint32_t CarLatticeSearch::intern(int i, int j, int h)
{
    const std::uint64_t k = pack(i, j, h);
    const std::uint32_t id = states_.intern(k);
    if (id == prim_.size())  // a new state, at its node's pose until a primitive reaches it
    {
        prim_.push_back(-1);
        gear_.push_back(0);
        pose_.push_back({i * lattice_->cell(), j * lattice_->cell(), lattice_->yaw(h)});
    }
    return id;
}

Pose2 CarLatticeSearch::nodePose(int i, int j, int h) const
{
    const double x = i * lattice_->cell(), y = j * lattice_->cell();
    return {ox_ + cphi_ * x - sphi_ * y, oy_ + sphi_ * x + cphi_ * y, wrapYaw(phi_ + lattice_->yaw(h))};
}

Pose2 CarLatticeSearch::sampleWorld(const Pose2 &at, double c, double s, const Pose2 &b) const
{
    // a hybrid lattice's samples are body-frame, turned to the state's own yaw; a node's are
    // lattice-frame offsets with their own yaw (wrapped in buildPath)
    if (lattice_->hybrid()) return toWorld({at.x + c * b.x - s * b.y, at.y + s * b.x + c * b.y, at.yaw + b.yaw});
    return toWorld({at.x + b.x, at.y + b.y, b.yaw});
}

void CarLatticeSearch::worldSamples(const Pose2 &at, const LatticePrimitive &p, std::vector<Pose2> &out) const
{
    out.clear();
    const bool turned = lattice_->hybrid();  // (a node's samples need no turning)
    const double c = turned ? std::cos(at.yaw) : 1.0, s = turned ? std::sin(at.yaw) : 0.0;
    for (const Pose2 &b : p.samples) out.push_back(sampleWorld(at, c, s, b));
}

bool CarLatticeSearch::primitiveFree(const Pose2 &at, const Pose2 &from, const LatticePrimitive &p) const
{
    const bool turned = lattice_->hybrid();  // (a node's samples need no turning)
    const double c = turned ? std::cos(at.yaw) : 1.0, s = turned ? std::sin(at.yaw) : 0.0;
    const int n = int(p.samples.size());
    if (!fc_) return curveFree(from, n, [&](int i) { return sampleWorld(at, c, s, p.samples[std::size_t(i - 1)]); });
    // a sample's world yaw is the frame's (and a hybrid state's own) plus its own: its cosine
    // and sine by turning the primitive's (with no turn at all, as in a frame of yaw 0, the
    // same bits as std::cos and std::sin of the sum)
    const double cw = cphi_ * c - sphi_ * s, sw = sphi_ * c + cphi_ * s;
    return fc_->curveFreeOriented(from, n, [&](int i) {
        const std::size_t k = std::size_t(i - 1);
        const auto &t = p.sampleCS[k];
        return OrientedPose{sampleWorld(at, c, s, p.samples[k]), cw * t[0] - sw * t[1], sw * t[0] + cw * t[1]};
    }, lattice_->margin());
}

bool CarLatticeSearch::curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt) const
{
    return col_->curveFree(from, n, poseAt, lattice_->margin());
}

bool CarLatticeSearch::curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double extra) const
{
    return col_->curveFree(from, n, poseAt, lattice_->margin() + extra);
}

bool CarLatticeSearch::fitsAtNode(int i, int j) const
{
    // a relaxation with gridcar's checker, so that the heuristic stays a lower bound: false
    // only where the distance field proves the car in collision at every lattice heading
    const std::array<double, 2> p = nodeXY(i, j);
    return col_->mayStandAt(p[0], p[1]);
}

const CurveTable *CarLatticeSearch::curveTable()
{
    if (lattice_->hybrid() || !(query_.curveWithin > 0)) return nullptr;
    // at most 4 Mi entries (16 MB; 16 headings: 127 cells each way), however fine the cells
    const int h = lattice_->headings();
    const int most = int((std::sqrt(double(std::size_t(4) << 20) / (h * std::max(1, h / 4))) - 1) / 2);
    const int span = std::min(most, std::max(1, int(std::ceil(query_.curveWithin / lattice_->cell()))));
    if (!curveTable_ || curveTable_->span() != span)  // kept while the span stays
        curveTable_ = std::make_unique<CurveTable>(*lattice_, span * lattice_->cell());
    return curveTable_.get();
}

void CarLatticeSearch::reclaimCollision()
{
    std::vector<double> yaws;
    for (int h = 0; h < lattice_->neighbourCount(); ++h) yaws.push_back(phi_ + lattice_->stepYaw(h));
    col_->setHeadings(yaws);
}

Pose2 CarLatticeSearch::latticePose(const Pose2 &w) const
{
    const double dx = w.x - ox_, dy = w.y - oy_;
    return {cphi_ * dx + sphi_ * dy, -sphi_ * dx + cphi_ * dy, wrapYaw(w.yaw - phi_)};
}

bool CarLatticeSearch::setFrame(const CarLatticeQuery &q)
{
    const bool again = q.boundsEpoch != 0 && q.boundsEpoch == epoch_ && q.start.x == query_.start.x &&
                       q.start.y == query_.start.y && q.start.yaw == query_.start.yaw &&
                       q.freeStartHeading == query_.freeStartHeading && q.goal.x == query_.goal.x && q.goal.y == query_.goal.y;
    epoch_ = q.boundsEpoch;
    query_ = q;
    ox_ = q.start.x;
    oy_ = q.start.y;
    phi_ = q.freeStartHeading ? 0.0 : wrapYaw(q.start.yaw);
    cphi_ = std::cos(phi_);
    sphi_ = std::sin(phi_);
    const std::array<double, 4> box = col_->extent();
    const double c = lattice_->cell();
    double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
    for (double wx : {box[0], box[2]})
        for (double wy : {box[1], box[3]})
        {
            const double x = cphi_ * (wx - ox_) + sphi_ * (wy - oy_), y = -sphi_ * (wx - ox_) + cphi_ * (wy - oy_);
            lo[0] = std::min(lo[0], x);
            hi[0] = std::max(hi[0], x);
            lo[1] = std::min(lo[1], y);
            hi[1] = std::max(hi[1], y);
        }
    i0_ = int(std::floor(lo[0] / c)) - 1;
    j0_ = int(std::floor(lo[1] / c)) - 1;
    ni_ = int(std::ceil(hi[0] / c)) + 2 - i0_;
    nj_ = int(std::ceil(hi[1] / c)) + 2 - j0_;
    return again;
}

bool CarLatticeSearch::tryShot(std::uint32_t s, const LatticeCostModel &cost, std::uint64_t expansions)
{
    const Pose2 from = statePose(s);
    const AnalyticExpansion::Range range = analytic_->due(from, query_.goal, expansions, [&] {
        const auto k = unpack(states_.key(s));
        return use2d_ ? h2d_->distance(k.i, k.j) : -1.0;
    });
    if (range == AnalyticExpansion::Range::Out) return false;
    AnalyticShot shot;
    if (!analytic_->shoot(from, gear_[s], query_, phi_, range, cost, cancelled_, shot, shotsTried_)) return false;
    shot_ = std::move(shot.poses);
    shotFrom_ = s;
    shotCost_ = shot.cost;
    return true;
}

}  // namespace gridcar

namespace gridcar
{
bool CarLatticeSearch::turnBoundApplies(const CarLatticeQuery &q, const LatticeCostModel &cost) const
{
    // only where turning has a cost of its own that the position bounds do not see, on a node
    // lattice (a state's heading is a lattice direction) whose 2D distances are metres, towards
    // a goal the seeds stand for (a goal position, or one within their radius: a wider
    // tolerance ends paths at nodes whose walk the seeds would make turn)
    if (!use2d_ || !cost.turnBound() || !(cost.minTurnCostPerRad() > 0) || lattice_->hybrid() || cost.weighted() ||
        !(cost.minCostPerMetre() > 0))
        return false;
    return !q.inGoal || (q.goalPositionTolerance >= 0 && q.goalPositionTolerance <= seedRadius_);
}

bool CarLatticeSearch::borrowBounds(const CarLatticeQuery &q, const LatticeCostModel &cost,
                                    const std::function<bool()> &cancelled)
{
    CarLatticeSearch *d = q.boundsFrom;
    // the same graph (steps, cell, node or hybrid states, measured ratio) over the same frame
    // and box, searched by the donor's last run from the same goal, unweighted (the weights
    // would be the donor's cost model's)
    if (!d || d == this || !d->h2d_ || !d->use2d_ || !q.aim || cost.weighted() || d->query_.goal.x != q.goal.x ||
        d->query_.goal.y != q.goal.y || d->ratio_ != ratio_ || d->lattice_->cell() != lattice_->cell() ||
        d->lattice_->hybrid() != lattice_->hybrid() || d->lattice_->neighbourCount() != lattice_->neighbourCount())
        return false;
    for (int h = 0; h < lattice_->neighbourCount(); ++h)
        if (d->lattice_->vi(h) != lattice_->vi(h) || d->lattice_->vj(h) != lattice_->vj(h)) return false;
    if (d->ox_ != ox_ || d->oy_ != oy_ || d->phi_ != phi_ || d->i0_ != i0_ || d->j0_ != j0_ || d->ni_ != ni_ ||
        d->nj_ != nj_)
        return false;
    h2d_ = d->h2d_;
    use2d_ = true;
    seedRadius_ = 1.5 * lattice_->cell();  // (as run() sets it)
    useTurn_ = d->useTurn_ && d->turn_ && turnBoundApplies(q, cost);
    turn_ = useTurn_ ? d->turn_ : ownTurn_.get();
    // their searches resume from here on: they poll this run's cancel
    h2d_->setCancel(cancelled);
    if (useTurn_)
    {
        turn_->setCancel(cancelled);
        d->fromStart_->setCancel(cancelled);
    }
    return true;
}

void CarLatticeSearch::setUpTurnHeuristic(const LatticeCostModel &cost,
                                          const std::vector<std::pair<std::array<int, 2>, double>> &seeds,
                                          const std::function<bool()> &cancelled)
{
    const double perRad = cost.minTurnCostPerRad(), perMetre = cost.minCostPerMetre();
    useTurn_ = false;
    const int H = lattice_->neighbourCount();
    if (!ownTurn_)
    {
        std::vector<std::array<int, 2>> steps;
        for (int h = 0; h < H; ++h) steps.push_back({lattice_->vi(h), lattice_->vj(h)});
        ownTurn_ = std::make_unique<TurnHeuristic>(steps, lattice_->cell());
        // the same 2D graph searched from the start, its node tests h2d_'s (asked once)
        fromStart_ = std::make_unique<ObstacleHeuristic>(steps, lattice_->cell(),
                                                         [this](int i, int j) { return h2d_->traversable(i, j); });
        std::vector<int> axis;
        for (int h = 0; h < H; ++h) axis.push_back(h % (H / 2));
        fromStart_->setAxisTest(axis, [this, H](int i, int j) {
            std::uint16_t m = 0;
            for (int a = 0; a < H / 2; ++a)
                if (h2d_->fitsAxis(i, j, a)) m = std::uint16_t(m | (1u << a));
            return m;
        });
    }
    turn_ = ownTurn_.get();
    turn_->setCancel(cancelled);
    fromStart_->setCancel(cancelled);
    // directed at the goal's nearest node
    std::array<int, 2> goalNode{0, 0};
    double nearest = kInf;
    for (const auto &s : seeds)
        if (s.second < nearest) nearest = s.second, goalNode = s.first;
    fromStart_->reset(i0_, j0_, ni_, nj_, {{{0, 0}, 0.0}}, goalNode[0], goalNode[1]);
    // graph units are metres of the 2D distance, divided by ratio_ when read (ObstacleBound):
    // a radian is worth ratio_ x perRad / perMetre of them
    useTurn_ = turn_->reset(*h2d_, i0_, j0_, ni_, nj_, seeds, 0, 0, ratio_ * perRad / perMetre,
                            [this](int i, int j) { return fromStart_->distance(i, j); });
}
}  // namespace gridcar

namespace gridcar
{
std::string CarLatticeSearch::provenUnreachable(const CarLatticeQuery &q, bool &startShutIn, std::size_t maxCells)
{
    // one goal position (a GoalState, or a PositionGoal within a micrometre: the reference
    // point at the goal, at its heading or any) on gridcar's checker
    if (!q.map || !q.aim || !q.shoot) return "";
    if (q.inGoal && !(q.goalPositionTolerance >= 0 && q.goalPositionTolerance <= 1e-6)) return "";
    const FootprintChecker::Reach r =
        q.map->reachability(q.start, q.freeStartHeading, q.goal, q.goalYawTolerance != 0, maxCells);
    if (r.verdict != FootprintChecker::Reach::Separated) return "";
    const double res = q.map->grid().resolution();
    // (a search from the goal back has its ends swapped)
    const bool goalShut = (r.shutEnd == 1) != q.timeReversed;
    startShutIn = !goalShut;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "no motion of the vehicle joins the start and the goal: the free space round the %s (%.1f m^2 where "
                  "the vehicle's inscribed disc fits) is shut off from the %s",
                  goalShut ? "goal" : "start", double(r.shutCells) * res * res, goalShut ? "start" : "goal");
    return buf;
}

double CarLatticeSearch::turnBoundAt(int i, int j, int h, const LatticeCostModel &cost)
{
    if (!useTurn_) return std::nan("");
    const double t = turn_->distance(i, j, h);
    if (t == kInf || t < 0) return t;
    const double perMetre = cost.minCostPerMetre();
    return t * perMetre / ratio_ - seedRadius_ * perMetre;
}

void CarLatticeSearch::forEachExpanded(const std::function<void(const Pose2 &, const Pose2 &)> &fn) const
{
    space_.forEach([&](std::uint32_t s, bool closed) {
        if (!closed) return;
        const Pose2 node = statePose(s);
        const std::uint32_t p = space_.parent(s);
        fn(node, p == SearchSpace::kNoParent ? node : statePose(p));
    });
}
}  // namespace gridcar
