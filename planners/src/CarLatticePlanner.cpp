/// @file CarLatticePlanner.cpp
/// @brief The car lattice's planner: its settings declared from their table, the primitive set
/// from them, set-up, one search, the explored graph.
#include "gridcar/planners/CarLatticePlanner.h"

#include "gridcar/planners/CarLatticeParams.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace
{
/// Curves the path shortcut may try per query (PathShortcut::apply()).
constexpr int kShortcutCurves = 3000;
}  // namespace

CarLatticePlanner::CarLatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
  : GridPlanner(si, name)
{
    declareSettings<CarLatticeSettings>(params(), name, carLatticeSettingFields(), settings_,
                                        [this](const std::string &n) { parameterSet(n); });
}

void CarLatticePlanner::setCarSettings(const CarLatticeSettings &s)
{
    settings_ = s;
    parameterSet("car lattice settings");
}

void CarLatticePlanner::setupFamily(const std::shared_ptr<CarCollision> &collision)
{
    if (settings_.reverse == AutoSwitch::On && onDubinsSpace())
        throw std::invalid_argument(getName() + ": reverse=on on a Dubins space, which drives forwards only (use "
                                                "reverse=auto or the Reeds-Shepp space)");
    setupCar(car_, collision, 0.0);
    // the grown body's checker and searches are made again when a query first needs them (the
    // settings, the map or the vehicle may have changed)
    grown_.reset();
    grownCollision_.reset();
    lastGrown_ = grownSearched_ = false;
}

void CarLatticePlanner::setupCar(CarFamily &family, const std::shared_ptr<CarCollision> &collision, double reach)
{
    // turns=auto: the lattice's clothoid turns for routes, its arcs for a goal pose to meet;
    // an automatic cell: routes on a coarser cell than a goal pose's manoeuvres (routeCell())
    const CarLatticeConfig cfg = carLatticeConfig(settings_.primitives == PrimitiveSet::Hybrid, reach);
    CarLatticeConfig poses = cfg;
    if (settings_.turns == TurnShape::Auto) poses.curvatureRate = 0.0;
    if (settings_.primitives != PrimitiveSet::Hybrid) poses.cell = poseCell();
    const CarLatticeConfig *forPoses = cfg != poses ? &poses : nullptr;
    if (settings_.primitives == PrimitiveSet::Auto)
    {
        const CarLatticeConfig hybrid = carLatticeConfig(true, reach);
        family.setup(cfg, collision, &hybrid, forPoses);
    }
    else
        family.setup(cfg, collision, nullptr, forPoses);
}

FamilyRun CarLatticePlanner::searchFamily(const ompl::base::State *start, const GoalTarget &goal,
                                          const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress)
{
    const std::unique_ptr<LatticeCostModel> cost = carCost();
    CarLatticeQuery terms;
    terms.settings = settings_;
    terms.freeStartHeading = freeStartHeading();
    terms.cuspPenalty = cuspPenalty() * cost->costPerMetreOfPenalty();
    terms.curveWithin = curveWithin();
    terms.reverseWithin = reverseWithin();
    terms.map = checker_;
    if (settings_.costLayerWeight > 0 && !terms.layered())
        OMPL_WARN("%s: cost_layer_weight is set but the map has no cost layer (a map_server map in scale or "
                  "raw mode, on gridcar's validity checker): it has no effect",
                  getName().c_str());
    const CarPostProcessing post{shortcutting() ? kShortcutCurves : 0, curvatureRate(), 1.0 / turningRadius()};
    lastGrown_ = grownSearched_ = false;
    FamilyRun run = car_.solve(si_, start, terms, post, goal, *cost, cancelled, progress);
    if (const double margin = safetyMargin(); margin > 0 && run.end.reached && run.end.path && !cancelled())
        keepMargin(run, margin, start, terms, post, goal, *cost, cancelled, progress);
    return run;
}

void CarLatticePlanner::familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const
{
    // both searches' explored states where the margin's search ran
    car_.plannerData(data, states);
    if (grownSearched_) grownCar_.plannerData(data, states);
}

CarLatticeConfig CarLatticePlanner::carLatticeConfig() const
{
    return carLatticeConfig(settings_.primitives == PrimitiveSet::Hybrid);
}

double CarLatticePlanner::curvatureRate() const
{
    if (!settings_.continuousCurvature) return 0.0;
    if (settings_.curvatureRate > 0) return settings_.curvatureRate;
    const double r = vehicle().curvatureRateLimit();
    return std::isfinite(r) ? r : 0.0;
}

double CarLatticePlanner::curveWithin() const
{
    const CarLatticeSearch *search = carSearch();
    if (!search) return 0.0;
    const double R = search->lattice().config().turnRadius;
    // the table covers nodes within 10 R per axis of the goal's; exact, within 30 R of it
    switch (settings_.curveHeuristic)
    {
        case CurveHeuristic::Table: return 10.0 * R;
        case CurveHeuristic::Exact: return 30.0 * R;
        case CurveHeuristic::Off: break;
    }
    return 0.0;
}

bool CarLatticePlanner::onDubinsSpace() const
{
    return dynamic_cast<const ompl::base::DubinsStateSpace *>(si_->getStateSpace().get()) != nullptr;
}

bool CarLatticePlanner::reversing() const
{
    if (settings_.reverse == AutoSwitch::Off) return false;
    return !(onDubinsSpace() && settings_.reverse == AutoSwitch::Auto);
}

double CarLatticePlanner::reverseWithin() const
{
    if (settings_.reverse != AutoSwitch::Auto || !reversing()) return -1.0;
    if (settings_.reverseZone > 0) return settings_.reverseZone;
    return 2 * turningRadius() + std::max(0.0, vehicle().length);
}

double CarLatticePlanner::cuspPenalty() const
{
    return settings_.cuspPenalty ? *settings_.cuspPenalty : gearChangeDistance(vehicle());
}

double CarLatticePlanner::poseCell() const
{
    const double rmin = turningRadius();
    if (latticeCell() > 0) return latticeCell();
    if (!checker_) return rmin / 4;
    const VehicleParams &v = checker_->vehicle();
    const double res = checker_->grid().resolution();
    const double want = std::min(v.isPoint() ? 4 * res : v.width, rmin > 0 ? rmin : 4 * res) / 4;
    return res * std::max(1.0, std::round(want / res));
}

double CarLatticePlanner::routeCell() const
{
    const double pose = poseCell();
    if (latticeCell() > 0 || !checker_) return pose;
    // twice the pose's, where a turn at R_min still spans 2.5 of those cells: paper I's car
    // (R_min 1.86 m) on 0.9 m cells drove 20 % longer routes and searched 10x longer at p90
    // (bench_native), paper C's robot (0.55 m on 0.2 m cells) and car (3.86 m on 0.9 m) did not
    const double rmin = turningRadius();
    return 2 * pose <= 0.4 * rmin ? 2 * pose : pose;
}

CarLatticeConfig CarLatticePlanner::carLatticeConfig(bool hybrid, double reach) const
{
    const double rmin = turningRadius();
    CarLatticeConfig cfg;
    cfg.headings = settings_.headings;
    if (checker_)
    {
        const double res = checker_->grid().resolution();
        cfg.cell = routeCell();
        cfg.spacing = std::min(res, 0.1);
        cfg.reach = reach > 0 ? reach : checker_->reach();
    }
    else
    {
        // any other validity checker: poses no farther apart than 0.1 m or OMPL's longest
        // valid segment, whichever is shorter (the checker sees poses only)
        cfg.cell = routeCell();
        cfg.spacing = std::min({0.1, cfg.cell / 2, si_->getStateSpace()->getLongestValidSegmentLength()});
        cfg.reach = 0.0;
    }
    // arcs 1 % wider than R_min: sampled curves then stay within K_max by a clear margin
    cfg.turnRadius = rmin > 0 ? 1.01 * rmin : cfg.cell;
    cfg.reverse = reversing();
    // clothoid turns a little inside the rate, so that sampled paths measure within it
    if (settings_.turns == TurnShape::Clothoid || (settings_.turns == TurnShape::Auto && !hybrid))
    {
        const double sigma = settings_.curvatureRate > 0 ? settings_.curvatureRate : vehicle().curvatureRateLimit();
        if (std::isfinite(sigma) && sigma > 0) cfg.curvatureRate = 0.95 * sigma;
    }
    if (hybrid)
    {
        // 72 bins of 5 degrees; cells small enough that an arc of one bin at R_min leaves its
        // cell (1.5 cells), on the map's resolution where there is a map
        cfg.hybrid = true;
        cfg.headings = 72;
        const double want = cfg.turnRadius * (2 * M_PI / 72) / 1.5;
        const double res = checker_ ? checker_->grid().resolution() : 0.0;
        if (latticeCell() > 0 && settings_.primitives == PrimitiveSet::Hybrid)
            cfg.cell = latticeCell();
        else
            cfg.cell = res > 0 ? res * std::max(1.0, std::floor(want / res)) : want;
        cfg.spacing = std::min(cfg.spacing, cfg.cell / 2);
    }
    return cfg;
}

}  // namespace gridcar
