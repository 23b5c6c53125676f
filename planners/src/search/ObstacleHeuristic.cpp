#include "gridcar/planners/search/ObstacleHeuristic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

namespace gridcar
{
namespace
{
constexpr std::uint8_t kClosed = 1, kAsked = 2, kFree = 4, kAxes = 8;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

ObstacleHeuristic::ObstacleHeuristic(std::vector<std::array<int, 2>> steps, double cell,
                                     std::function<bool(int, int)> traversable)
  : steps_(std::move(steps)), cell_(cell), traversable_(std::move(traversable))
{
    // both directions of every step
    const std::size_t n = steps_.size();
    for (std::size_t k = 0; k < n; ++k)
    {
        const std::array<int, 2> back{-steps_[k][0], -steps_[k][1]};
        if (std::find(steps_.begin(), steps_.end(), back) == steps_.end()) steps_.push_back(back);
    }
    for (const auto &s : steps_) stepLen_.push_back(cell_ * std::hypot(double(s[0]), double(s[1])));
}

bool ObstacleHeuristic::traversable(int i, int j)
{
    if (!inBox(i, j)) return false;
    Node &x = at(idx(i, j));
    if (!(x.state & kAsked)) x.state |= kAsked | (traversable_(i, j) ? kFree : 0);
    return (x.state & kFree) != 0;
}

void ObstacleHeuristic::push(std::size_t n, double g)
{
    at(n).g = g;
    const int i = int(n % std::size_t(ni_)) + i0_, j = int(n / std::size_t(ni_)) + j0_;
    const double di = i - ti_, dj = j - tj_;
    const double h = cell_ * std::sqrt(di * di + dj * dj);
    heap_.push_back({g + h, g, std::uint32_t(n)});
    std::push_heap(heap_.begin(), heap_.end());
}

void ObstacleHeuristic::reset(int i0, int j0, int ni, int nj, const std::vector<std::pair<std::array<int, 2>, double>> &seeds,
                              int ti, int tj)
{
    if (ni <= 0 || nj <= 0 || double(ni) * double(nj) > 4.0e8)
        throw std::invalid_argument("obstacle heuristic: node box must be non-empty and at most 4e8 nodes");
    i0_ = i0;
    j0_ = j0;
    ni_ = ni;
    nj_ = nj;
    const std::size_t need = std::size_t(ni) * std::size_t(nj);
    if (nodeCount_ < need)
    {
        nodes_.reset(static_cast<Node *>(std::calloc(need, sizeof(Node))));
        if (!nodes_) throw std::bad_alloc();
        nodeCount_ = need;
        epoch_ = 0;
    }
    if (++epoch_ == 0)  // wrapped: every stamp is stale again
    {
        for (std::size_t n = 0; n < nodeCount_; ++n) nodes_[n].stamp = 0;
        epoch_ = 1;
    }
    heap_.clear();
    closedCount_ = 0;
    stopped_ = false;
    poll_ = PollSchedule(1023);
    ti_ = ti;
    tj_ = tj;
    for (const auto &s : seeds)
    {
        if (!inBox(s.first[0], s.first[1])) continue;
        const std::size_t n = idx(s.first[0], s.first[1]);
        if (s.second < at(n).g) push(n, s.second);
    }
}

void ObstacleHeuristic::setAxisTest(std::vector<int> stepAxis, std::function<std::uint16_t(int, int)> fitsAxes)
{
    stepAxis_ = std::move(stepAxis);
    stepAxis_.resize(steps_.size(), -1);  // reverse steps added by the constructor: no test
    fitsAxes_ = std::move(fitsAxes);
}

bool ObstacleHeuristic::axisFits(std::size_t n, int i, int j, int axis)
{
    Node &x = at(n);
    if (!(x.state & kAxes))
    {
        x.state |= kAxes;
        x.axisOk = fitsAxes_(i, j);
    }
    return (x.axisOk >> axis) & 1u;
}

bool ObstacleHeuristic::fitsAxis(int i, int j, int axis)
{
    if (!inBox(i, j)) return false;
    if (!fitsAxes_) return traversable(i, j);
    return axisFits(idx(i, j), i, j, axis);
}

double ObstacleHeuristic::weightAt(std::size_t n, int i, int j)
{
    Node &x = at(n);
    if (x.w < 0) x.w = float(std::max(1.0, weight_(i, j)));
    return x.w;
}

bool ObstacleHeuristic::expandUntil(std::size_t target)
{
    while (!heap_.empty())
    {
        Entry e;
        if (!popUnlessCancelled(heap_, poll_, closedCount_ + 1, cancelled_, stopped_, e)) return false;
        Node &en = at(e.n);
        if ((en.state & kClosed) || e.g > en.g) continue;
        en.state |= kClosed;
        ++closedCount_;
        const int i = int(e.n % std::size_t(ni_)) + i0_, j = int(e.n / std::size_t(ni_)) + j0_;
        for (std::size_t k = 0; k < steps_.size(); ++k)
        {
            const int a = i + steps_[k][0], b = j + steps_[k][1];
            if (!inBox(a, b)) continue;
            const std::size_t m = idx(a, b);
            if (at(m).state & kClosed) continue;
            if (fitsAxes_ && stepAxis_[k] >= 0)
            {
                // the oriented test implies the node test
                if (!(axisFits(e.n, i, j, stepAxis_[k]) && axisFits(m, a, b, stepAxis_[k]))) continue;
            }
            else if (!traversable(a, b))
                continue;
            double len = stepLen_[k];
            if (weight_) len *= std::min(weightAt(e.n, i, j), weightAt(m, a, b));
            const double ng = e.g + len;
            if (ng >= at(m).g) continue;
            push(m, ng);
        }
        if (e.n == target) return true;
    }
    return false;
}

double ObstacleHeuristic::lowerBound(int i, int j) const
{
    if (!inBox(i, j)) return kInf;
    const Node &x = nodes_[idx(i, j)];
    if (x.stamp == epoch_)
    {
        if (x.state & kClosed) return x.g;
        if ((x.state & kAsked) && !(x.state & kFree)) return kInf;
    }
    if (stopped_) return -1.0;
    if (heap_.empty()) return kInf;
    const double di = i - ti_, dj = j - tj_;
    // (less a rounding's worth: the key and the guide were summed in another order)
    return std::max(0.0, (heap_.front().f - cell_ * std::sqrt(di * di + dj * dj)) * (1.0 - 1e-12));
}

double ObstacleHeuristic::distance(int i, int j)
{
    if (!inBox(i, j)) return kInf;
    const std::size_t n = idx(i, j);
    if (at(n).state & kClosed) return at(n).g;
    if (!traversable(i, j)) return kInf;
    if (stopped_) return -1.0;
    if (expandUntil(n)) return at(n).g;
    return stopped_ ? -1.0 : kInf;
}

}  // namespace gridcar
