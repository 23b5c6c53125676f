#include "gridcar/planners/search/TurnHeuristic.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <stdexcept>

namespace gridcar
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
/// A stored float read back as a bound: less its rounding.
double fromStored(float g) { return std::max(0.0, double(g) * (1.0 - 1e-5) - 1e-6); }
}  // namespace

TurnHeuristic::TurnHeuristic(std::vector<std::array<int, 2>> steps, double cell)
  : steps_(std::move(steps)), cell_(cell), axes_(int(steps_.size()) / 2)
{
    if (steps_.size() != 8 && steps_.size() != 16)
        throw std::invalid_argument("turn heuristic: the lattice must have 8 or 16 directions");
    std::vector<double> yaw;
    for (int a = 0; a < axes_; ++a)
    {
        const auto &v = steps_[std::size_t(a)];
        stepLen_.push_back(cell_ * std::hypot(double(v[0]), double(v[1])));
        yaw.push_back(std::atan2(double(v[1]), double(v[0])));
    }
    // the angle between neighbouring axes (axis a is heading a and its reverse, a in [0, pi))
    for (int a = 0; a < axes_; ++a)
    {
        const double prev = a == 0 ? M_PI - yaw[std::size_t(axes_ - 1)] + yaw[0] : yaw[std::size_t(a)] - yaw[std::size_t(a - 1)];
        const double next = a == axes_ - 1 ? M_PI - yaw[std::size_t(a)] + yaw[0] : yaw[std::size_t(a + 1)] - yaw[std::size_t(a)];
        rot_.push_back({std::abs(prev), std::abs(next)});
    }
}

TurnHeuristic::Node &TurnHeuristic::at(std::size_t n)
{
    Node &x = store_[n];
    if (x.stamp != epoch_)
    {
        x.stamp = epoch_;
        x.closed = 0;
        x.guide = -1.0f;
        std::fill(std::begin(x.g), std::end(x.g), std::numeric_limits<float>::infinity());
    }
    return x;
}

bool TurnHeuristic::reset(ObstacleHeuristic &nodes, int i0, int j0, int ni, int nj,
                          const std::vector<std::pair<std::array<int, 2>, double>> &seeds, int ti, int tj,
                          double rotationPerRad, std::function<double(int, int)> guide)
{
    if (ni <= 0 || nj <= 0 || double(ni) * double(nj) > kMaxNodes || !(rotationPerRad >= 0)) return false;
    const std::size_t need = std::size_t(ni) * std::size_t(nj);
    if (storeCount_ < need)
    {
        store_.reset(static_cast<Node *>(std::calloc(need, sizeof(Node))));
        if (!store_)
        {
            storeCount_ = 0;
            return false;
        }
        storeCount_ = need;
        epoch_ = 0;
    }
    if (++epoch_ == 0)  // wrapped: every stamp is stale again
    {
        for (std::size_t n = 0; n < storeCount_; ++n) store_[n].stamp = 0;
        epoch_ = 1;
    }
    nodes_ = &nodes;
    i0_ = i0;
    j0_ = j0;
    ni_ = ni;
    nj_ = nj;
    ti_ = ti;
    tj_ = tj;
    rotationPerRad_ = rotationPerRad;
    guide_ = std::move(guide);
    heap_.clear();
    closedCount_ = 0;
    stopped_ = false;
    poll_ = PollSchedule(1023);
    for (const auto &s : seeds)
    {
        if (!inBox(s.first[0], s.first[1])) continue;
        for (int a = 0; a < axes_; ++a) relax(idx(s.first[0], s.first[1]), s.first[0], s.first[1], a, s.second);
    }
    return true;
}

double TurnHeuristic::guideAt(Node &x, int i, int j)
{
    if (x.guide >= 0) return x.guide;
    double d = guide_ ? guide_(i, j) : -1.0;
    if (guide_ && d < 0) stopped_ = true;  // the guide's search was cancelled: so is this one
    if (!(d >= 0 && d < kInf))
    {
        const double di = i - ti_, dj = j - tj_;
        d = cell_ * std::sqrt(di * di + dj * dj);
    }
    // kept as a float rounded down: still a lower bound, consistent to within the rounding
    x.guide = std::nextafter(float(d), 0.0f);
    return x.guide;
}

void TurnHeuristic::relax(std::size_t n, int i, int j, int a, double g)
{
    Node &x = at(n);
    if ((x.closed >> a) & 1u || !(float(g) < x.g[a])) return;
    x.g[a] = float(g);
    heap_.push_back({g + guideAt(x, i, j), g, std::uint32_t(n), std::uint8_t(a)});
    std::push_heap(heap_.begin(), heap_.end());
}

bool TurnHeuristic::expandUntil(std::size_t target, int axis)
{
    while (!heap_.empty() && !stopped_)
    {
        Entry e;
        if (!popUnlessCancelled(heap_, poll_, closedCount_ + 1, cancelled_, stopped_, e)) return false;
        Node &x = at(e.n);
        const int a = e.a;
        if ((x.closed >> a) & 1u || float(e.g) > x.g[a]) continue;
        x.closed |= std::uint8_t(1u << a);
        ++closedCount_;
        const int i = int(e.n % std::size_t(ni_)) + i0_, j = int(e.n / std::size_t(ni_)) + j0_;
        relax(e.n, i, j, (a + axes_ - 1) % axes_, e.g + rotationPerRad_ * rot_[std::size_t(a)][0]);
        relax(e.n, i, j, (a + 1) % axes_, e.g + rotationPerRad_ * rot_[std::size_t(a)][1]);
        const auto &v = steps_[std::size_t(a)];
        for (int sign : {1, -1})
        {
            const int p = i + sign * v[0], q = j + sign * v[1];
            if (!inBox(p, q) || !(nodes_->fitsAxis(i, j, a) && nodes_->fitsAxis(p, q, a))) continue;
            relax(idx(p, q), p, q, a, e.g + stepLen_[std::size_t(a)]);
        }
        if (e.n == target && a == axis) return true;
    }
    return false;
}

double TurnHeuristic::distance(int i, int j, int heading)
{
    if (!nodes_ || !inBox(i, j)) return kInf;
    const int a = heading % axes_;
    const std::size_t n = idx(i, j);
    if ((at(n).closed >> a) & 1u) return fromStored(at(n).g[a]);
    if (!nodes_->traversable(i, j)) return kInf;
    if (stopped_) return -1.0;
    if (expandUntil(n, a)) return fromStored(at(n).g[a]);
    return stopped_ ? -1.0 : kInf;
}

}  // namespace gridcar
