/// @file ImprovedAStar.cpp
/// @brief Paper I's improved A* on the car lattice, and what both its planners share: the
/// settings table and the obstacle cost o(n).
#include "gridcar/planners/ImprovedAStar.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
namespace
{
using S = ImprovedSettings;

std::vector<SettingField<S>> makeFields()
{
    return {{"mode", "paper,integral", "paper: eq. 4-5 (greedy); integral: length x (1 + o), consistent",
             [](S &s, const std::string &v) {
                 s.paperMode = settings::oneOf("mode", v, {"paper", "integral"}, "one of paper, integral") == 0;
             },
             [](const S &s) { return std::string(s.paperMode ? "paper" : "integral"); }},
            {"delta", "0.:0.1:100.", "the obstacle-cost gain, m",
             [](S &s, const std::string &v) { s.delta = settings::real("delta", v, 0.0, 1e9, "a finite number >= 0"); },
             [](const S &s) { return settings::print(s.delta); }},
            {"obstacle_cost", "inverse,voronoi", "o(n): delta / d_O (inverse) or delta x the Voronoi field",
             [](S &s, const std::string &v) {
                 s.voronoi = settings::oneOf("obstacle_cost", v, {"inverse", "voronoi"}, "one of inverse, voronoi") == 1;
             },
             [](const S &s) { return std::string(s.voronoi ? "voronoi" : "inverse"); }}};
}

/// o(n) of paper I at a world point: delta / d_O (inverse) or delta x rho_V (voronoi).
double obstacleCostAtPoint(const DistanceField &f, const OccupancyGrid &g, double delta, bool voronoi, const Pose2 &p)
{
    if (voronoi) return delta * f.voronoiField(p.x, p.y);
    const Cell c = g.worldToCell(p.x, p.y);
    const double d = f.cellDistance(c.col, c.row);
    return d > 0 ? delta / d : std::numeric_limits<double>::infinity();
}
}  // namespace

const std::vector<SettingField<ImprovedSettings>> &improvedSettingFields()
{
    static const std::vector<SettingField<S>> fields = makeFields();
    return fields;
}

ObstacleCost::~ObstacleCost()
{
    if (scratch_) si_->freeState(scratch_);
}

void ObstacleCost::setup(const ompl::base::SpaceInformationPtr &si, const FootprintChecker *checker, const std::string &planner)
{
    if (scratch_ && si != si_)
    {
        si_->freeState(scratch_);
        scratch_ = nullptr;
    }
    si_ = si;
    checker_ = checker;
    if (!scratch_) scratch_ = si_->allocState();
    if (!checker_ && settings.voronoi)
        throw ompl::Exception(planner, "obstacle_cost=voronoi needs gridcar's footprint validity checker (the map's distance field)");
}

double ObstacleCost::atPose(const Pose2 &p) const
{
    if (checker_) return obstacleCostAtPoint(checker_->field(), checker_->grid(), settings.delta, settings.voronoi, p);
    // any other validity checker: its clearance() when it computes one, else no obstacle cost
    const auto &vc = si_->getStateValidityChecker();
    if (!vc || vc->getSpecs().clearanceComputationType == ompl::base::StateValidityCheckerSpecs::NONE) return 0.0;
    setPose(scratch_, p);
    const double d = vc->clearance(scratch_);
    return d > 0 ? settings.delta / d : std::numeric_limits<double>::infinity();
}

double ObstacleCost::atCell(const GridSE2StateSpace &space, int col, int row) const
{
    if (!checker_) return atPose({space.cellCenterX(col), space.cellCenterY(row), 0.0});
    const DistanceField &f = checker_->field();
    if (settings.voronoi) return settings.delta * f.voronoiField(space.cellCenterX(col), space.cellCenterY(row));
    const double d = f.cellDistance(col, row);
    return d > 0 ? settings.delta / d : std::numeric_limits<double>::infinity();
}

ImprovedAStar::ImprovedAStar(const ompl::base::SpaceInformationPtr &si) : CarLatticePlanner(si, "improved-astar")
{
    // on the car lattice the consistent ordering by default: paper I's greedy priority takes
    // long detours and loops there (mode=paper keeps it; improved-astar-grid is the paper's
    // own search, greedy by default)
    obstacles_.settings.paperMode = false;
    declareSettings<ImprovedSettings>(params(), getName(), improvedSettingFields(), obstacles_.settings,
                                      [this](const std::string &n) { parameterSet(n); });
}

void ImprovedAStar::setup()
{
    CarLatticePlanner::setup();
    obstacles_.setup(si_, checker_, getName());
}

PlannerReport ImprovedAStar::lastReport() const
{
    PlannerReport r = CarLatticePlanner::lastReport();
    r.smoothsItself = true;  // paper I's planner: its car-lattice paths are final, drivable as searched
    return r;
}

namespace
{
/// What both of paper I's costs on the car lattice need: o(n) at a pose, and the 2D
/// heuristic's edges weighted by 1 + o.
class ObstacleCostModel : public LatticeCostModel
{
public:
    explicit ObstacleCostModel(const ObstacleCost &o) : o_(o) {}
    double o(const Pose2 &p) const { return o_.atPose(p); }
    double nodeWeight(const Pose2 &p) const override { return 1.0 + o(p); }
    bool weighted() const override { return true; }

private:
    const ObstacleCost &o_;
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
    double priority(double g, double h, const Pose2 &at) const override { return paperPriority(g, h, o(at)); }
};
}  // namespace

std::unique_ptr<LatticeCostModel> ImprovedAStar::carCost() const
{
    if (obstacles_.settings.paperMode) return std::make_unique<PaperCost>(obstacles_);
    return std::make_unique<IntegralCost>(obstacles_);
}

}  // namespace gridcar
