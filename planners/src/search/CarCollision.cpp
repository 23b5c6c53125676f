/// @file CarCollision.cpp
/// @brief The car lattice's collision queries: gridcar's FootprintChecker or any OMPL validity checker.
#include "gridcar/planners/search/CarCollision.h"

#include "gridcar/core/Angles.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/spaces/SE2StateSpace.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
bool CarCollision::fitsAtSomeHeading(double x, double y, int steps) const
{
    for (int k = 0; k < steps; ++k)
        if (poseFree({x, y, wrapYaw(k * 2.0 * M_PI / steps)})) return true;
    return false;
}

namespace
{
/// axesStanding()'s answer has a bit per axis: at most 32, and at most the headings set.
void checkAxes(int axes, std::size_t headings)
{
    if (axes < 0 || axes > 32 || std::size_t(axes) > headings)
        throw std::invalid_argument("CarCollision::axesStanding: " + std::to_string(axes) +
                                    " axes asked, at most 32 and at most the " + std::to_string(headings) +
                                    " headings set (setHeadings())");
}
}  // namespace

std::uint32_t CarCollision::axesStanding(double x, double y, int axes) const
{
    checkAxes(axes, 32);
    std::uint32_t m = 0;
    for (int h = 0; h < axes; ++h)
        if (mayStandOnAxis(x, y, h)) m |= std::uint32_t(1) << h;
    return m;
}

std::array<double, 4> FootprintCollision::extent() const
{
    const OccupancyGrid &g = c_.grid();
    return {g.originX(), g.originY(), g.originX() + g.sizeX(), g.originY() + g.sizeY()};
}

bool FootprintCollision::curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double m) const
{
    return curveFreeOriented(from, n, [&poseAt](int i) {
        const Pose2 p = poseAt(i);
        return OrientedPose{p, std::cos(p.yaw), std::sin(p.yaw)};
    }, m);
}

void FootprintCollision::setHeadings(const std::vector<double> &yaws)
{
    discs_.clear();
    discsBack_.clear();
    for (double y : yaws)
    {
        discs_.push_back(c_.inscribedDiscOffsets(y));
        discsBack_.push_back(c_.inscribedDiscOffsets(y + M_PI));
    }
}

bool FootprintCollision::mayStandOnAxis(double x, double y, int h) const
{
    // not proven blocked (a relaxation: the distance field's inscribed discs only); in open
    // ground one bit shows it for every heading
    if (c_.discsClearAtEveryYawAt(x, y)) return true;
    return !c_.provenBlockedAt(x, y, discs_[std::size_t(h)]) || !c_.provenBlockedAt(x, y, discsBack_[std::size_t(h)]);
}

std::uint32_t FootprintCollision::axesStanding(double x, double y, int axes) const
{
    checkAxes(axes, discs_.size());
    if (c_.discsClearAtEveryYawAt(x, y)) return axes >= 32 ? ~std::uint32_t(0) : (std::uint32_t(1) << axes) - 1;
    std::uint32_t m = 0;
    for (int h = 0; h < axes; ++h)
        if (!c_.provenBlockedAt(x, y, discs_[std::size_t(h)]) || !c_.provenBlockedAt(x, y, discsBack_[std::size_t(h)]))
            m |= std::uint32_t(1) << h;
    return m;
}

bool FootprintCollision::mayStandAt(double x, double y) const
{
    if (c_.discsClearAtEveryYawAt(x, y)) return true;
    for (const auto &d : discs_)
        if (!c_.provenBlockedAt(x, y, d)) return true;
    return false;
}

SpaceCollision::SpaceCollision(ompl::base::SpaceInformationPtr si) : si_(std::move(si))
{
    if (!si_ || !dynamic_cast<const ompl::base::SE2StateSpace *>(si_->getStateSpace().get()))
        throw std::invalid_argument("the car lattice needs a state space derived from ompl::base::SE2StateSpace");
    scratch_ = si_->allocState();
    scratchB_ = si_->allocState();
    const auto &b = si_->getStateSpace()->as<ompl::base::SE2StateSpace>()->getBounds();
    boundsLow_ = {b.low[0], b.low[1]};
    boundsHigh_ = {b.high[0], b.high[1]};
    boundsMargin_ = std::min(0.01, 1e-3 * std::hypot(b.high[0] - b.low[0], b.high[1] - b.low[1]));
}

SpaceCollision::~SpaceCollision()
{
    si_->freeState(scratch_);
    si_->freeState(scratchB_);
}

bool SpaceCollision::segmentFree(const Pose2 &a, const Pose2 &b) const
{
    setPose(scratch_, a);
    setPose(scratchB_, b);
    return si_->isValid(scratch_) && si_->isValid(scratchB_) && si_->checkMotion(scratch_, scratchB_);
}

std::array<double, 4> SpaceCollision::extent() const
{
    const auto &b = si_->getStateSpace()->as<ompl::base::SE2StateSpace>()->getBounds();
    return {b.low[0], b.low[1], b.high[0], b.high[1]};
}

bool SpaceCollision::poseFree(const Pose2 &p) const
{
    // a little inside the space's bounds (a thousandth of their diagonal, at most 1 cm): a path
    // along a bound is otherwise interpolated just outside it by OMPL's simplifier, whose repair
    // (PathGeometric::checkAndRepair(), OMPL 1.5) then samples near that state with bounds the
    // wrong way round and aborts on an assertion
    if (!(p.x >= boundsLow_[0] + boundsMargin_ && p.x <= boundsHigh_[0] - boundsMargin_ &&
          p.y >= boundsLow_[1] + boundsMargin_ && p.y <= boundsHigh_[1] - boundsMargin_))
        return false;
    auto *s = scratch_->as<ompl::base::SE2StateSpace::StateType>();
    s->setXY(p.x, p.y);
    s->setYaw(wrapYaw(p.yaw));
    return si_->satisfiesBounds(scratch_) && si_->isValid(scratch_);
}

bool SpaceCollision::curveFree(const Pose2 &, int n, const std::function<Pose2(int)> &poseAt, double) const
{
    for (int i = 1; i <= n; ++i)
        if (!poseFree(poseAt(i))) return false;
    return true;
}

bool SpaceCollision::mayStandOnAxis(double x, double y, int h) const
{
    const double yaw = yaws_[std::size_t(h)];
    return poseFree({x, y, yaw}) || poseFree({x, y, yaw + M_PI});
}

}  // namespace gridcar
