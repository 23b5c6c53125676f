#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/SE2StateSpace.h>

#include <cmath>

namespace gridcar
{
Pose2 toPose(const ompl::base::State *state)
{
    const auto *s = state->as<ompl::base::SE2StateSpace::StateType>();
    return Pose2{s->getX(), s->getY(), s->getYaw()};
}

FootprintValidityChecker::FootprintValidityChecker(const ompl::base::SpaceInformationPtr &si,
                                                   std::shared_ptr<const FootprintChecker> checker)
  : ompl::base::StateValidityChecker(si), checker_(std::move(checker))
{
    specs_.clearanceComputationType = ompl::base::StateValidityCheckerSpecs::APPROXIMATE;
}

bool FootprintValidityChecker::isValid(const ompl::base::State *state) const
{
    const Pose2 p = toPose(state);
    return checker_->isValid(p.x, p.y, p.yaw);
}

double FootprintValidityChecker::clearance(const ompl::base::State *state) const
{
    const Pose2 p = toPose(state);
    return checker_->clearance(p.x, p.y, p.yaw);
}

FootprintMotionValidator::FootprintMotionValidator(const ompl::base::SpaceInformationPtr &si,
                                                   std::shared_ptr<const FootprintChecker> checker)
  : ompl::base::MotionValidator(si), checker_(std::move(checker))
{
}

bool FootprintMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const
{
    const bool ok = checker_->isMotionValid(toPose(s1), toPose(s2));
    if (ok) ++valid_;
    else ++invalid_;
    return ok;
}

bool FootprintMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                           std::pair<ompl::base::State *, double> &lastValid) const
{
    const Pose2 a = toPose(s1), b = toPose(s2);
    const int n = checker_->sweepSteps(a, b);
    const double dyaw = std::remainder(b.yaw - a.yaw, 2.0 * M_PI);
    bool ok = n > 0;
    double lastT = 0.0;
    for (int i = 1; ok && i <= n; ++i)
    {
        const double t = double(i) / n;
        if (!checker_->isValid(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.yaw + t * dyaw)) ok = false;
        else lastT = t;
    }
    if (!ok)
    {
        if (lastValid.first) si_->getStateSpace()->interpolate(s1, s2, lastT, lastValid.first);
        lastValid.second = lastT;
        ++invalid_;
    }
    else
        ++valid_;
    return ok;
}

}  // namespace gridcar
