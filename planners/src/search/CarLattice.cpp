#include "gridcar/planners/search/CarLattice.h"

#include "gridcar/core/Angles.h"
#include "gridcar/curves/CarCurves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gridcar
{
namespace
{
bool positive(double v) { return std::isfinite(v) && v > 0.0; }
}  // namespace

CarLattice::CarLattice(const CarLatticeConfig &config) : config_(config)
{
    if (!positive(config.cell)) throw std::invalid_argument("car lattice: cell size must be a finite number > 0");
    if (!positive(config.turnRadius)) throw std::invalid_argument("car lattice: turning radius must be a finite number > 0");
    for (double r : config.extraRadii)
        if (!positive(r) || r <= config.turnRadius)
            throw std::invalid_argument("car lattice: every further arc radius must be a finite number > the turning radius");
    if (!positive(config.spacing)) throw std::invalid_argument("car lattice: sample spacing must be a finite number > 0");
    if (!(std::isfinite(config.reach) && config.reach >= 0.0))
        throw std::invalid_argument("car lattice: vehicle reach must be a finite number >= 0");
    if (config.hybrid ? (config.headings < 16 || config.headings > 360) : (config.headings != 8 && config.headings != 16))
        throw std::invalid_argument(config.hybrid ? "car lattice: hybrid heading bins must be 16 to 360, got " +
                                                        std::to_string(config.headings)
                                                  : "car lattice: headings must be 8 or 16 (directions of lattice vectors), got " +
                                                        std::to_string(config.headings));
    // first-quadrant vectors, counter-clockwise; the others are their rotations by 90 degrees
    const std::vector<std::array<int, 2>> quadrant =
        config.headings == 8 ? std::vector<std::array<int, 2>>{{1, 0}, {1, 1}} :
                               std::vector<std::array<int, 2>>{{1, 0}, {2, 1}, {1, 1}, {1, 2}};
    for (int q = 0; q < 4; ++q)
        for (auto v : quadrant)
        {
            for (int k = 0; k < q; ++k) v = {-v[1], v[0]};
            vec_.push_back(v);
            stepYaw_.push_back(std::atan2(double(v[1]), double(v[0])));
        }
    if (config.hybrid)
    {
        for (int h = 0; h < config.headings; ++h) yaw_.push_back(wrapYaw(2 * M_PI * h / config.headings));
        addHybrid();
        cacheSampleTrig();
        return;
    }
    yaw_ = stepYaw_;
    prims_.resize(std::size_t(config.headings));
    for (int h = 0; h < config.headings; ++h)
    {
        addStraight(h);
        for (int dir : {1, -1})
        {
            if (!addTurn(h, dir, config.turnRadius)) throw std::logic_error("car lattice: no turn primitive found");
            for (double r : config.extraRadii) addTurn(h, dir, r);
        }
        // clothoid turns start and end at curvature 0: a corner made of one-step turns would
        // straighten the wheel between steps (a wider, longer corner). Turns of several steps,
        // up to 90 degrees, are one clothoid turn each, at full lock where they need it.
        if (config.curvatureRate > 0)
            for (int steps = 2; steps <= config.headings / 4; ++steps)
                for (int dir : {steps, -steps}) addTurn(h, dir, config.turnRadius);
    }
    if (config.reverse)
        for (int h = 0; h < config.headings; ++h) addReverse(h);
    cacheSampleTrig();
}

void CarLattice::cacheSampleTrig()
{
    for (auto &set : prims_)
        for (LatticePrimitive &p : set)
        {
            p.sampleCS.clear();
            for (const Pose2 &q : p.samples) p.sampleCS.push_back({std::cos(q.yaw), std::sin(q.yaw)});
        }
}

void CarLattice::addReverse(int h)
{
    // backwards from heading h = the forward primitives from the opposite heading, the body
    // turned round: the same positions, every yaw + pi
    const int n = headings(), back = (h + n / 2) % n;
    const std::size_t forward = prims_[std::size_t(back)].size();  // only the forward ones
    for (std::size_t k = 0; k < forward; ++k)
    {
        const LatticePrimitive &f = prims_[std::size_t(back)][k];
        if (f.reverse) continue;
        LatticePrimitive p = f;
        p.from = h;
        p.to = (f.to + n / 2) % n;
        p.reverse = true;
        for (Pose2 &q : p.samples) q.yaw = wrapYaw(q.yaw + M_PI);
        p.samples.back().yaw = yaw_[std::size_t(p.to)];
        prims_[std::size_t(h)].push_back(std::move(p));
    }
}

void CarLattice::addHybrid()
{
    // one primitive length: a whole number of bins of heading on an arc of R_min, and at least
    // 1.5 cells so that every primitive leaves its start's cell
    const double bin = 2 * M_PI / config_.headings, R = config_.turnRadius;
    const double length = R * bin * std::max(1.0, std::ceil(1.5 * config_.cell / (R * bin) - 1e-9));
    prims_.assign(1, {});
    std::vector<double> radii{0.0, R};
    for (double r : config_.extraRadii) radii.push_back(r);
    for (int gear : config_.reverse ? std::vector<int>{1, -1} : std::vector<int>{1})
        for (double r : radii)
            for (Steer steer : r == 0 ? std::vector<Steer>{Steer::Straight} : std::vector<Steer>{Steer::Left, Steer::Right})
            {
                LatticePrimitive p;
                p.length = length;
                p.radius = r;
                p.reverse = gear < 0;
                const CurveSegment seg{steer, gear * length};
                const Pose2 end = driveSegment({}, seg, r > 0 ? r : 1.0);
                p.turn = end.yaw;
                // with a curvature rate, the same change of heading as a clothoid turn (longer)
                const bool clothoid = r > 0 && config_.curvatureRate > 0;
                const double delta = steer == Steer::Left ? length / r : -length / r;
                if (clothoid) p.length = turnLength(delta, r);
                const double travel = r > 0 ? p.length * (1.0 + config_.reach / r) : p.length;
                const int n = std::max(1, int(std::ceil(travel / config_.spacing - 1e-9)));
                for (int k = 1; k <= n; ++k)
                {
                    if (!clothoid)
                    {
                        p.samples.push_back(driveSegment({}, {steer, gear * length * k / n}, r > 0 ? r : 1.0));
                        continue;
                    }
                    const Pose2 q = turnPose(delta, r, p.length * k / n);  // backwards: mirrored along x
                    p.samples.push_back(gear > 0 ? q : Pose2{-q.x, q.y, -q.yaw});
                }
                if (clothoid) p.turn = p.samples.back().yaw;
                prims_[0].push_back(std::move(p));
            }
}

int CarLattice::nearestHeading(double yaw) const
{
    if (config_.hybrid)
    {
        const int n = config_.headings;
        const int h = int(std::lround(wrapAngle(yaw) / (2 * M_PI / n)));
        return ((h % n) + n) % n;
    }
    int best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (int h = 0; h < headings(); ++h)
    {
        const double d = std::abs(wrapAngle(yaw - yaw_[h]));
        if (d < bestD)
        {
            bestD = d;
            best = h;
        }
    }
    return best;
}

void CarLattice::addStraight(int h)
{
    LatticePrimitive p;
    p.di = vec_[h][0];
    p.dj = vec_[h][1];
    p.from = p.to = h;
    p.length = config_.cell * std::hypot(double(p.di), double(p.dj));
    sample(p, p.length);
    prims_[h].push_back(std::move(p));
}

const ClothoidTurn &CarLattice::clothoidTurn(double R) const
{
    auto it = turns_.find(R);
    if (it == turns_.end()) it = turns_.emplace(R, ClothoidTurn(R, config_.curvatureRate)).first;
    return it->second;
}

double CarLattice::turnLength(double delta, double R) const
{
    if (!(config_.curvatureRate > 0)) return R * std::abs(delta);
    return clothoidTurn(R).length(delta);  // clothoid, arc at 1 / R (or a lower peak), clothoid
}

Pose2 CarLattice::turnPose(double delta, double R, double s) const
{
    if (!(config_.curvatureRate > 0))
    {
        const double phi = (delta >= 0 ? 1.0 : -1.0) * s / R;
        return {R * std::sin(std::abs(phi)), (delta >= 0 ? 1.0 : -1.0) * R * (1.0 - std::cos(phi)), phi};
    }
    return clothoidTurn(R).pose(delta, s);
}

bool CarLattice::addTurn(int h, int dir, double R)
{
    const int n = headings();
    const int to = ((h + dir) % n + n) % n;
    const double t1 = yaw_[h], t2 = yaw_[to];
    const double delta = wrapAngle(t2 - t1);  // signed, 0 < |delta| <= 90 degrees
    const double c = config_.cell, sg = delta > 0 ? 1.0 : -1.0;
    // displacement of the curved part alone (an arc of curvature sg / R, or a clothoid turn,
    // from yaw t1 to t2)
    (void)sg;
    const Pose2 local = turnPose(delta, R, turnLength(delta, R));
    const double ax = std::cos(t1) * local.x - std::sin(t1) * local.y, ay = std::sin(t1) * local.x + std::cos(t1) * local.y;
    const double u1x = std::cos(t1), u1y = std::sin(t1), u2x = std::cos(t2), u2y = std::sin(t2);
    const double det = u1x * u2y - u1y * u2x;
    const int W = int(std::ceil((2 * R + turnLength(delta, R) + 3 * c) / c)) + 2;
    LatticePrimitive best;
    double bestLen = std::numeric_limits<double>::infinity(), bestS1 = 0;
    for (int i = -W; i <= W; ++i)
        for (int j = -W; j <= W; ++j)
        {
            const double rx = i * c - ax, ry = j * c - ay;
            const double s1 = (rx * u2y - ry * u2x) / det, s2 = (u1x * ry - u1y * rx) / det;
            if (s1 < -1e-9 || s2 < -1e-9) continue;
            const double len = std::max(s1, 0.0) + std::max(s2, 0.0) + turnLength(delta, R);
            if (len < bestLen - 1e-9)
            {
                bestLen = len;
                best.di = i;
                best.dj = j;
                bestS1 = std::max(s1, 0.0);
            }
        }
    if (!std::isfinite(bestLen)) return false;
    for (const LatticePrimitive &p : prims_[std::size_t(h)])
        if (p.to == to && p.di == best.di && p.dj == best.dj) return true;  // a tighter turn lands there already
    best.from = h;
    best.to = to;
    best.length = bestLen;
    best.turn = delta;
    best.radius = R;
    sample(best, bestS1);
    prims_[h].push_back(std::move(best));
    return true;
}

void CarLattice::sample(LatticePrimitive &p, double s1) const
{
    const double t1 = yaw_[p.from], R = p.radius > 0 ? p.radius : config_.turnRadius;
    const double arc = p.turn != 0 ? turnLength(p.turn, R) : 0.0;  // the curved part's length
    const double travel = arc > 0 ? p.length * (1.0 + config_.reach / R) : p.length;
    const int n = std::max(1, int(std::ceil(travel / config_.spacing - 1e-9)));
    const double u1x = std::cos(t1), u1y = std::sin(t1);
    const double t2 = t1 + p.turn;
    const Pose2 endLocal = arc > 0 ? turnPose(p.turn, R, arc) : Pose2{};
    const double ax = u1x * endLocal.x - u1y * endLocal.y, ay = u1y * endLocal.x + u1x * endLocal.y;
    // arc-length parameter at n points; the straight parts move points by ds, the arc by at most
    // ds (1 + reach / R): n was chosen from the larger so every step stays under the spacing
    p.samples.clear();
    for (int k = 1; k <= n; ++k)
    {
        const double s = p.length * k / n;
        Pose2 q;
        if (s <= s1)
            q = {s * u1x, s * u1y, t1};
        else if (s <= s1 + arc)
        {
            const Pose2 l = turnPose(p.turn, R, s - s1);
            q = {s1 * u1x + u1x * l.x - u1y * l.y, s1 * u1y + u1y * l.x + u1x * l.y, t1 + l.yaw};
        }
        else
        {
            const double e = s - s1 - arc;
            q = {s1 * u1x + ax + e * std::cos(t2), s1 * u1y + ay + e * std::sin(t2), t2};
        }
        p.samples.push_back(q);
    }
    // the end is exactly the node (rounding of the parametrisation)
    p.samples.back() = {p.di * config_.cell, p.dj * config_.cell, yaw_[p.to]};
}

}  // namespace gridcar
