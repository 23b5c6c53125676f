#include "gridcar/planners/search/CarLatticeSearch.h"

#include "gridcar/core/Angles.h"

#include "gridcar/curves/CarCurves.h"
#include "gridcar/planners/search/detail/CurveSampling.h"

#include <algorithm>
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
    const CarLatticeConfig &cfg = lattice_->config();
    if (cfg.curvatureRate > 0 && !cfg.reverse) clothoid_ = std::make_unique<ClothoidTurn>(cfg.turnRadius, cfg.curvatureRate);
}

bool CarLatticeSearch::clothoidShot(const Pose2 &from, const Pose2 &to, std::vector<Pose2> &poses, double &length,
                                    double &turn) const
{
    const double K = 1.0 / clothoid_->radius();
    for (const ClothoidCurve &c : clothoidCurves(from, to, *clothoid_, 2))
    {
        // each part sampled on its own, no body point moving more than the lattice's spacing
        std::vector<double> arc;
        double at = 0;
        for (const double l : {clothoid_->length(c.delta1), c.straight, clothoid_->length(c.delta2)})
        {
            if (l < 1e-6)  // (a deflection of 1e-13 rad is a turn of 1e-7 m: no pose of its own)
            {
                at += l;
                continue;
            }
            detail::appendArcs(l, l * (1.0 + col_->reach() * K), lattice_->config().spacing, at, arc);
        }
        if (arc.empty()) continue;
        const auto poseAt = [&](int i) { return clothoidCurvePose(c, *clothoid_, arc[std::size_t(i - 1)]); };
        if (!shotFree(from, int(arc.size()), poseAt)) continue;
        poses.clear();
        for (int i = 1; i <= int(arc.size()); ++i) poses.push_back(poseAt(i));
        length = c.length;
        turn = c.turning();
        return true;
    }
    return false;
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

bool CarLatticeSearch::shotFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt) const
{
    // blocks of 64 poses, the run's termination condition polled between them
    constexpr int kBlock = 64;
    Pose2 blockStart = from;
    for (int b = 0; b < n; b += kBlock)
    {
        if (b > 0 && cancelled_ && (*cancelled_)()) return false;
        const int m = std::min(kBlock, n - b);
        if (!col_->curveFree(blockStart, m, [&](int i) { return poseAt(b + i); }, lattice_->margin())) return false;
        blockStart = poseAt(b + m);
    }
    return true;
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

Pose2 CarLatticeSearch::latticePose(const Pose2 &w) const
{
    const double dx = w.x - ox_, dy = w.y - oy_;
    return {cphi_ * dx + sphi_ * dy, -sphi_ * dx + cphi_ * dy, wrapYaw(w.yaw - phi_)};
}

void CarLatticeSearch::setFrame(const CarLatticeQuery &q)
{
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
}

namespace
{
/// With a cost layer the analytic expansion ends the search at once, so it must not cross
/// ground costlier than the query's start or goal: the search then goes round a costly band,
/// not through it (measured from the query's start, not the shot's, or a node just inside
/// the band would shoot through the rest). True when @p poses' mean cost exceeds that + 8.
bool crossesCostlierGround(const CarLatticeQuery &q, const std::vector<Pose2> &poses)
{
    if (!q.layered() || poses.empty()) return false;
    const auto costAt = [&q](const Pose2 &p) {
        const Cell c = q.layer->worldToCell(p.x, p.y);
        return double(q.layer->cost(c.col, c.row));
    };
    double mean = 0;
    for (const Pose2 &p : poses) mean += costAt(p);
    return mean / double(poses.size()) > std::max(costAt(q.start), costAt(q.goal)) + 8.0;
}
}  // namespace


bool CarLatticeSearch::tryShot(std::uint32_t s, const LatticeCostModel &cost, std::uint64_t expansions)
{
    const auto k = unpack(states_.key(s));
    const Pose2 from = statePose(s);
    const Pose2 &g = query_.goal;
    const double e = std::hypot(g.x - from.x, g.y - from.y);
    const double R = lattice_->config().turnRadius, c = lattice_->cell();
    if (e > 30 * R + 10 * c) return false;
    const bool near = e <= 2 * R + 2 * c;
    if (!near)
    {
        if (expansions % 8 != 0) return false;
        // where the obstacle-aware distance is well above the straight line, something is in
        // the way: a Dubins curve (nearly straight this far out) would hit it
        const double d = use2d_ ? h2d_->distance(k.i, k.j) : -1.0;
        if (d > 1.1 * e + R) return false;
    }
    std::vector<double> yaws;
    if (query_.goalYawTolerance < 0)
    {
        yaws.push_back(std::atan2(g.y - from.y, g.x - from.x));
        for (int h = 0; h < lattice_->neighbourCount(); ++h) yaws.push_back(wrapYaw(phi_ + lattice_->stepYaw(h)));
    }
    else
    {
        yaws.push_back(g.yaw);
        if (query_.goalYawTolerance > 0)
            for (double d : {-query_.goalYawTolerance, query_.goalYawTolerance}) yaws.push_back(wrapYaw(g.yaw + d));
    }
    // gridcar's Dubins / Reeds-Shepp curves (OMPL 1.5.2's asserts on rounding errors and would
    // abort); near the goal the few shortest words per end yaw, since in a tight spot the
    // shortest one is often blocked where a slightly longer one is free
    const bool rs = lattice_->config().reverse;
    const int words = near ? (rs ? 4 : 2) : 1;
    std::vector<std::pair<double, double>> cand;  // (length, index)
    std::vector<CarCurve> curves;
    std::vector<double> curveYaw;
    for (double y : yaws)
    {
        // the curve family of the primitive set's directions: Reeds-Shepp when it reverses
        const Pose2 to{g.x, g.y, y};
        for (const CarCurve &c : rs ? reedsSheppCurves(from, to, R, words) : dubinsCurves(from, to, R, words))
            if (c.length <= e + 2 * M_PI * R)
            {
                cand.push_back({c.length, double(curves.size())});
                curves.push_back(c);
                curveYaw.push_back(y);
            }
    }
    std::sort(cand.begin(), cand.end());
    const std::size_t tries = near ? (rs ? 6u : 3u) : 1u;
    if (cand.size() > tries) cand.resize(tries);
    std::vector<double> arc;  // arc length of each sampled pose along the curve
    for (const auto &candidate : cand)
    {
        const double len = candidate.first;  // a plain variable: lambdas may capture it (C++17)
        const double index = candidate.second;
        ++shotsTried_;
        const CarCurve &path = curves[std::size_t(index)];
        const double y = curveYaw[std::size_t(index)];
        detail::sampleArcs(path, col_->reach(), lattice_->config().spacing, arc);
        const int n = int(arc.size());
        auto poseAt = [&](int i) {
            Pose2 p = curvePose(from, path, std::min(arc[std::size_t(i - 1)], len));
            p.yaw = wrapYaw(p.yaw);
            return p;
        };
        if (cancelled_ && (*cancelled_)()) return false;  // the loop then stops at its next poll
        const bool free = shotFree(from, n, poseAt);
        if (!free) continue;
        double turn = 0, forward = 0, backward = 0;
        for (int seg = 0; seg < path.count; ++seg)
        {
            const CurveSegment &sg = path.segments[std::size_t(seg)];
            if (sg.steer != Steer::Straight) turn += std::abs(sg.length) / R;
            (sg.length < 0 ? backward : forward) += std::abs(sg.length);
        }
        // gear changes: the curve's cusps, and one before it when it sets off in the other gear
        int gearChanges = path.cusps();
        for (int seg = 0; seg < path.count; ++seg)
            if (path.segments[std::size_t(seg)].length != 0)
            {
                const int first = path.segments[std::size_t(seg)].length < 0 ? -1 : 1;
                if (gear_[s] != 0 && gear_[s] != first) ++gearChanges;
                break;
            }
        std::vector<Pose2> poses;
        if (clothoid_)
        {
            // the Dubins curve's arcs break the curvature rate: its clothoid counterpart (the
            // free Dubins curve only tells where one is worth computing)
            if (!clothoidShot(from, {g.x, g.y, y}, poses, forward, turn)) continue;
        }
        else
        {
            poses.reserve(std::size_t(n));
            for (int i = 1; i <= n; ++i) poses.push_back(poseAt(i));
        }
        poses.back() = {g.x, g.y, y};
        if (crossesCostlierGround(query_, poses)) continue;
        shot_ = std::move(poses);
        shotFrom_ = s;
        if (query_.timeReversed) std::swap(forward, backward);  // driven in the other gear
        shotCost_ = cost.stepCost(from, shot_, forward + query_.settings.reversePenalty * backward, turn) +
                    gearChanges * query_.cuspPenalty +
                    query_.layerCost(shot_, forward + backward) * cost.costPerMetreOfPenalty();
        return true;
    }
    return false;
}

}  // namespace gridcar
