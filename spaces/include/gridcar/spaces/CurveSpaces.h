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

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace gridcar
{
/// A pose of an SE(2) state, and back (yaw wrapped into OMPL's range).
Pose2 poseOfSE2(const ompl::base::State *s);
void setSE2(ompl::base::State *s, const Pose2 &p);

/**
 * @brief What DubinsSpace and ReedsSheppSpace share: OMPL's car space @p Base whose distance()
 * and interpolate() come from gridcar's curve function @p CurveFn, and whose cached-path
 * interpolation (OMPL's `interpolate(from, to, t, firstTime, path, state)`, which OMPL's own
 * motion validators use) goes through @p Codec: our curve into @p Path (OMPL's record of a
 * curve: its word and lengths in radii) and back.
 */
template <class Base, class Path, CarCurve (*CurveFn)(const Pose2 &, const Pose2 &, double), class Codec>
class CurveSpace : public Base
{
public:
    CurveSpace(double turningRadius, const std::string &name) : Base(turningRadius)
    {
        if (!(turningRadius > 0) || !std::isfinite(turningRadius))
            throw std::invalid_argument("a car space needs a turning radius > 0");
        this->setName(name + this->getName());
    }
    double turningRadius() const { return this->rho_; }
    /// The shortest curve between two states.
    CarCurve curve(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return CurveFn(poseOfSE2(from), poseOfSE2(to), this->rho_);
    }
    double distance(const ompl::base::State *a, const ompl::base::State *b) const override { return curve(a, b).length; }
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                     ompl::base::State *state) const override
    {
        along(from, to, curve(from, to), t, state);
    }
    void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t, bool &firstTime, Path &path,
                     ompl::base::State *state) const override
    {
        if (firstTime)
        {
            path = Codec::toPath(curve(from, to), this->rho_);
            firstTime = false;
        }
        if (t >= 1) this->copyState(state, to);
        else interpolate(from, path, t, state);
    }

protected:
    void interpolate(const ompl::base::State *from, const Path &path, double t, ompl::base::State *state) const override
    {
        along(from, nullptr, Codec::fromPath(path, this->rho_), t, state);
    }

private:
    /// t in [0, 1] of the curve's length from @p from; the end states exactly.
    void along(const ompl::base::State *from, const ompl::base::State *to, const CarCurve &c, double t,
               ompl::base::State *state) const
    {
        if (c.empty() || !(t > 0)) this->copyState(state, from);
        else if (t >= 1 && to) this->copyState(state, to);
        else setSE2(state, curvePose(poseOfSE2(from), c, std::min(t, 1.0) * c.length));
    }
};

/// Our curves into OMPL's DubinsPath (a three-letter word, lengths in radii) and back.
struct DubinsCodec
{
    static ompl::base::DubinsStateSpace::DubinsPath toPath(const CarCurve &c, double radius);
    static CarCurve fromPath(const ompl::base::DubinsStateSpace::DubinsPath &p, double radius);
};
/// Our curves into OMPL's ReedsSheppPath (its table of 18 words) and back.
struct ReedsSheppCodec
{
    static ompl::base::ReedsSheppStateSpace::ReedsSheppPath toPath(const CarCurve &c, double radius);
    static CarCurve fromPath(const ompl::base::ReedsSheppStateSpace::ReedsSheppPath &p, double radius);
};

/**
 * @brief ompl::base::DubinsStateSpace (forward-only car of turning radius R) whose distance
 * and interpolation come from gridcar::dubinsCurve.
 *
 * @par External documentation
 * A. M. Shkel and V. Lumelsky, "Classification of the Dubins set", Robotics and Autonomous
 * Systems 34(4):179-202, 2001.
 */
class DubinsSpace
  : public CurveSpace<ompl::base::DubinsStateSpace, ompl::base::DubinsStateSpace::DubinsPath, dubinsCurve, DubinsCodec>
{
public:
    explicit DubinsSpace(double turningRadius) : CurveSpace(turningRadius, "GridcarDubins") {}
};

/**
 * @brief ompl::base::ReedsSheppStateSpace (a car of turning radius R driving both ways) whose
 * distance and interpolation come from gridcar::reedsSheppCurve.
 *
 * @par External documentation
 * J. A. Reeds and L. A. Shepp, "Optimal paths for a car that goes both forwards and
 * backwards", Pacific Journal of Mathematics 145(2):367-393, 1990.
 */
class ReedsSheppSpace : public CurveSpace<ompl::base::ReedsSheppStateSpace, ompl::base::ReedsSheppStateSpace::ReedsSheppPath,
                                          reedsSheppCurve, ReedsSheppCodec>
{
public:
    explicit ReedsSheppSpace(double turningRadius) : CurveSpace(turningRadius, "GridcarReedsShepp") {}
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
