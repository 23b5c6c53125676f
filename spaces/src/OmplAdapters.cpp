#include "gridcar/spaces/OmplAdapters.h"

#include "gridcar/core/Angles.h"

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

void setPose(ompl::base::State *state, const Pose2 &pose)
{
    auto *s = state->as<ompl::base::SE2StateSpace::StateType>();
    s->setXY(pose.x, pose.y);
    s->setYaw(wrapYaw(pose.yaw));
}

std::vector<Pose2> toPoses(const ompl::geometric::PathGeometric &path)
{
    std::vector<Pose2> out;
    out.reserve(path.getStateCount());
    for (std::size_t i = 0; i < path.getStateCount(); ++i) out.push_back(toPose(path.getState(i)));
    return out;
}

ompl::geometric::PathGeometric toPath(const ompl::base::SpaceInformationPtr &si, const std::vector<Pose2> &poses)
{
    ompl::geometric::PathGeometric path(si);
    ompl::base::State *tmp = si->allocState();
    for (const Pose2 &p : poses)
    {
        setPose(tmp, p);
        path.append(tmp);
    }
    si->freeState(tmp);
    return path;
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
    double lastT = 0.0;
    const bool ok = checker_->isMotionValid(toPose(s1), toPose(s2), &lastT);
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
