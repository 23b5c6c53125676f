#include "gridcar/spaces/CarSpaces.h"
#include "gridcar/core/Errors.h"

#include "gridcar/spaces/CurveSpaces.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
SpaceKind parseSpaceKind(const std::string &name)
{
    if (name == "se2") return SpaceKind::SE2;
    if (name == "dubins") return SpaceKind::Dubins;
    if (name == "reeds-shepp") return SpaceKind::ReedsShepp;
    throw std::invalid_argument("unknown state space '" + printable(name) + "' (choose se2, dubins or reeds-shepp)");
}

std::string spaceKindName(SpaceKind kind)
{
    switch (kind)
    {
        case SpaceKind::Dubins: return "dubins";
        case SpaceKind::ReedsShepp: return "reeds-shepp";
        default: return "se2";
    }
}

CurveMotionValidator::CurveMotionValidator(const ompl::base::SpaceInformationPtr &si,
                                           std::shared_ptr<const FootprintChecker> checker, double turningRadius,
                                           double step)
  : ompl::base::MotionValidator(si), checker_(std::move(checker)), radius_(turningRadius), step_(step)
{
    if (!(radius_ > 0) || !(step_ > 0)) throw std::invalid_argument("CurveMotionValidator needs a radius and a step > 0");
}

CurveMotionValidator::~CurveMotionValidator() = default;

int CurveMotionValidator::firstBlocked(const ompl::base::State *s1, const ompl::base::State *s2, int &n,
                                       bool endFirst) const
{
    const auto &space = si_->getStateSpace();
    // the car space's curve from gridcar's curve code, computed once and sampled
    CarCurve curve;
    const bool car = carSpaceCurve(*space, s1, s2, curve);
    const double len = car ? curve.length : space->distance(s1, s2);
    n = std::max(1, int(std::ceil(len * (1.0 + checker_->reach() / radius_) / step_)));
    if (endFirst && !checker_->isValid(toPose(s2))) return n;  // the cheapest rejection first
    ompl::base::State *tmp = si_->allocState();
    const Pose2 from = toPose(s1);
    int blocked = -1;
    for (int i = 1; i <= n && blocked < 0; ++i)
    {
        const double t = double(i) / n;
        Pose2 p;
        if (i == n) p = toPose(s2);
        else if (car) p = curvePose(from, curve, t * len);
        else
        {
            space->interpolate(s1, s2, t, tmp);
            p = toPose(tmp);
        }
        // the end state exactly (a state of the path, already valid by the checker); the poses
        // between with the rectangle grown by half the step: no body point moves farther than
        // the step between two poses, so the swept motion is certified, not only its samples
        if (!(i == n ? checker_->isValid(p) : checker_->isValidInflated(p, 0.5 * step_))) blocked = i;
    }
    si_->freeState(tmp);
    return blocked;
}

bool CurveMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const
{
    int n = 0;
    const bool ok = firstBlocked(s1, s2, n, true) < 0;
    if (ok) ++valid_;
    else ++invalid_;
    return ok;
}

bool CurveMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                       std::pair<ompl::base::State *, double> &lastValid) const
{
    int n = 0;
    const int b = firstBlocked(s1, s2, n, false);
    if (b < 0)
    {
        ++valid_;
        return true;
    }
    // the last valid pose is the one before the first blocked pose
    const double t = double(b - 1) / n;
    if (lastValid.first) si_->getStateSpace()->interpolate(s1, s2, t, lastValid.first);
    lastValid.second = t;
    ++invalid_;
    return false;
}

}  // namespace gridcar
