#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/core/Errors.h"

#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
ImprovedAStar::ImprovedAStar(const ompl::base::SpaceInformationPtr &si) : GridPlanner(si, "improved-astar")
{
    declareParam<std::string>("mode", this, &ImprovedAStar::setMode, &ImprovedAStar::mode, "paper,integral");
    declareParam<std::string>("heuristic", this, &ImprovedAStar::setHeuristic, &ImprovedAStar::heuristic,
                              "auto,arc,euclidean,octile");
    declareParam<double>("delta", this, &ImprovedAStar::setDelta, &ImprovedAStar::delta, "0.:0.1:100.");
    declareParam<std::string>("obstacle_cost", this, &ImprovedAStar::setObstacleCost, &ImprovedAStar::obstacleCost,
                              "inverse,voronoi");
    declareParam<std::string>("contour", this, &ImprovedAStar::setContour, &ImprovedAStar::contour, "fcl,points");
    declareParam<bool>("smooth", this, &ImprovedAStar::setSmooth, &ImprovedAStar::smooth, "0,1");
    declareParam<std::string>("lattice", this, &ImprovedAStar::setLattice, &ImprovedAStar::lattice, "car,grid");
    declareCarLatticeParams();
}

namespace
{
std::string oneOf(const std::string &v, std::initializer_list<const char *> allowed, const char *param)
{
    std::string list;
    for (const char *a : allowed)
    {
        if (v == a) return v;
        list += (list.empty() ? "" : ", ") + std::string(a);
    }
    throw std::invalid_argument("improved-astar: " + std::string(param) + " must be one of " + list + ", got '" + printable(v) + "'");
}
}  // namespace

void ImprovedAStar::setMode(const std::string &m)
{
    paperMode_ = oneOf(m, {"paper", "integral"}, "mode") == "paper";
    parameterSet("mode");
}
void ImprovedAStar::setLattice(const std::string &l)
{
    carLattice_ = oneOf(l, {"car", "grid"}, "lattice") == "car";
    parameterSet("lattice");
}
void ImprovedAStar::setHeuristic(const std::string &h)
{
    heuristic_ = oneOf(h, {"auto", "arc", "euclidean", "octile"}, "heuristic");
    parameterSet("heuristic");
}
void ImprovedAStar::setDelta(double d)
{
    if (!std::isfinite(d) || d < 0.0) throw std::invalid_argument("improved-astar: delta must be a finite number >= 0");
    delta_ = d;
    parameterSet("delta");
}
void ImprovedAStar::setObstacleCost(const std::string &c)
{
    voronoi_ = oneOf(c, {"inverse", "voronoi"}, "obstacle_cost") == "voronoi";
    parameterSet("obstacle_cost");
}
void ImprovedAStar::setContour(const std::string &c)
{
    points_ = oneOf(c, {"fcl", "points"}, "contour") == "points";
    parameterSet("contour");
}

ImprovedAStar::~ImprovedAStar()
{
    if (obstacleScratch_) si_->freeState(obstacleScratch_);
}

void ImprovedAStar::setup()
{
    GridPlanner::setup();
    if (!obstacleScratch_) obstacleScratch_ = si_->allocState();
    if (!checker_ && (voronoi_ || points_))
        throw ompl::Exception(getName(), std::string(voronoi_ ? "obstacle_cost=voronoi" : "contour=points") +
                                             " needs gridcar's footprint validity checker (the map's distance field)");
    const VehicleParams &v = vehicle();
    const double kmax = v.maxCurvature();
    const double half = M_PI / 8;  // half of a 45-degree turn
    const double lturn = std::isfinite(kmax) ? 2 * std::sin(half) / (kmax * std::cos(half) * std::cos(half)) : 0.0;
    need_[0] = int(std::ceil(lturn / straightStep_ - 1e-9));
    need_[1] = int(std::ceil(lturn / diagStep_ - 1e-9));
    runStates_ = std::max(need_[0], need_[1]) + 1;
    const double phi = v.maxSteerDeg * M_PI / 180.0;
    arcFactor_ = phi > 1e-9 ? phi / std::sin(phi) : 1.0;
    const std::string h = heuristic_ == "auto" ? (paperMode_ ? "arc" : "octile") : heuristic_;
    hKind_ = h == "arc" ? 0 : h == "euclidean" ? 1 : 2;
}

void ImprovedAStar::clear()
{
    GridPlanner::clear();
    records_.reset();
    states_.clear();
    lastSmoothing_ = SmoothingResult();
    latticePath_.clear();
}

std::size_t ImprovedAStar::stateCount() const { return states_.size(); }

std::uint32_t ImprovedAStar::intern(std::uint64_t key) const { return states_.intern(key); }

ImprovedAStar::Key ImprovedAStar::keyCodec() const { return {std::uint64_t(width_), std::uint64_t(runStates_)}; }

void ImprovedAStar::decode(std::uint32_t s, int &col, int &row, int &dir) const
{
    int k;
    keyCodec().split(keyOf(s), col, row, dir, k);
}

double ImprovedAStar::obstacleCostAt(int col, int row) const
{
    if (!checker_) return obstacleCostAtPose({space_->cellCenterX(col), space_->cellCenterY(row), 0.0});
    const DistanceField &f = checker_->field();
    if (voronoi_) return delta_ * f.voronoiField(space_->cellCenterX(col), space_->cellCenterY(row));
    const double d = f.cellDistance(col, row);
    return d > 0 ? delta_ / d : std::numeric_limits<double>::infinity();
}

double ImprovedAStar::heuristicAt(int col, int row, int goalCol, int goalRow) const
{
    const double dx = std::abs(goalCol - col), dy = std::abs(goalRow - row);
    switch (hKind_)
    {
        case 0: return arcFactor_ * straightStep_ * std::hypot(dx, dy);
        case 1: return straightStep_ * std::hypot(dx, dy);
        default: return octile(col, row, goalCol, goalRow);
    }
}

std::vector<std::uint32_t> ImprovedAStar::startStates(const Query &q) const
{
    states_.clear();
    const Key key = keyCodec();
    std::vector<std::uint32_t> out;
    for (int d = 0; d < 8; ++d)
        if (q.startDir < 0 || d == q.startDir) out.push_back(intern(key.of(q.startCol, q.startRow, d, need_[d & 1] / 2)));
    return out;
}

void ImprovedAStar::forEachClosed(const std::function<void(std::uint32_t)> &fn) const
{
    records_.forEach([&](std::uint32_t s, bool closed) {
        if (closed) fn(s);
    });
}

/// Successors of improved A*: state = (cell * 8 + heading) * K + straight run.
struct ImprovedExpander
{
    const ImprovedAStar *self;
    const GridPlanner::Query &q;
    ImprovedAStar::Key key;
    int K;
    void split(std::uint32_t s, int &c, int &r, int &dir, int &k) const { key.split(self->keyOf(s), c, r, dir, k); }
    double hAt(int c, int r) const { return q.goalIsState ? self->heuristicAt(c, r, q.goalCol, q.goalRow) : 0.0; }
    double heuristic(std::uint32_t s) const
    {
        int c, r, d, k;
        split(s, c, r, d, k);
        return hAt(c, r);
    }
    bool isGoal(std::uint32_t s) const
    {
        int c, r, d, k;
        split(s, c, r, d, k);
        const int need = self->need_[d & 1];
        return k >= need - need / 2 && self->isGoal(c, r, d);
    }
    bool moveOk(int c, int r, int d) const
    {
        if (!self->points_) return self->moveValid(c, r, d);
        const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
        const OccupancyGrid &g = self->checker_->grid();
        if (!g.inBounds(nc, nr) || g.isBlocked(nc, nr)) return false;
        if ((d & 1) && !self->allowCornerCutting() && (g.isBlocked(nc, r) || g.isBlocked(c, nr))) return false;
        return self->checker_->isValidDetectionPoints(g.cellCenterX(nc), g.cellCenterY(nr));
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r, dir, k;
        split(s, c, r, dir, k);
        const bool mayTurn = k >= self->need_[dir & 1];
        const double oHere = self->paperMode_ ? 0.0 : self->obstacleCostAt(c, r);
        for (int dd : {0, 1, -1})
        {
            if (dd != 0 && !mayTurn) continue;
            const int d = (dir + dd + 8) % 8;
            if (!moveOk(c, r, d)) continue;
            const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
            const int nk = std::min(dd == 0 ? k + 1 : 1, K - 1);
            const std::uint32_t next = self->intern(key.of(nc, nr, d, nk));
            double cost = self->stepLength(d);
            if (!self->paperMode_) cost *= 1.0 + 0.5 * (oHere + self->obstacleCostAt(nc, nr));
            emit(next, cost, hAt(nc, nr));
        }
    }
};

namespace
{
/// Paper I's priority f = g' + h (1 + o) (s is the rejection of invalid successors).
struct PaperExpander : ImprovedExpander
{
    double priority(double g, double h, std::uint32_t s) const
    {
        int c, r, d, k;
        split(s, c, r, d, k);
        return ImprovedAStar::paperPriority(g, h, self->obstacleCostAt(c, r));
    }
};
}  // namespace

SearchResult ImprovedAStar::runSearch(const Query &q, const std::vector<std::uint32_t> &starts,
                                      const ompl::base::PlannerTerminationCondition &ptc)
{
    latticePath_.clear();
    lastSmoothing_ = SmoothingResult();
    auto cancelled = [&] { return ptc.eval(); };
    if (paperMode_)
    {
        PaperExpander ex{{this, q, keyCodec(), runStates_}};
        return astar(records_, starts, ex, cancelled, &progressExpanded_, /*reopen=*/false);
    }
    ImprovedExpander ex{this, q, keyCodec(), runStates_};
    return astar(records_, starts, ex, cancelled, &progressExpanded_);
}

namespace
{
/// o(n) of paper I at a world point: delta / d_O (inverse) or delta x rho_V (voronoi).
double obstacleCostAtPoint(const DistanceField &f, const OccupancyGrid &g, double delta, bool voronoi, const Pose2 &p)
{
    if (voronoi) return delta * f.voronoiField(p.x, p.y);
    const Cell c = g.worldToCell(p.x, p.y);
    const double d = f.cellDistance(c.col, c.row);
    return d > 0 ? delta / d : std::numeric_limits<double>::infinity();
}

/// What both of paper I's costs on the car lattice need: o(n) at a pose, and the 2D
/// heuristic's edges weighted by 1 + o.
class ObstacleCostModel : public LatticeCostModel
{
public:
    explicit ObstacleCostModel(const ImprovedAStar &p) : p_(p) {}
    double o(const Pose2 &p) const { return p_.obstacleCostAtPose(p); }
    double nodeWeight(const Pose2 &p) const override { return 1.0 + o(p); }
    bool weighted() const override { return true; }

private:
    const ImprovedAStar &p_;
};

/// Integral mode on the car lattice: length x (1 + o), o averaged over the primitive's samples.
class IntegralCost : public ObstacleCostModel
{
public:
    using ObstacleCostModel::ObstacleCostModel;
    double stepCost(const Pose2 &, const std::vector<Pose2> &samples, double length, double) const override
    {
        double sum = 0;
        for (const Pose2 &p : samples) sum += o(p);
        return length * (1.0 + sum / double(std::max<std::size_t>(1, samples.size())));
    }
};

/// Paper mode on the car lattice: g = length, open list ordered by eq. 4-5 with o at the node.
class PaperCost : public ObstacleCostModel
{
public:
    using ObstacleCostModel::ObstacleCostModel;
    double stepCost(const Pose2 &, const std::vector<Pose2> &, double length, double) const override { return length; }
    bool customPriority() const override { return true; }
    double priority(double g, double h, const Pose2 &at) const override { return ImprovedAStar::paperPriority(g, h, o(at)); }
};
}  // namespace

double ImprovedAStar::obstacleCostAtPose(const Pose2 &p) const
{
    if (checker_) return obstacleCostAtPoint(checker_->field(), checker_->grid(), delta_, voronoi_, p);
    // any other validity checker: its clearance() when it computes one, else no obstacle cost
    const auto &vc = si_->getStateValidityChecker();
    if (!vc || vc->getSpecs().clearanceComputationType == ompl::base::StateValidityCheckerSpecs::NONE) return 0.0;
    setPose(obstacleScratch_, p);
    const double d = vc->clearance(obstacleScratch_);
    return d > 0 ? delta_ / d : std::numeric_limits<double>::infinity();
}

std::unique_ptr<LatticeCostModel> ImprovedAStar::carCost() const
{
    if (paperMode_) return std::make_unique<PaperCost>(*this);
    return std::make_unique<IntegralCost>(*this);
}

bool ImprovedAStar::postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
{
    if (!smooth_ || path.getStateCount() < 3)
    {
        latticePath_ = toPoses(path);
        return false;
    }
    if (!checker_)
    {
        // paper I's smoothing checks the footprint on the map: not available here
        OMPL_WARN("%s: smooth=1 needs gridcar's footprint validity checker; the path is not smoothed", getName().c_str());
        latticePath_ = toPoses(path);
        return false;
    }
    lastSmoothing_ = smoothSolutionPath(si_, *checker_, path, latticePath_, ptc);
    if (lastSmoothing_.cancelled)
    {
        OMPL_WARN("%s: smoothing stopped by the termination condition; the path is the search's, unsmoothed", getName().c_str());
        lastSmoothing_ = SmoothingResult();
        markNotExact("the smoothing was stopped by the termination condition: the path is the search's, unsmoothed");
        return false;
    }
    return true;
}

}  // namespace gridcar
