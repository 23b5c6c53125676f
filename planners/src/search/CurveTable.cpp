/// @file CurveTable.cpp
/// @brief The lattice's node-to-node Reeds-Shepp / Dubins distances, computed on first use,
/// and the bound they give to a goal pose between nodes.
#include "gridcar/planners/search/CurveTable.h"

#include "gridcar/core/Angles.h"
#include "gridcar/curves/CarCurves.h"
#include "gridcar/planners/search/CarLattice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace gridcar
{
namespace
{
constexpr std::size_t kMaxEntries = std::size_t(64) << 20;

/// The shortest Reeds-Shepp (@p reverse) or Dubins curve from @p a to @p b.
CarCurve shortest(const Pose2 &a, const Pose2 &b, double radius, bool reverse)
{
    return reverse ? reedsSheppCurve(a, b, radius) : dubinsCurve(a, b, radius);
}

/// A rounding allowance on a curve length of @p len metres.
double allowance(double len) { return 1e-9 * (1.0 + len); }
}  // namespace

CurveTable::CurveTable(const CarLattice &lattice, double range)
  : cell_(lattice.cell()),
    headings_(lattice.headings()),
    quarter_(lattice.headings()),
    radius_(lattice.config().turnRadius),
    reverse_(lattice.config().reverse)
{
    if (lattice.hybrid())
        throw std::invalid_argument("CurveTable: a hybrid lattice's states are not nodes; the table needs a node lattice");
    if (!std::isfinite(range) || !(range > 0))
        throw std::invalid_argument("CurveTable: range must be finite and > 0 m, got " + std::to_string(range));
    // a range of a whole number of cells is that many (span x cell / cell may round above it)
    span_ = std::max(1, int(std::ceil(range / cell_ - 1e-9)));
    for (int h = 0; h < headings_; ++h) yaw_.push_back(lattice.yaw(h));
    // a quarter turn maps the square grid to itself; it maps the headings too when heading
    // h + headings/4 is heading h turned by 90 degrees (true of the lattice-vector headings)
    if (headings_ % 4 == 0)
    {
        bool symmetric = true;
        const int q = headings_ / 4;
        for (int h = 0; h < headings_ && symmetric; ++h)
            symmetric = std::abs(wrapAngle(yaw_[std::size_t((h + q) % headings_)] - yaw_[std::size_t(h)] - M_PI / 2)) < 1e-9;
        if (symmetric) quarter_ = q;
    }
    const std::size_t w = std::size_t(2 * span_ + 1);
    const std::size_t n = w * w * std::size_t(headings_) * std::size_t(quarter_);
    if (n > kMaxEntries)
        throw std::invalid_argument("CurveTable: a range of " + std::to_string(range) + " m over cells of " +
                                    std::to_string(cell_) + " m needs " + std::to_string(n) +
                                    " entries, more than the 64 Mi allowed");
    d_.assign(n, std::numeric_limits<float>::quiet_NaN());
}

Pose2 CurveTable::node(int i, int j, int h) const { return {i * cell_, j * cell_, yaw_[std::size_t(h)]}; }

std::size_t CurveTable::index(int di, int dj, int hs, int hg) const
{
    const std::size_t w = std::size_t(2 * span_ + 1);
    return ((std::size_t(hg) * std::size_t(headings_) + std::size_t(hs)) * w + std::size_t(dj + span_)) * w +
           std::size_t(di + span_);
}

double CurveTable::compute(int di, int dj, int hs, int hg) const
{
    // less the rounding allowance, so that it stays below the true length (0: no curve, no bound)
    const CarCurve c = shortest(node(di, dj, hs), node(0, 0, hg), radius_, reverse_);
    return c.empty() ? 0.0 : std::max(0.0, c.length - allowance(c.length));
}

double CurveTable::distance(int di, int dj, int hs, int hg) const
{
    if (std::abs(di) > span_ || std::abs(dj) > span_) return -1.0;
    // turn the pair by quarter turns until the goal heading is a stored one: (di, dj) -> (dj, -di)
    while (hg >= quarter_)
    {
        const int t = di;
        di = dj;
        dj = -t;
        hg -= quarter_;
        hs = (hs - quarter_ + headings_) % headings_;
    }
    float &v = d_[index(di, dj, hs, hg)];
    if (std::isnan(v))
    {
        const double len = compute(di, dj, hs, hg);
        float f = float(len);
        if (double(f) > len) f = std::nextafter(f, 0.0f);
        v = f;
        ++computed_;
    }
    return double(v);
}

void CurveTable::fill() const
{
    for (int hg = 0; hg < quarter_; ++hg)
        for (int hs = 0; hs < headings_; ++hs)
            for (int dj = -span_; dj <= span_; ++dj)
                for (int di = -span_; di <= span_; ++di) distance(di, dj, hs, hg);
}

CurveTableBound::CurveTableBound(const CurveTable &table, const Pose2 &goal) : table_(&table)
{
    // the two headings nearest the goal's
    const int n = table.headings();
    std::vector<std::pair<double, int>> byTurn;
    for (int h = 0; h < n; ++h) byTurn.push_back({std::abs(wrapAngle(goal.yaw - table.node(0, 0, h).yaw)), h});
    std::partial_sort(byTurn.begin(), byTurn.begin() + std::min(2, n), byTurn.end());
    // the nodes within R / 2 of the goal's cell: a forward-only car reaches a node a little
    // ahead of it cheaply, one beside or behind it only by a loop
    const double cell = table.cell();
    const int i0 = int(std::floor(goal.x / cell)), j0 = int(std::floor(goal.y / cell));
    const int w = std::max(1, int(std::ceil(0.5 * table.radius() / cell)));
    std::vector<Ref> all;
    for (int k = 0; k < std::min(2, n); ++k)
        for (int di = 1 - w; di <= w; ++di)
            for (int dj = 1 - w; dj <= w; ++dj)
            {
                Ref r{i0 + di, j0 + dj, byTurn[std::size_t(k)].second, 0.0};
                const CarCurve c = shortest(goal, table.node(r.i, r.j, r.h), table.radius(), table.reverse());
                if (c.empty()) continue;
                r.slack = c.length + allowance(c.length);  // rounded up: the slack is subtracted
                all.push_back(r);
            }
    std::sort(all.begin(), all.end(), [](const Ref &a, const Ref &b) { return a.slack < b.slack; });
    for (const Ref &r : all)
    {
        if (count_ == int(refs_.size())) break;
        refs_[std::size_t(count_++)] = r;
    }
}

double CurveTableBound::operator()(int i, int j, int h) const
{
    double best = 0.0;
    for (int k = 0; k < count_; ++k)
    {
        const Ref &r = refs_[std::size_t(k)];
        const double d = table_->distance(i - r.i, j - r.j, h, r.h);
        if (d >= 0) best = std::max(best, d - r.slack);
    }
    return best;
}

}  // namespace gridcar
