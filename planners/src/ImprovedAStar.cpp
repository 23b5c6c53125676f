#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/core/Errors.h"

#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/planners/search/detail/StateInterner.h"
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
    ip_.paperMode = oneOf(m, {"paper", "integral"}, "mode") == "paper";
    parameterSet("mode");
}
void ImprovedAStar::setLattice(const std::string &l)
{
    ip_.carLattice = oneOf(l, {"car", "grid"}, "lattice") == "car";
    parameterSet("lattice");
}
void ImprovedAStar::setHeuristic(const std::string &h)
{
    ip_.heuristic = oneOf(h, {"auto", "arc", "euclidean", "octile"}, "heuristic");
    parameterSet("heuristic");
}
void ImprovedAStar::setDelta(double d)
{
    if (!std::isfinite(d) || d < 0.0) throw std::invalid_argument("improved-astar: delta must be a finite number >= 0");
    ip_.delta = d;
    parameterSet("delta");
}
void ImprovedAStar::setObstacleCost(const std::string &c)
{
    ip_.voronoi = oneOf(c, {"inverse", "voronoi"}, "obstacle_cost") == "voronoi";
    parameterSet("obstacle_cost");
}
void ImprovedAStar::setContour(const std::string &c)
{
    ip_.points = oneOf(c, {"fcl", "points"}, "contour") == "points";
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
    if (!checker_ && (ip_.voronoi || ip_.points))
        throw ompl::Exception(getName(), std::string(ip_.voronoi ? "obstacle_cost=voronoi" : "contour=points") +
                                             " needs gridcar's footprint validity checker (the map's distance field)");
    const VehicleParams &v = vehicle();
    const double kmax = v.maxCurvature();
    const double half = M_PI / 8;  // half of a 45-degree turn
    const double lturn = std::isfinite(kmax) ? 2 * std::sin(half) / (kmax * std::cos(half) * std::cos(half)) : 0.0;
    need_[0] = int(std::ceil(lturn / cellSize() - 1e-9));
    need_[1] = int(std::ceil(lturn / (cellSize() * std::sqrt(2.0)) - 1e-9));
    runStates_ = std::max(need_[0], need_[1]) + 1;
    const double phi = v.maxSteerDeg * M_PI / 180.0;
    arcFactor_ = phi > 1e-9 ? phi / std::sin(phi) : 1.0;
    const std::string h = ip_.heuristic == "auto" ? (ip_.paperMode ? "arc" : "octile") : ip_.heuristic;
    hKind_ = h == "arc" ? 0 : h == "euclidean" ? 1 : 2;
}

void ImprovedAStar::clear()
{
    GridPlanner::clear();
    lastSmoothing_ = SmoothingResult();
    latticePath_.clear();
}

ImprovedAStar::Key ImprovedAStar::keyCodec() const { return {std::uint64_t(space_->width()), std::uint64_t(runStates_)}; }

double ImprovedAStar::obstacleCostAt(int col, int row) const
{
    if (!checker_) return obstacleCostAtPose({space_->cellCenterX(col), space_->cellCenterY(row), 0.0});
    const DistanceField &f = checker_->field();
    if (ip_.voronoi) return ip_.delta * f.voronoiField(space_->cellCenterX(col), space_->cellCenterY(row));
    const double d = f.cellDistance(col, row);
    return d > 0 ? ip_.delta / d : std::numeric_limits<double>::infinity();
}

double ImprovedAStar::heuristicAt(int col, int row, int goalCol, int goalRow) const
{
    const double step = cellSize(), diag = cellSize() * std::sqrt(2.0);
    const double dx = std::abs(goalCol - col), dy = std::abs(goalRow - row);
    switch (hKind_)
    {
        case 0: return arcFactor_ * step * std::hypot(dx, dy);
        case 1: return step * std::hypot(dx, dy);
        default: return step * std::max(dx, dy) + (diag - step) * std::min(dx, dy);  // octile
    }
}

/// Paper I's node type on the grid lattice: (cell, heading of 8, straight run k), interned on
/// discovery (the lattice is not bounded by 32-bit dense indices), records in chunks.
class ImprovedNodes : public GridNodes
{
public:
    explicit ImprovedNodes(ImprovedAStar &p) : p_(p) {}
    std::size_t denseStates(const GridFamily &) const override { return 0; }
    std::vector<std::uint32_t> starts(const GridFamily &f) override
    {
        states_.clear();
        const ImprovedAStar::Key key = p_.keyCodec();
        const GridQuery &q = f.query();
        std::vector<std::uint32_t> out;
        for (int d = 0; d < 8; ++d)
            if (q.startDir < 0 || d == q.startDir)
                out.push_back(intern(key.of(q.startCol, q.startRow, d, p_.need_[d & 1] / 2)));
        return out;
    }
    SearchResult search(GridFamily &f, const std::vector<std::uint32_t> &starts, const std::function<bool()> &cancelled,
                        std::atomic<std::uint64_t> *progress) override;
    void decode(const GridFamily &, std::uint32_t s, int &col, int &row, int &dir) const override
    {
        int k;
        p_.keyCodec().split(keyOf(s), col, row, dir, k);
    }
    std::uint32_t parent(const GridFamily &, std::uint32_t s) const override { return records_.parent(s); }
    double g(const GridFamily &, std::uint32_t s) const override { return records_.g(s); }
    void forEachClosed(const GridFamily &, const std::function<void(std::uint32_t)> &fn) const override
    {
        records_.forEach([&](std::uint32_t s, bool closed) {
            if (closed) fn(s);
        });
    }
    void clear() override
    {
        records_.reset();
        states_.clear();
    }
    std::uint32_t intern(std::uint64_t key) const { return states_.intern(key); }
    std::uint64_t keyOf(std::uint32_t id) const { return states_.key(id); }

private:
    ImprovedAStar &p_;
    mutable StateInterner states_;  ///< state key -> dense state id
    GrowingSearchSpace records_;
};

/// Successors of improved A*: state = (cell * 8 + heading) * K + straight run.
struct ImprovedExpander
{
    const ImprovedAStar *self;
    const ImprovedNodes &nodes;
    const GridFamily &f;
    ImprovedAStar::Key key;
    int K;
    void split(std::uint32_t s, int &c, int &r, int &dir, int &k) const { key.split(nodes.keyOf(s), c, r, dir, k); }
    double hAt(int c, int r) const
    {
        const GridQuery &q = f.query();
        return q.goalKnown ? f.towardGoal(self->heuristicAt(c, r, q.goalCol, q.goalRow)) : 0.0;
    }
    double closeness(std::uint32_t s) const
    {
        int c, r, d, k;
        split(s, c, r, d, k);
        return f.closeness(c, r, d);
    }
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
        return k >= need - need / 2 && f.isGoal(c, r, d);
    }
    bool moveOk(int c, int r, int d) const
    {
        if (!self->ip_.points) return f.moveValid(c, r, d);
        const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
        const OccupancyGrid &g = self->checker_->grid();
        if (!g.inBounds(nc, nr) || g.isBlocked(nc, nr)) return false;
        if ((d & 1) && !f.allowCornerCutting() && (g.isBlocked(nc, r) || g.isBlocked(c, nr))) return false;
        return self->checker_->isValidDetectionPoints(g.cellCenterX(nc), g.cellCenterY(nr));
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r, dir, k;
        split(s, c, r, dir, k);
        const bool mayTurn = k >= self->need_[dir & 1];
        const double oHere = self->ip_.paperMode ? 0.0 : self->obstacleCostAt(c, r);
        for (int dd : {0, 1, -1})
        {
            if (dd != 0 && !mayTurn) continue;
            const int d = (dir + dd + 8) % 8;
            if (!moveOk(c, r, d)) continue;
            const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
            const int nk = std::min(dd == 0 ? k + 1 : 1, K - 1);
            const std::uint32_t next = nodes.intern(key.of(nc, nr, d, nk));
            double cost = f.stepLength(d);
            if (!self->ip_.paperMode) cost *= 1.0 + 0.5 * (oHere + self->obstacleCostAt(nc, nr));
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

SearchResult ImprovedNodes::search(GridFamily &f, const std::vector<std::uint32_t> &starts,
                                   const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    p_.latticePath_.clear();
    p_.lastSmoothing_ = SmoothingResult();
    if (p_.ip_.paperMode)
    {
        PaperExpander ex{{&p_, *this, f, p_.keyCodec(), p_.runStates_}};
        return astar(records_, starts, ex, cancelled, progress, /*reopen=*/false);
    }
    ImprovedExpander ex{&p_, *this, f, p_.keyCodec(), p_.runStates_};
    return astar(records_, starts, ex, cancelled, progress);
}

std::unique_ptr<GridNodes> ImprovedAStar::makeGridNodes() { return std::make_unique<ImprovedNodes>(*this); }

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
    bool shapeOnly() const override { return true; }  // (the search then makes no samples for it)
    bool customPriority() const override { return true; }
    double priority(double g, double h, const Pose2 &at) const override { return ImprovedAStar::paperPriority(g, h, o(at)); }
};
}  // namespace

double ImprovedAStar::obstacleCostAtPose(const Pose2 &p) const
{
    if (checker_) return obstacleCostAtPoint(checker_->field(), checker_->grid(), ip_.delta, ip_.voronoi, p);
    // any other validity checker: its clearance() when it computes one, else no obstacle cost
    const auto &vc = si_->getStateValidityChecker();
    if (!vc || vc->getSpecs().clearanceComputationType == ompl::base::StateValidityCheckerSpecs::NONE) return 0.0;
    setPose(obstacleScratch_, p);
    const double d = vc->clearance(obstacleScratch_);
    return d > 0 ? ip_.delta / d : std::numeric_limits<double>::infinity();
}

std::unique_ptr<LatticeCostModel> ImprovedAStar::carCost() const
{
    if (ip_.paperMode) return std::make_unique<PaperCost>(*this);
    return std::make_unique<IntegralCost>(*this);
}

PlannerReport ImprovedAStar::lastReport() const
{
    PlannerReport r = GridPlanner::lastReport();
    r.smoothsItself = ip_.smooth;  // the `smooth` switch (acting on the grid lattice)
    r.smoothing = &lastSmoothing();
    r.rawPath = lastRawPath();
    return r;
}

bool ImprovedAStar::postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
{
    if (ip_.carLattice) return false;  // the car lattice's paths are drivable curves as searched
    if (!ip_.smooth || path.getStateCount() < 3)
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
