/// @file GridPlannerParams.cpp
/// @brief GridPlanner's parameter setters (each validates, then redoes set-up) and the car
/// lattice's primitive set from them.
#include "gridcar/planners/GridPlanner.h"

#include "gridcar/core/Errors.h"
#include "gridcar/vehicle/Dynamics.h"

#include <ompl/base/spaces/DubinsStateSpace.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace
{
/// "on" / "off" for each way a switch is written (1 / 0, true / false, on / off, as OMPL's own
/// bool parameters and YAML take them; any case), else @p value as it is.
std::string switchWord(const std::string &value)
{
    std::string v = value;
    std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (v == "1" || v == "true" || v == "on") return "on";
    if (v == "0" || v == "false" || v == "off") return "off";
    return value;
}
}  // namespace

void GridPlanner::declareCarLatticeParams()
{
    declareParam<int>("headings", this, &GridPlanner::setLatticeHeadings, &GridPlanner::latticeHeadings, "8,16");
    declareParam<double>("heuristic_weight", this, &GridPlanner::setHeuristicWeight, &GridPlanner::heuristicWeight,
                         "1.:0.05:3.");
    declareParam<std::string>("reverse", this, &GridPlanner::setReverse, &GridPlanner::reverse, "off,on,auto");
    declareParam<double>("reverse_penalty", this, &GridPlanner::setReversePenalty, &GridPlanner::reversePenalty,
                         "1.:0.5:10.");
    declareParam<double>("cusp_penalty", this, &GridPlanner::setCuspPenalty, &GridPlanner::cuspPenalty, "0.:1.:100.");
    declareParam<std::string>("curve_heuristic", this, &GridPlanner::setCurveHeuristic, &GridPlanner::curveHeuristic,
                              "off,table,exact");
    declareParam<std::string>("primitives", this, &GridPlanner::setPrimitives, &GridPlanner::primitives, "auto,lattice,hybrid");
    declareParam<bool>("continuous_curvature", this, &GridPlanner::setContinuousCurvature, &GridPlanner::continuousCurvature,
                       "0,1");
    declareParam<double>("curvature_rate", this, &GridPlanner::setCurvatureRate, &GridPlanner::curvatureRateParam,
                         "0.:0.05:100.");
    declareParam<double>("cost_layer_weight", this, &GridPlanner::setCostLayerWeight, &GridPlanner::costLayerWeight,
                         "0.:0.5:100.");
    declareParam<std::string>("turns", this, &GridPlanner::setTurns, &GridPlanner::turns, "auto,arc,clothoid");
    declareParam<std::string>("shortcut", this, &GridPlanner::setShortcut, &GridPlanner::shortcut, "auto,on,off");
}

void GridPlanner::setShortcut(const std::string &mode)
{
    const std::string m = switchWord(mode);
    if (m != "auto" && m != "on" && m != "off")
        throw std::invalid_argument(getName() + ": shortcut must be auto, on (1, true) or off (0, false), got '" +
                                    printable(mode) + "'");
    params_.shortcut = m;
    parameterSet("shortcut");
}

void GridPlanner::setTurns(const std::string &t)
{
    if (t != "auto" && t != "arc" && t != "clothoid")
        throw std::invalid_argument(getName() + ": turns must be auto, arc or clothoid, got '" + printable(t) + "'");
    params_.turns = t;
    parameterSet("turns");
}

void GridPlanner::setCostLayerWeight(double w)
{
    if (!std::isfinite(w) || w < 0.0 || w > 1000.0)
        throw std::invalid_argument(getName() + ": cost_layer_weight must be in [0, 1000] (extra metres per metre at cost 252)");
    params_.costLayerWeight = w;
    parameterSet("cost_layer_weight");
}

void GridPlanner::setContinuousCurvature(bool on)
{
    params_.continuousCurvature = on;
    parameterSet("continuous_curvature");
}

void GridPlanner::setCurvatureRate(double rate)
{
    if (!std::isfinite(rate) || rate < 0.0 || rate > 1e4)
        throw std::invalid_argument(getName() + ": curvature_rate must be in [0, 10000] 1/m^2 (0: the vehicle's)");
    params_.curvatureRate = rate;
    parameterSet("curvature_rate");
}

double GridPlanner::curvatureRate() const
{
    if (!params_.continuousCurvature) return 0.0;
    if (params_.curvatureRate > 0) return params_.curvatureRate;
    const double r = vehicle().curvatureRateLimit();
    return std::isfinite(r) ? r : 0.0;
}

bool GridPlanner::matchGoalHeading() const
{
    return params_.matchGoalHeading.value_or(usesCarLattice());
}

void GridPlanner::setCurveHeuristic(const std::string &mode)
{
    // 0 and 1 as before the table existed: off, and the exact bound
    const std::string m = mode == "0" ? "off" : mode == "1" ? "exact" : mode;
    if (m != "off" && m != "table" && m != "exact")
        throw std::invalid_argument(getName() + ": curve_heuristic must be off, table or exact, got '" + printable(mode) +
                                    "'");
    params_.curveHeuristic = m;
    parameterSet("curve_heuristic");
}

double GridPlanner::curveWithin() const
{
    const CarLatticeSearch *search = carSearch();
    if (!search) return 0.0;
    const double R = search->lattice().config().turnRadius;
    // the table covers nodes within 10 R per axis of the goal's; exact, within 30 R of it
    return params_.curveHeuristic == "table" ? 10.0 * R : params_.curveHeuristic == "exact" ? 30.0 * R : 0.0;
}

void GridPlanner::setPrimitives(const std::string &p)
{
    if (p != "lattice" && p != "hybrid" && p != "auto")
        throw std::invalid_argument(getName() + ": primitives must be lattice, hybrid or auto, got '" + printable(p) + "'");
    params_.primitives = p;
    parameterSet("primitives");
}

void GridPlanner::setReverse(const std::string &value)
{
    const std::string r = switchWord(value);
    if (r != "off" && r != "on" && r != "auto")
        throw std::invalid_argument(getName() + ": reverse must be off (0, false), on (1, true) or auto, got '" +
                                    printable(value) + "'");
    params_.reverse = r;
    parameterSet("reverse");
}

void GridPlanner::setReversePenalty(double f)
{
    if (!std::isfinite(f) || f < 1.0 || f > 1000.0)
        throw std::invalid_argument(getName() + ": reverse_penalty must be a factor in [1, 1000]");
    params_.reversePenalty = f;
    parameterSet("reverse_penalty");
}

void GridPlanner::setCuspPenalty(double m)
{
    if (!std::isfinite(m) || m < 0.0 || m > 1e4)
        throw std::invalid_argument(getName() + ": cusp_penalty must be a length in [0, 10000] m");
    params_.cuspPenalty = m;
    parameterSet("cusp_penalty");
}

bool GridPlanner::onDubinsSpace() const
{
    return dynamic_cast<const ompl::base::DubinsStateSpace *>(si_->getStateSpace().get()) != nullptr;
}

bool GridPlanner::reversing() const
{
    if (params_.reverse == "off") return false;
    return !(onDubinsSpace() && params_.reverse == "auto");
}

double GridPlanner::cuspPenalty() const
{
    return params_.cuspPenalty ? *params_.cuspPenalty : gearChangeDistance(vehicle());
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

void GridPlanner::setHeuristicWeight(double w)
{
    if (!std::isfinite(w) || w < 1.0 || w > 100.0)
        throw std::invalid_argument(getName() + ": heuristic_weight must be a number in [1, 100]");
    params_.heuristicWeight = w;
    parameterSet("heuristic_weight");
}

void GridPlanner::setLatticeCell(double m)
{
    if (!std::isfinite(m) || m < 0.0 || m > 1000.0)
        throw std::invalid_argument(getName() + ": lattice_cell must be 0 (automatic) or a length in (0, 1000] m");
    params_.latticeCell = m;
    parameterSet("lattice_cell");
}

void GridPlanner::setLatticeHeadings(int h)
{
    if (h != 8 && h != 16)
        throw std::invalid_argument(getName() + ": headings must be 8 or 16 on the car lattice (the directions of lattice "
                                                "vectors: 32 or 72 equal steps do not land on nodes), got " +
                                    std::to_string(h));
    params_.headings = h;
    parameterSet("headings");
}

CarLatticeConfig GridPlanner::carLatticeConfig() const { return carLatticeConfig(params_.primitives == "hybrid"); }

CarLatticeConfig GridPlanner::carLatticeConfig(bool hybrid) const
{
    const double rmin = turningRadius();
    CarLatticeConfig cfg;
    cfg.headings = params_.headings;
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
    if (params_.turns == "clothoid" || (params_.turns == "auto" && !hybrid))
    {
        const double sigma = params_.curvatureRate > 0 ? params_.curvatureRate : vehicle().curvatureRateLimit();
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
        if (params_.latticeCell > 0 && params_.primitives == "hybrid")
            cfg.cell = params_.latticeCell;
        else
            cfg.cell = res > 0 ? res * std::max(1.0, std::floor(want / res)) : want;
        cfg.spacing = std::min(cfg.spacing, cfg.cell / 2);
    }
    return cfg;
}

}  // namespace gridcar
