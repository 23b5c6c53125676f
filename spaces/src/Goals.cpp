#include "gridcar/spaces/Goals.h"

#include "gridcar/core/Angles.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
PositionGoal::PositionGoal(const ompl::base::SpaceInformationPtr &si, double x, double y, double positionTolerance,
                           double yaw, double yawTolerance)
  : ompl::base::GoalSampleableRegion(si), x_(x), y_(y), yaw_(wrapYaw(yaw)), yawTol_(yawTolerance < 0 ? -1.0 : yawTolerance)
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
        throw std::invalid_argument("PositionGoal: position and yaw must be finite");
    if (!std::isfinite(positionTolerance) || positionTolerance < 0)
        throw std::invalid_argument("PositionGoal: position tolerance must be a finite number >= 0");
    if (std::isnan(yawTolerance)) throw std::invalid_argument("PositionGoal: yaw tolerance is NaN");
    setThreshold(positionTolerance);
}

double PositionGoal::distanceGoal(const ompl::base::State *st) const
{
    const auto *s = st->as<ompl::base::SE2StateSpace::StateType>();
    double d = std::hypot(s->getX() - x_, s->getY() - y_);
    if (yawTol_ >= 0)
    {
        const double excess = std::abs(wrapAngle(s->getYaw() - yaw_)) - yawTol_;
        if (excess > 0) d += excess;
    }
    return d;
}

bool PositionGoal::isSatisfied(const ompl::base::State *st, double *distance) const
{
    const auto *s = st->as<ompl::base::SE2StateSpace::StateType>();
    const double d = std::hypot(s->getX() - x_, s->getY() - y_);
    const double excess = yawTol_ >= 0 ? std::abs(wrapAngle(s->getYaw() - yaw_)) - yawTol_ : 0.0;
    if (distance) *distance = d + std::max(0.0, excess);
    // both tolerances on their own: a heading out of its tolerance is not made up for by a
    // position well within its own (distanceGoal() adds them, for ranking states only)
    return d <= getThreshold() && excess <= 1e-12;
}

void PositionGoal::sampleGoal(ompl::base::State *st) const
{
    if (yawTol_ >= 0)
    {
        setPose(st, {x_, y_, yaw_});
        return;
    }
    for (int k = 0; k < 72; ++k)
    {
        setPose(st, {x_, y_, wrapYaw(k * M_PI / 36)});
        if (si_->isValid(st)) return;
    }
    setPose(st, {x_, y_, 0.0});
}

}  // namespace gridcar
