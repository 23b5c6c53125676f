#pragma once
/// @file CarSpaces.h
/// @brief OMPL's car spaces for gridcar set-ups: which space a SimpleSetup plans on (plain
/// SE(2), Dubins or Reeds-Shepp at the vehicle's minimum turning radius), and a motion
/// validator that checks the vehicle's footprint along the space's own curves.

#include "gridcar/collision/FootprintChecker.h"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateSpace.h>

#include <memory>
#include <string>

namespace gridcar
{
/// The state space of a set-up.
enum class SpaceKind
{
    SE2,        ///< gridcar::GridSE2StateSpace: straight motions, the car may slide sideways
    Dubins,     ///< ompl::base::DubinsStateSpace: forward arcs of radius R_min and lines
    ReedsShepp  ///< ompl::base::ReedsSheppStateSpace: the same forwards and backwards (cusps)
};

/// "se2", "dubins" or "reeds-shepp" (std::invalid_argument naming the choices otherwise).
SpaceKind parseSpaceKind(const std::string &name);
std::string spaceKindName(SpaceKind kind);

/**
 * @brief Motion validity on a Dubins or Reeds-Shepp space: the footprint at poses along the
 * space's curve from s1 to s2, spaced so that no point of the vehicle moves more than @p step
 * metres between two of them (the curve's length x (1 + reach / R) / step poses), each pose
 * between the ends with the rectangle grown by step / 2 (FootprintChecker::isValidInflated), so
 * that the swept motion is free, not only its samples; the end state with the exact rectangle.
 * With the set-up's half a map cell, the car OMPL's planners drive is certified along its
 * whole path (up to the first half step after a state, which the state's own check covers
 * only exactly).
 */
class CurveMotionValidator : public ompl::base::MotionValidator
{
public:
    CurveMotionValidator(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<const FootprintChecker> checker,
                         double turningRadius, double step);
    ~CurveMotionValidator() override;
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                     std::pair<ompl::base::State *, double> &lastValid) const override;

private:
    /// Index of the first pose in collision (poses 1..n along the curve; with @p endFirst the
    /// end pose is tried before the others), or -1.
    int firstBlocked(const ompl::base::State *s1, const ompl::base::State *s2, int &n, bool endFirst) const;
    std::shared_ptr<const FootprintChecker> checker_;
    double radius_, step_;
};

}  // namespace gridcar
