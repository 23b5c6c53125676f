#include "gridcar/spaces/CurveSpaces.h"

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace
{
using ompl::base::DubinsStateSpace;
using ompl::base::ReedsSheppStateSpace;
using SE2State = ompl::base::SE2StateSpace::StateType;

Pose2 poseOf(const ompl::base::State *s)
{
    const auto *st = s->as<SE2State>();
    return {st->getX(), st->getY(), st->getYaw()};
}

void setState(ompl::base::State *s, const Pose2 &p)
{
    auto *st = s->as<SE2State>();
    st->setXY(p.x, p.y);
    st->setYaw(wrapYaw(p.yaw));
}

/// The radius OMPL 1.5.2 keeps protected, read through a pointer to the member formed in a
/// derived class (legal C++: the access check is on the naming class).
struct DubinsRadius : DubinsStateSpace
{
    static double of(const DubinsStateSpace &s) { return s.*(&DubinsRadius::rho_); }
};
struct ReedsSheppRadius : ReedsSheppStateSpace
{
    static double of(const ReedsSheppStateSpace &s) { return s.*(&ReedsSheppRadius::rho_); }
};

Steer steerOfDubins(DubinsStateSpace::DubinsPathSegmentType t)
{
    return t == DubinsStateSpace::DUBINS_LEFT ? Steer::Left : t == DubinsStateSpace::DUBINS_RIGHT ? Steer::Right : Steer::Straight;
}
DubinsStateSpace::DubinsPathSegmentType dubinsOfSteer(Steer s)
{
    return s == Steer::Left ? DubinsStateSpace::DUBINS_LEFT : s == Steer::Right ? DubinsStateSpace::DUBINS_RIGHT : DubinsStateSpace::DUBINS_STRAIGHT;
}
ReedsSheppStateSpace::ReedsSheppPathSegmentType rsOfSteer(Steer s)
{
    return s == Steer::Left ? ReedsSheppStateSpace::RS_LEFT : s == Steer::Right ? ReedsSheppStateSpace::RS_RIGHT : ReedsSheppStateSpace::RS_STRAIGHT;
}

/// Interpolation along @p c from @p from: t in [0, 1] of its length; the end states exactly.
void interpolateCurve(const ompl::base::StateSpace &space, const ompl::base::State *from, const ompl::base::State *to,
                      const CarCurve &c, double t, ompl::base::State *state)
{
    if (c.empty() || !(t > 0)) space.copyState(state, from);
    else if (t >= 1 && to) space.copyState(state, to);
    else setState(state, curvePose(poseOf(from), c, std::min(t, 1.0) * c.length));
}

void checkRadius(double r)
{
    if (!(r > 0) || !std::isfinite(r)) throw std::invalid_argument("a car space needs a turning radius > 0");
}
}  // namespace

// ---------------------------------------------------------------- Dubins

DubinsSpace::DubinsSpace(double turningRadius) : DubinsStateSpace(turningRadius, false)
{
    checkRadius(turningRadius);
    setName("GridcarDubins" + getName());
}

CarCurve DubinsSpace::curve(const ompl::base::State *from, const ompl::base::State *to) const
{
    return dubinsCurve(poseOf(from), poseOf(to), rho_);
}

double DubinsSpace::distance(const ompl::base::State *a, const ompl::base::State *b) const { return curve(a, b).length; }

void DubinsSpace::interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                              ompl::base::State *state) const
{
    interpolateCurve(*this, from, to, curve(from, to), t, state);
}

void DubinsSpace::interpolate(const ompl::base::State *from, const ompl::base::State *to, double t, bool &firstTime,
                              DubinsPath &path, ompl::base::State *state) const
{
    if (firstTime)
    {
        // the curve into OMPL's path record (its three-letter word, lengths in radii)
        const CarCurve c = curve(from, to);
        firstTime = false;
        path.reverse_ = false;
        path.type_ = dubinsPathType[0];
        for (int i = 0; i < 3; ++i) path.length_[i] = 0.0;
        for (int row = 0; row < 6 && c.count == 3; ++row)
        {
            bool same = true;
            for (int i = 0; i < 3; ++i) same = same && dubinsPathType[row][i] == dubinsOfSteer(c.segments[std::size_t(i)].steer);
            if (!same) continue;
            path.type_ = dubinsPathType[row];
            for (int i = 0; i < 3; ++i) path.length_[i] = c.segments[std::size_t(i)].length / rho_;
        }
    }
    if (t >= 1) copyState(state, to);
    else interpolate(from, path, t, state);
}

void DubinsSpace::interpolate(const ompl::base::State *from, const DubinsPath &path, double t, ompl::base::State *state) const
{
    CarCurve c;
    c.radius = rho_;
    c.count = 3;
    c.length = 0.0;
    for (int i = 0; i < 3; ++i)
    {
        c.segments[std::size_t(i)] = {steerOfDubins(path.type_[i]), path.length_[i] * rho_};
        c.length += path.length_[i] * rho_;
    }
    interpolateCurve(*this, from, nullptr, c, t, state);
}

// ---------------------------------------------------------------- Reeds-Shepp

ReedsSheppSpace::ReedsSheppSpace(double turningRadius) : ReedsSheppStateSpace(turningRadius)
{
    checkRadius(turningRadius);
    setName("GridcarReedsShepp" + getName());
}

CarCurve ReedsSheppSpace::curve(const ompl::base::State *from, const ompl::base::State *to) const
{
    return reedsSheppCurve(poseOf(from), poseOf(to), rho_);
}

double ReedsSheppSpace::distance(const ompl::base::State *a, const ompl::base::State *b) const { return curve(a, b).length; }

void ReedsSheppSpace::interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                                  ompl::base::State *state) const
{
    interpolateCurve(*this, from, to, curve(from, to), t, state);
}

void ReedsSheppSpace::interpolate(const ompl::base::State *from, const ompl::base::State *to, double t, bool &firstTime,
                                  ReedsSheppPath &path, ompl::base::State *state) const
{
    if (firstTime)
    {
        // the curve into OMPL's path record: the row of its word in OMPL's table of 18
        const CarCurve c = curve(from, to);
        firstTime = false;
        double len[5] = {0, 0, 0, 0, 0};
        for (int i = 0; i < c.count; ++i) len[i] = c.segments[std::size_t(i)].length / rho_;
        int found = 0;  // the equal-poses curve (no segment): row 0 with lengths 0
        for (int row = 0; row < 18 && c.count > 0; ++row)
        {
            bool same = true;
            for (int i = 0; i < 5; ++i)
                same = same && reedsSheppPathType[row][i] == (i < c.count ? rsOfSteer(c.segments[std::size_t(i)].steer) : RS_NOP);
            if (same) found = row;
        }
        path = ReedsSheppPath(reedsSheppPathType[found], len[0], len[1], len[2], len[3], len[4]);
    }
    if (t >= 1) copyState(state, to);
    else interpolate(from, path, t, state);
}

void ReedsSheppSpace::interpolate(const ompl::base::State *from, const ReedsSheppPath &path, double t,
                                  ompl::base::State *state) const
{
    CarCurve c;
    c.radius = rho_;
    c.length = 0.0;
    for (int i = 0; i < 5 && path.type_[i] != RS_NOP; ++i)
    {
        const Steer s = path.type_[i] == RS_LEFT ? Steer::Left : path.type_[i] == RS_RIGHT ? Steer::Right : Steer::Straight;
        c.segments[std::size_t(c.count++)] = {s, path.length_[i] * rho_};
        c.length += std::abs(path.length_[i]) * rho_;
    }
    interpolateCurve(*this, from, nullptr, c, t, state);
}

// ---------------------------------------------------------------- any car space

double carSpaceTurningRadius(const ompl::base::StateSpace &space)
{
    if (const auto *d = dynamic_cast<const DubinsStateSpace *>(&space)) return DubinsRadius::of(*d);
    if (const auto *r = dynamic_cast<const ReedsSheppStateSpace *>(&space)) return ReedsSheppRadius::of(*r);
    return 0.0;
}

bool carSpaceCurve(const ompl::base::StateSpace &space, const ompl::base::State *a, const ompl::base::State *b,
                   CarCurve &curve)
{
    if (dynamic_cast<const DubinsStateSpace *>(&space))
        curve = dubinsCurve(poseOf(a), poseOf(b), carSpaceTurningRadius(space));
    else if (dynamic_cast<const ReedsSheppStateSpace *>(&space))
        curve = reedsSheppCurve(poseOf(a), poseOf(b), carSpaceTurningRadius(space));
    else
        return false;
    return !curve.empty();
}

std::vector<Pose2> carSpacePoses(const ompl::base::StateSpace &space, const ompl::geometric::PathGeometric &path,
                                 double step)
{
    std::vector<Pose2> out;
    if (path.getStateCount() == 0) return out;
    out.push_back(poseOf(path.getState(0)));
    for (std::size_t i = 1; i < path.getStateCount(); ++i)
    {
        const Pose2 a = poseOf(path.getState(i - 1)), b = poseOf(path.getState(i));
        CarCurve c;
        if (!carSpaceCurve(space, path.getState(i - 1), path.getState(i), c) || !(c.length > 0)) continue;
        std::vector<double> at;
        const int n = std::max(1, int(std::ceil(c.length / step)));
        for (int k = 1; k < n; ++k) at.push_back(c.length * k / n);
        double acc = 0;
        for (int k = 0; k + 1 < c.count; ++k)
        {
            acc += std::abs(c.segments[std::size_t(k)].length);
            if (acc > 0 && acc < c.length) at.push_back(acc);
        }
        std::sort(at.begin(), at.end());
        for (double s : at)
        {
            Pose2 p = curvePose(a, c, s);
            p.yaw = wrapYaw(p.yaw);
            out.push_back(p);
        }
        out.push_back(b);  // the state itself, exactly
    }
    return out;
}

}  // namespace gridcar
