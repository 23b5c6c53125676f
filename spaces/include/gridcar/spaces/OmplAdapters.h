#pragma once
/// @file OmplAdapters.h
/// @brief The FootprintChecker as OMPL's StateValidityChecker and MotionValidator.

#include "gridcar/collision/FootprintChecker.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/geometric/PathGeometric.h>

#include <memory>
#include <vector>

namespace gridcar
{
/// Validity = FootprintChecker::isValid at the SE(2) state; clearance() from the footprint.
class FootprintValidityChecker : public ompl::base::StateValidityChecker
{
public:
    FootprintValidityChecker(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const FootprintChecker> checker);
    bool isValid(const ompl::base::State *state) const override;
    double clearance(const ompl::base::State *state) const override;
    const FootprintChecker &checker() const { return *checker_; }

private:
    std::shared_ptr<const FootprintChecker> checker_;
};

/// Motion validity = FootprintChecker::isMotionValid (swept footprint, straight line in x-y,
/// yaw the shorter way, spacing a fraction of a cell).
class FootprintMotionValidator : public ompl::base::MotionValidator
{
public:
    FootprintMotionValidator(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const FootprintChecker> checker);
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                     std::pair<ompl::base::State *, double> &lastValid) const override;

private:
    std::shared_ptr<const FootprintChecker> checker_;
};

/// Pose of an SE(2) state.
Pose2 toPose(const ompl::base::State *state);
/// Sets an SE(2) state to a pose (yaw wrapped into OMPL's [-pi, pi)).
void setPose(ompl::base::State *state, const Pose2 &pose);
/// The poses of a geometric path on an SE(2) space.
std::vector<Pose2> toPoses(const ompl::geometric::PathGeometric &path);
/// A geometric path through @p poses (yaws wrapped into [-pi, pi)).
ompl::geometric::PathGeometric toPath(const ompl::base::SpaceInformationPtr &si, const std::vector<Pose2> &poses);

}  // namespace gridcar
