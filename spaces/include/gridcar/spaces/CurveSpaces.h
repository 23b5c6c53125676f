#pragma once
/// @file CurveSpaces.h
/// @brief OMPL's Dubins and Reeds-Shepp state spaces with gridcar's own curve code
/// (gridcar/curves/CarCurves.h) behind distance() and interpolate().
///
/// Debian's OMPL 1.5.2 is built with assertions, and its DubinsStateSpace asserts on rounding
/// errors that RRT, RRT* and BIT* produce now and then: the process aborts. These subclasses
/// are what makeGridSetup() hands to OMPL's planners; they are still a DubinsStateSpace /
/// ReedsSheppStateSpace (every OMPL planner, projection and dynamic_cast works as before), but
/// no call an OMPL planner makes through the StateSpace interface reaches OMPL's curve code.
/// (OMPL's non-virtual dubins() / reedsShepp() still run OMPL's code if called by name.)

#include "gridcar/core/Pose2.h"
#include "gridcar/curves/CarCurves.h"

#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/geometric/PathGeometric.h>

#include <vector>

namespace gridcar
{
/**
 * @brief ompl::base::DubinsStateSpace (forward-only car of turning radius R) whose distance
 * and interpolation come from gridcar::dubinsCurve.
 *
 * @par External documentation
 * A. M. Shkel and V. Lumelsky, "Classification of the Dubins set", Robotics and Autonomous
 * Systems 34(4):179-202, 2001.
 */
class DubinsSpace : public ompl::base::DubinsStateSpace
{
public:
    explicit DubinsSpace(double turningRadius);
    double turningRadius() const { return rho_; }
    /// The shortest Dubins curve between two states.
    CarCurve curve(const ompl::base::State *from, const ompl::base::State *to) const;

    double distance(const ompl::base::State *a, const ompl::base::State *b) const override;
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                     ompl::base::State *state) const override;
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t, bool &firstTime,
                     DubinsPath &path, ompl::base::State *state) const override;

protected:
    void interpolate(const ompl::base::State *from, const DubinsPath &path, double t,
                     ompl::base::State *state) const override;
};

/**
 * @brief ompl::base::ReedsSheppStateSpace (a car of turning radius R driving both ways) whose
 * distance and interpolation come from gridcar::reedsSheppCurve.
 *
 * @par External documentation
 * J. A. Reeds and L. A. Shepp, "Optimal paths for a car that goes both forwards and
 * backwards", Pacific Journal of Mathematics 145(2):367-393, 1990.
 */
class ReedsSheppSpace : public ompl::base::ReedsSheppStateSpace
{
public:
    explicit ReedsSheppSpace(double turningRadius);
    double turningRadius() const { return rho_; }
    /// The shortest Reeds-Shepp curve between two states.
    CarCurve curve(const ompl::base::State *from, const ompl::base::State *to) const;

    double distance(const ompl::base::State *a, const ompl::base::State *b) const override;
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                     ompl::base::State *state) const override;
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t, bool &firstTime,
                     ReedsSheppPath &path, ompl::base::State *state) const override;

protected:
    void interpolate(const ompl::base::State *from, const ReedsSheppPath &path, double t,
                     ompl::base::State *state) const override;
};

/// The turning radius of any Dubins or Reeds-Shepp space (gridcar's or OMPL's own); 0 for
/// any other space.
double carSpaceTurningRadius(const ompl::base::StateSpace &space);

/// The curve the car space @p space joins @p a and @p b with, from gridcar's curve code (for
/// OMPL's own Dubins / Reeds-Shepp spaces too: their radius, our curves); false for any
/// other space. A symmetric DubinsStateSpace is taken as the plain forward one.
bool carSpaceCurve(const ompl::base::StateSpace &space, const ompl::base::State *a, const ompl::base::State *b,
                   CarCurve &curve);

/// The poses along a path on a car space, its states joined by the space's curves: at most
/// @p step apart, every segment end (so every cusp) included exactly.
std::vector<Pose2> carSpacePoses(const ompl::base::StateSpace &space, const ompl::geometric::PathGeometric &path,
                                 double step);

}  // namespace gridcar
