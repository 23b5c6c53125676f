#include "gridcar/planners/CornerAStar.h"
#include "gridcar/core/Angles.h"
#include "gridcar/core/Errors.h"
#include "gridcar/vehicle/Dynamics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace
{
/// A corner A* search state: cell index * 8 + arrival direction.
struct CornerState
{
    CellIndex cells;
    std::uint32_t encode(int c, int r, int d) const { return cells.of(c, r) * 8 + std::uint32_t(d); }
    void decode(std::uint32_t s, int &c, int &r, int &d) const
    {
        d = int(s % 8);
        cells.split(s / 8, c, r);
    }
};
}  // namespace

namespace
{
/// Successors of corner-weighted A*: a move in any direction but a reversal, costing its
/// length plus the corner weight of the heading change.
struct CornerExpander
{
    const GridFamily &f;
    const double *turnCost;
    CornerState states;
    double hAt(int c, int r) const
    {
        const GridQuery &q = f.query();
        return q.goalKnown ? f.towardGoal(f.octile(c, r, q.goalCol, q.goalRow)) : 0.0;
    }
    double closeness(std::uint32_t s) const
    {
        int c, r, d;
        states.decode(s, c, r, d);
        return f.closeness(c, r, d);
    }
    double heuristic(std::uint32_t s) const
    {
        int c, r, d;
        states.decode(s, c, r, d);
        return hAt(c, r);
    }
    bool isGoal(std::uint32_t s) const
    {
        int c, r, d;
        states.decode(s, c, r, d);
        return f.isGoal(c, r, d);
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r, dir;
        states.decode(s, c, r, dir);
        for (int d = 0; d < 8; ++d)
        {
            const int t = Moves::turn(dir, d);
            if (t == 4 || !f.moveValid(c, r, d)) continue;  // never a reversal
            const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
            emit(states.encode(nc, nr, d), f.stepLength(d) + turnCost[t], hAt(nc, nr));
        }
    }
};

/// Paper C's node type on the grid lattice: (cell, arrival direction), dense.
class CornerNodes : public GridNodes
{
public:
    explicit CornerNodes(const CornerAStarGrid &p) : p_(p) {}
    std::size_t denseStates(const GridFamily &f) const override { return std::size_t(f.width()) * f.height() * 8; }
    std::vector<std::uint32_t> starts(const GridFamily &f) override
    {
        const CornerState states{f.cellIndex()};
        const GridQuery &q = f.query();
        // the start state's yaw (nearest of 8 directions), or every direction at g = 0 when the
        // start heading is free: the first move then costs no corner
        if (q.startDir >= 0) return {states.encode(q.startCol, q.startRow, q.startDir)};
        std::vector<std::uint32_t> all;
        for (int d = 0; d < 8; ++d) all.push_back(states.encode(q.startCol, q.startRow, d));
        return all;
    }
    SearchResult search(GridFamily &f, const std::vector<std::uint32_t> &starts, const std::function<bool()> &cancelled,
                        std::atomic<std::uint64_t> *progress) override
    {
        const CornerWeights &w = p_.weights();
        const double turnCost[5] = {0.0, w.w45, w.w90, w.w135, 0.0};
        CornerExpander ex{f, turnCost, CornerState{f.cellIndex()}};
        return astar(f.dense(), starts, ex, cancelled, progress);
    }
    void decode(const GridFamily &f, std::uint32_t s, int &col, int &row, int &dir) const override
    {
        CornerState{f.cellIndex()}.decode(s, col, row, dir);
    }

private:
    const CornerAStarGrid &p_;
};
}  // namespace

CornerAStar::CornerAStar(const ompl::base::SpaceInformationPtr &si) : CornerWeighted(si, "corner-astar")
{
    declareParam<std::string>("cost", this, &CornerAStar::setCost, &CornerAStar::cost, "corners,time");
    declareParam<bool>("turn_heuristic", this, &CornerAStar::setTurnHeuristic, &CornerAStar::turnHeuristic, "0,1");
}

void CornerAStar::setTurnHeuristic(bool on)
{
    turnHeuristic_ = on;
    parameterSet("turn_heuristic");
}

void CornerAStar::setCost(const std::string &c)
{
    if (c != "corners" && c != "time")
        throw std::invalid_argument("corner-astar: cost must be 'corners' or 'time', got '" + printable(c) + "'");
    timeCost_ = c == "time";
    parameterSet("cost");
}

CornerAStarGrid::CornerAStarGrid(const ompl::base::SpaceInformationPtr &si) : CornerWeighted(si, "corner-astar-grid") {}

std::unique_ptr<GridNodes> CornerAStarGrid::makeGridNodes() { return std::make_unique<CornerNodes>(*this); }

namespace
{
/// Corner A* on the car lattice: length + the corner weight of the heading change.
class CornerCost : public LatticeCostModel
{
public:
    explicit CornerCost(const CornerAStar &p) : p_(p) {}
    double stepCost(const Pose2 &, const std::vector<Pose2> &, double length, double absTurn) const override
    {
        return length + p_.turnWeight(absTurn);
    }
    bool shapeOnly() const override { return true; }
    bool turnBound() const override { return p_.turnHeuristic(); }
    double minTurnCostPerRad() const override
    {
        // turnWeight() is linear between its table points, so w(x) / x is least at one of them
        const CornerWeights &w = p_.weights();
        return std::min({w.w45 / (M_PI / 4), w.w90 / (M_PI / 2), w.w135 / (3 * M_PI / 4)});
    }

private:
    const CornerAStar &p_;
};
}  // namespace

namespace
{
/// Driving time (s): each sample interval at the speed limit of its curvature, plus the time lost
/// braking for the primitive's heading change and accelerating after it.
class TimeCost : public LatticeCostModel
{
public:
    explicit TimeCost(const VehicleParams &v)
      : v_(v), aLat_(lateralAccelLimit(v)), vMax_(v.maxSpeed), vManoeuvre_(manoeuvringSpeed(v))
    {
    }
    double stepCost(const Pose2 &from, const std::vector<Pose2> &samples, double length, double absTurn) const override
    {
        double t = 0.0, s = 0.0, vLow = vMax_;
        Pose2 a = from;
        for (const Pose2 &b : samples)
        {
            const double ds = std::hypot(b.x - a.x, b.y - a.y);
            const double k = ds > 1e-9 ? std::abs(wrapAngle(b.yaw - a.yaw)) / ds : 0.0;
            const double v = k > 1e-9 && aLat_ > 0 ? std::min(vMax_, std::sqrt(aLat_ / k)) : vMax_;
            t += ds / v;
            s += ds;
            vLow = std::min(vLow, v);
            a = b;
        }
        if (s < length) t += (length - s) / vMax_;  // a step whose samples do not cover it all
        // braking for the motion and accelerating after it: to the speed of its sharpest
        // curvature (a small change of heading at full lock is driven as slowly as a large one),
        // at least what the heading change costs taken as one smooth corner
        return t + std::max(cornerTimeLost(v_, absTurn), cornerDistanceLost(v_, vLow) / vMax_);
    }
    bool shapeOnly() const override { return true; }  // lengths and heading changes only
    double minCostPerMetre() const override { return 1.0 / vMax_; }
    double costPerMetreOfPenalty() const override { return 1.0 / vManoeuvre_; }

private:
    VehicleParams v_;
    double aLat_, vMax_, vManoeuvre_;
};
}  // namespace

std::unique_ptr<LatticeCostModel> CornerAStar::carCost() const
{
    if (timeCost_) return std::make_unique<TimeCost>(vehicle());
    return std::make_unique<CornerCost>(*this);
}

}  // namespace gridcar
