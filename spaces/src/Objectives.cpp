#include "gridcar/objectives/Objectives.h"
#include "gridcar/core/Errors.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/SE2StateSpace.h>

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace ob = ompl::base;

ObstacleDistanceObjective::ObstacleDistanceObjective(const ob::SpaceInformationPtr &si,
                                                     std::shared_ptr<const DistanceField> field, double delta,
                                                     bool voronoi)
  : ob::StateCostIntegralObjective(si, true), field_(std::move(field)), delta_(delta), voronoi_(voronoi)
{
    if (!field_) throw std::invalid_argument("ObstacleDistanceObjective needs a distance field");
    if (!std::isfinite(delta) || delta < 0) throw std::invalid_argument("obstacle cost delta must be finite and >= 0");
    description_ = "obstacle distance (delta / d_O integrated along the path)";
}

ob::Cost ObstacleDistanceObjective::stateCost(const ob::State *s) const
{
    const auto *se2 = s->as<ob::SE2StateSpace::StateType>();
    if (voronoi_) return ob::Cost(delta_ * field_->voronoiField(se2->getX(), se2->getY()));
    const double d = std::max(field_->distance(se2->getX(), se2->getY()), 0.5 * field_->resolution());
    return ob::Cost(delta_ / d);
}

DrivingTimeObjective::DrivingTimeObjective(const ob::SpaceInformationPtr &si, const VehicleParams &vehicle)
  : ob::OptimizationObjective(si), vehicle_(vehicle)
{
    if (!(vehicle.maxSpeed > 0) || !(vehicle.acceleration > 0) || !(vehicle.deceleration > 0))
        throw std::invalid_argument("DrivingTimeObjective needs max_speed, acceleration and deceleration > 0");
    description_ = "driving time (s)";
}

ob::Cost DrivingTimeObjective::stateCost(const ob::State *) const { return identityCost(); }

double DrivingTimeObjective::turnPenalty(double theta) const
{
    return cornerTimeLost(vehicle_, theta);
}

ob::Cost DrivingTimeObjective::motionCost(const ob::State *s1, const ob::State *s2) const
{
    const auto *a = s1->as<ob::SE2StateSpace::StateType>();
    const auto *b = s2->as<ob::SE2StateSpace::StateType>();
    const double dx = b->getX() - a->getX(), dy = b->getY() - a->getY();
    const double len = std::hypot(dx, dy);
    double t = len / vehicle_.maxSpeed;
    if (len > 1e-9) t += turnPenalty(wrapAngle(std::atan2(dy, dx) - a->getYaw()));
    return ob::Cost(t);
}

ob::Cost DrivingTimeObjective::motionCostHeuristic(const ob::State *s1, const ob::State *s2) const
{
    const auto *a = s1->as<ob::SE2StateSpace::StateType>();
    const auto *b = s2->as<ob::SE2StateSpace::StateType>();
    return ob::Cost(std::hypot(b->getX() - a->getX(), b->getY() - a->getY()) / vehicle_.maxSpeed);
}

std::vector<std::string> objectiveNames() { return {"length", "obstacle", "length+obstacle", "driving-time"}; }

ob::OptimizationObjectivePtr makeObjective(const std::string &name, const ob::SpaceInformationPtr &si,
                                           const FootprintChecker &checker, double delta)
{
    if (name == "length") return std::make_shared<ob::PathLengthOptimizationObjective>(si);
    if (name == "obstacle") return std::make_shared<ObstacleDistanceObjective>(si, checker.fieldPtr(), delta);
    if (name == "length+obstacle")
    {
        auto m = std::make_shared<ob::MultiOptimizationObjective>(si);
        m->addObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si), 1.0);
        m->addObjective(std::make_shared<ObstacleDistanceObjective>(si, checker.fieldPtr(), delta), 1.0);
        return m;
    }
    if (name == "driving-time") return std::make_shared<DrivingTimeObjective>(si, checker.vehicle());
    std::string list;
    for (const auto &n : objectiveNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown objective '" + printable(name) + "' (known: " + list + ")");
}

}  // namespace gridcar
