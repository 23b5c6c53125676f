/// @file ImprovedAStarGrid.cpp
/// @brief Paper I's improved A* as published, on the map's cells: its node type, heuristics
/// and smoothing.
#include "gridcar/planners/ImprovedAStar.h"

#include "gridcar/core/Errors.h"
#include "gridcar/planners/search/detail/StateInterner.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
ImprovedAStarGrid::ImprovedAStarGrid(const ompl::base::SpaceInformationPtr &si) : GridLatticePlanner(si, "improved-astar-grid")
{
    declareSettings<ImprovedSettings>(params(), getName(), improvedSettingFields(), obstacles_.settings,
                                      [this](const std::string &n) { parameterSet(n); });
    declareParam<std::string>("heuristic", this, &ImprovedAStarGrid::setHeuristic, &ImprovedAStarGrid::heuristic,
                              "auto,arc,euclidean,octile");
    declareParam<std::string>("contour", this, &ImprovedAStarGrid::setContour, &ImprovedAStarGrid::contour, "fcl,points");
    declareParam<bool>("smooth", this, &ImprovedAStarGrid::setSmooth, &ImprovedAStarGrid::smooth, "0,1");
}

void ImprovedAStarGrid::setHeuristic(const std::string &h)
{
    if (h != "auto" && h != "arc" && h != "euclidean" && h != "octile")
        throw std::invalid_argument(getName() + ": heuristic must be one of auto, arc, euclidean, octile, got '" +
                                    printable(h) + "'");
    heuristic_ = h;
    parameterSet("heuristic");
}

void ImprovedAStarGrid::setContour(const std::string &c)
{
    if (c != "fcl" && c != "points")
        throw std::invalid_argument(getName() + ": contour must be one of fcl, points, got '" + printable(c) + "'");
    points_ = c == "points";
    parameterSet("contour");
}

void ImprovedAStarGrid::setup()
{
    GridLatticePlanner::setup();
    obstacles_.setup(si_, checker_, getName());
    if (!checker_ && points_)
        throw ompl::Exception(getName(), "contour=points needs gridcar's footprint validity checker (the map's distance field)");
    const VehicleParams &v = vehicle();
    const double kmax = v.maxCurvature();
    const double half = M_PI / 8;  // half of a 45-degree turn
    const double lturn = std::isfinite(kmax) ? 2 * std::sin(half) / (kmax * std::cos(half) * std::cos(half)) : 0.0;
    need_[0] = int(std::ceil(lturn / cellSize() - 1e-9));
    need_[1] = int(std::ceil(lturn / (cellSize() * std::sqrt(2.0)) - 1e-9));
    runStates_ = std::max(need_[0], need_[1]) + 1;
    const double phi = v.maxSteerDeg * M_PI / 180.0;
    arcFactor_ = phi > 1e-9 ? phi / std::sin(phi) : 1.0;
    const std::string h = heuristic_ == "auto" ? (improvedSettings().paperMode ? "arc" : "octile") : heuristic_;
    hKind_ = h == "arc" ? 0 : h == "euclidean" ? 1 : 2;
}

void ImprovedAStarGrid::clear()
{
    GridLatticePlanner::clear();
    lastSmoothing_ = SmoothingResult();
    latticePath_.clear();
}

ImprovedAStarGrid::Key ImprovedAStarGrid::keyCodec() const
{
    return {std::uint64_t(space_->width()), std::uint64_t(runStates_)};
}

double ImprovedAStarGrid::heuristicAt(int col, int row, int goalCol, int goalRow) const
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
    explicit ImprovedNodes(ImprovedAStarGrid &p) : p_(p) {}
    std::size_t denseStates(const GridFamily &) const override { return 0; }
    std::vector<std::uint32_t> starts(const GridFamily &f) override
    {
        states_.clear();
        const ImprovedAStarGrid::Key key = p_.keyCodec();
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
    ImprovedAStarGrid &p_;
    mutable StateInterner states_;  ///< state key -> dense state id
    GrowingSearchSpace records_;
};

/// Successors of improved A*: state = (cell * 8 + heading) * K + straight run.
struct ImprovedExpander
{
    const ImprovedAStarGrid *self;
    const ImprovedNodes &nodes;
    const GridFamily &f;
    ImprovedAStarGrid::Key key;
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
        if (!self->points_) return f.moveValid(c, r, d);
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
        const double oHere = self->improvedSettings().paperMode ? 0.0 : self->obstacleCostAt(c, r);
        for (int dd : {0, 1, -1})
        {
            if (dd != 0 && !mayTurn) continue;
            const int d = (dir + dd + 8) % 8;
            if (!moveOk(c, r, d)) continue;
            const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
            const int nk = std::min(dd == 0 ? k + 1 : 1, K - 1);
            const std::uint32_t next = nodes.intern(key.of(nc, nr, d, nk));
            double cost = f.stepLength(d);
            if (!self->improvedSettings().paperMode) cost *= 1.0 + 0.5 * (oHere + self->obstacleCostAt(nc, nr));
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
        return paperPriority(g, h, self->obstacleCostAt(c, r));
    }
};
}  // namespace

SearchResult ImprovedNodes::search(GridFamily &f, const std::vector<std::uint32_t> &starts,
                                   const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    p_.latticePath_.clear();
    p_.lastSmoothing_ = SmoothingResult();
    if (p_.improvedSettings().paperMode)
    {
        PaperExpander ex{{&p_, *this, f, p_.keyCodec(), p_.runStates_}};
        return astar(records_, starts, ex, cancelled, progress, /*reopen=*/false);
    }
    ImprovedExpander ex{&p_, *this, f, p_.keyCodec(), p_.runStates_};
    return astar(records_, starts, ex, cancelled, progress);
}

std::unique_ptr<GridNodes> ImprovedAStarGrid::makeGridNodes() { return std::make_unique<ImprovedNodes>(*this); }

PlannerReport ImprovedAStarGrid::lastReport() const
{
    PlannerReport r = GridLatticePlanner::lastReport();
    r.smoothsItself = smooth_;
    r.smoothing = &lastSmoothing_;
    r.rawPath = lastRawPath();
    return r;
}

bool ImprovedAStarGrid::postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc)
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
