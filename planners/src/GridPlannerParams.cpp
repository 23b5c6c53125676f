/// @file GridPlannerParams.cpp
/// @brief GridPlanner's parameter setters (each validates, then redoes set-up), the car
/// lattice's settings declared from their table, and its primitive set from them.
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/planners/CarLatticeParams.h"

#include "gridcar/core/Errors.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/base/spaces/DubinsStateSpace.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
void GridPlanner::declareCarLatticeParams()
{
    declareSettings<CarLatticeSettings>(params(), getName(), carLatticeSettingFields(), params_.car,
                                        [this](const std::string &name) { parameterSet(name); });
}

std::vector<std::string> GridPlanner::carLatticeOnlyParams() const
{
    std::vector<std::string> names;
    for (const auto &f : carLatticeSettingFields()) names.push_back(f.name);
    return names;
}

void GridPlanner::setCarSettings(const CarLatticeSettings &s)
{
    for (const auto &f : carLatticeSettingFields())
        if (f.print(s) != f.print(params_.car)) parameterSet(f.name);
    params_.car = s;
    setup_ = false;
}

double GridPlanner::curvatureRate() const
{
    if (!params_.car.continuousCurvature) return 0.0;
    if (params_.car.curvatureRate > 0) return params_.car.curvatureRate;
    const double r = vehicle().curvatureRateLimit();
    return std::isfinite(r) ? r : 0.0;
}

bool GridPlanner::matchGoalHeading() const
{
    return params_.matchGoalHeading.value_or(usesCarLattice());
}

double GridPlanner::curveWithin() const
{
    const CarLatticeSearch *search = carSearch();
    if (!search) return 0.0;
    const double R = search->lattice().config().turnRadius;
    // the table covers nodes within 10 R per axis of the goal's; exact, within 30 R of it
    switch (params_.car.curveHeuristic)
    {
        case CurveHeuristic::Table: return 10.0 * R;
        case CurveHeuristic::Exact: return 30.0 * R;
        case CurveHeuristic::Off: break;
    }
    return 0.0;
}

bool GridPlanner::onDubinsSpace() const
{
    return dynamic_cast<const ompl::base::DubinsStateSpace *>(si_->getStateSpace().get()) != nullptr;
}

bool GridPlanner::reversing() const
{
    if (params_.car.reverse == AutoSwitch::Off) return false;
    return !(onDubinsSpace() && params_.car.reverse == AutoSwitch::Auto);
}

double GridPlanner::cuspPenalty() const
{
    return params_.car.cuspPenalty ? *params_.car.cuspPenalty : gearChangeDistance(vehicle());
}

void GridPlanner::setAllowCornerCutting(bool v)
{
    params_.allowCornerCutting = v;
    parameterSet("allow_corner_cutting");
}

void GridPlanner::setFreeStartHeading(bool v)
{
    params_.freeStartHeading = v;
    parameterSet("free_start_heading");
}

void GridPlanner::setMatchGoalHeading(bool v)
{
    params_.matchGoalHeading = v;
    parameterSet("match_goal_heading");
}

void GridPlanner::setMaxMemoryMb(double mb)
{
    if (!std::isfinite(mb) || mb < 0.0 || mb > 1e7)
        throw std::invalid_argument(getName() + ": max_memory_mb must be 0 (no bound) or a size in MB up to 1e7");
    params_.maxMemoryMb = mb;
    parameterSet("max_memory_mb");
}

void GridPlanner::setTurningRadius(double r)
{
    if (!std::isfinite(r) || r < 0.0 || r > 1e4)
        throw std::invalid_argument(getName() + ": turning_radius must be 0 (automatic) or a length in (0, 10000] m");
    params_.turningRadius = r;
    parameterSet("turning_radius");
}

void GridPlanner::setLatticeCell(double m)
{
    if (!std::isfinite(m) || m < 0.0 || m > 1000.0)
        throw std::invalid_argument(getName() + ": lattice_cell must be 0 (automatic) or a length in (0, 1000] m");
    params_.latticeCell = m;
    parameterSet("lattice_cell");
}

CarLatticeConfig GridPlanner::carLatticeConfig() const { return carLatticeConfig(params_.car.primitives == PrimitiveSet::Hybrid); }

CarLatticeConfig GridPlanner::carLatticeConfig(bool hybrid) const
{
    const double rmin = turningRadius();
    CarLatticeConfig cfg;
    cfg.headings = params_.car.headings;
    if (checker_)
    {
        const VehicleParams &v = checker_->vehicle();
        const double res = checker_->grid().resolution();
        const double want = std::min(v.isPoint() ? 4 * res : v.width, rmin > 0 ? rmin : 4 * res) / 4;
        cfg.cell = params_.latticeCell > 0 ? params_.latticeCell : res * std::max(1.0, std::round(want / res));
        cfg.spacing = std::min(res, 0.1);
        cfg.reach = checker_->reach();
    }
    else
    {
        // any other validity checker: poses no farther apart than 0.1 m or OMPL's longest
        // valid segment, whichever is shorter (the checker sees poses only)
        cfg.cell = params_.latticeCell > 0 ? params_.latticeCell : rmin / 4;
        cfg.spacing = std::min({0.1, cfg.cell / 2, si_->getStateSpace()->getLongestValidSegmentLength()});
        cfg.reach = 0.0;
    }
    // arcs 1 % wider than R_min: sampled curves then stay within K_max by a clear margin
    cfg.turnRadius = rmin > 0 ? 1.01 * rmin : cfg.cell;
    cfg.reverse = reversing();
    // clothoid turns a little inside the rate, so that sampled paths measure within it
    if (params_.car.turns == TurnShape::Clothoid || (params_.car.turns == TurnShape::Auto && !hybrid))
    {
        const double sigma = params_.car.curvatureRate > 0 ? params_.car.curvatureRate : vehicle().curvatureRateLimit();
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
        if (params_.latticeCell > 0 && params_.car.primitives == PrimitiveSet::Hybrid)
            cfg.cell = params_.latticeCell;
        else
            cfg.cell = res > 0 ? res * std::max(1.0, std::floor(want / res)) : want;
        cfg.spacing = std::min(cfg.spacing, cfg.cell / 2);
    }
    return cfg;
}

}  // namespace gridcar
