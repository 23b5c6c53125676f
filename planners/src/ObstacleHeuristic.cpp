#include "gridcar/planners/search/ObstacleHeuristic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gridcar
{
namespace
{
constexpr std::uint8_t kClosed = 1, kAsked = 2, kFree = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

ObstacleHeuristic::ObstacleHeuristic(int i0, int j0, int ni, int nj, std::vector<std::array<int, 2>> steps, double cell,
                                     std::function<bool(int, int)> traversable)
  : i0_(i0), j0_(j0), ni_(ni), nj_(nj), steps_(std::move(steps)), cell_(cell), traversable_(std::move(traversable))
{
    if (ni <= 0 || nj <= 0 || double(ni) * double(nj) > 4.0e8)
        throw std::invalid_argument("obstacle heuristic: node box must be non-empty and at most 4e8 nodes");
    // both directions of every step
    const std::size_t n = steps_.size();
    for (std::size_t k = 0; k < n; ++k)
    {
        const std::array<int, 2> back{-steps_[k][0], -steps_[k][1]};
        if (std::find(steps_.begin(), steps_.end(), back) == steps_.end()) steps_.push_back(back);
    }
    for (const auto &s : steps_) stepLen_.push_back(cell_ * std::hypot(double(s[0]), double(s[1])));
    g_.assign(std::size_t(ni) * std::size_t(nj), kInf);
    state_.assign(g_.size(), 0);
}

bool ObstacleHeuristic::traversable(int i, int j)
{
    if (!inBox(i, j)) return false;
    std::uint8_t &st = state_[idx(i, j)];
    if (!(st & kAsked)) st |= kAsked | (traversable_(i, j) ? kFree : 0);
    return (st & kFree) != 0;
}

void ObstacleHeuristic::push(std::size_t n, double g)
{
    g_[n] = g;
    const int i = int(n % std::size_t(ni_)) + i0_, j = int(n / std::size_t(ni_)) + j0_;
    const double di = i - ti_, dj = j - tj_;
    const double h = cell_ * std::sqrt(di * di + dj * dj);
    heap_.push_back({g + h, g, std::uint32_t(n)});
    std::push_heap(heap_.begin(), heap_.end());
}

void ObstacleHeuristic::reset(const std::vector<std::pair<std::array<int, 2>, double>> &seeds, int ti, int tj)
{
    std::fill(g_.begin(), g_.end(), kInf);
    for (auto &s : state_) s &= std::uint8_t(~kClosed);
    heap_.clear();
    closedCount_ = 0;
    stopped_ = false;
    ti_ = ti;
    tj_ = tj;
    for (const auto &s : seeds)
    {
        if (!inBox(s.first[0], s.first[1])) continue;
        const std::size_t n = idx(s.first[0], s.first[1]);
        if (s.second < g_[n]) push(n, s.second);
    }
}

void ObstacleHeuristic::setAxisTest(std::vector<int> stepAxis, std::function<bool(int, int, int)> fitsAxis)
{
    stepAxis_ = std::move(stepAxis);
    stepAxis_.resize(steps_.size(), -1);  // reverse steps added by the constructor: no test
    fitsAxis_ = std::move(fitsAxis);
    axisAsked_.assign(g_.size(), 0);
    axisOk_.assign(g_.size(), 0);
}

bool ObstacleHeuristic::axisFits(std::size_t n, int i, int j, int axis)
{
    const auto bit = std::uint16_t(1u << axis);
    if (!(axisAsked_[n] & bit))
    {
        axisAsked_[n] |= bit;
        if (fitsAxis_(i, j, axis)) axisOk_[n] |= bit;
    }
    return (axisOk_[n] & bit) != 0;
}

double ObstacleHeuristic::weightAt(std::size_t n, int i, int j)
{
    if (w_.empty()) w_.assign(g_.size(), -1.0f);
    if (w_[n] < 0) w_[n] = float(std::max(1.0, weight_(i, j)));
    return w_[n];
}

bool ObstacleHeuristic::expandUntil(std::size_t target)
{
    while (!heap_.empty())
    {
        if (cancelled_ && (closedCount_ & 1023u) == 1023u && cancelled_())
        {
            stopped_ = true;
            return false;
        }
        std::pop_heap(heap_.begin(), heap_.end());
        const Entry e = heap_.back();
        heap_.pop_back();
        if ((state_[e.n] & kClosed) || e.g > g_[e.n]) continue;
        state_[e.n] |= kClosed;
        ++closedCount_;
        const int i = int(e.n % std::size_t(ni_)) + i0_, j = int(e.n / std::size_t(ni_)) + j0_;
        for (std::size_t k = 0; k < steps_.size(); ++k)
        {
            const int a = i + steps_[k][0], b = j + steps_[k][1];
            if (!inBox(a, b)) continue;
            const std::size_t m = idx(a, b);
            if (state_[m] & kClosed) continue;
            if (fitsAxis_ && stepAxis_[k] >= 0)
            {
                // the oriented test implies the node test
                if (!(axisFits(e.n, i, j, stepAxis_[k]) && axisFits(m, a, b, stepAxis_[k]))) continue;
            }
            else if (!traversable(a, b))
                continue;
            double len = stepLen_[k];
            if (weight_) len *= std::min(weightAt(e.n, i, j), weightAt(m, a, b));
            const double ng = e.g + len;
            if (ng >= g_[m]) continue;
            push(m, ng);
        }
        if (e.n == target) return true;
    }
    return false;
}

double ObstacleHeuristic::distance(int i, int j)
{
    if (!inBox(i, j)) return kInf;
    const std::size_t n = idx(i, j);
    if (state_[n] & kClosed) return g_[n];
    if (!traversable(i, j)) return kInf;
    if (stopped_) return -1.0;
    const auto t0 = std::chrono::steady_clock::now();
    const bool found = expandUntil(n);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (found) return g_[n];
    return stopped_ ? -1.0 : kInf;
}

}  // namespace gridcar
