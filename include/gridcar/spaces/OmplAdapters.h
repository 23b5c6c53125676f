#pragma once
/// @file OmplAdapters.h
/// @brief The FootprintChecker as OMPL's StateValidityChecker and MotionValidator.

#include "gridcar/collision/FootprintChecker.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include <memory>

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

}  // namespace gridcar
