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
}  // namespace

Pose2 poseOfSE2(const ompl::base::State *s)
{
    const auto *st = s->as<SE2State>();
    return {st->getX(), st->getY(), st->getYaw()};
}

void setSE2(ompl::base::State *s, const Pose2 &p)
{
    auto *st = s->as<SE2State>();
    st->setXY(p.x, p.y);
    st->setYaw(wrapYaw(p.yaw));
}

DubinsStateSpace::DubinsPath DubinsCodec::toPath(const CarCurve &c, double radius)
{
    // the equal-poses curve (no segment) stays row 0 with lengths 0
    DubinsStateSpace::DubinsPath path(DubinsStateSpace::dubinsPathType[0], 0.0, 0.0, 0.0);
    for (int row = 0; row < 6 && c.count == 3; ++row)
    {
        bool same = true;
        for (int i = 0; i < 3; ++i)
            same = same && DubinsStateSpace::dubinsPathType[row][i] == dubinsOfSteer(c.segments[std::size_t(i)].steer);
        if (!same) continue;
        path.type_ = DubinsStateSpace::dubinsPathType[row];
        for (int i = 0; i < 3; ++i) path.length_[i] = c.segments[std::size_t(i)].length / radius;
    }
    return path;
}

CarCurve DubinsCodec::fromPath(const DubinsStateSpace::DubinsPath &p, double radius)
{
    CarCurve c;
    c.radius = radius;
    c.count = 3;
    c.length = 0.0;
    for (int i = 0; i < 3; ++i)
    {
        c.segments[std::size_t(i)] = {steerOfDubins(p.type_[i]), p.length_[i] * radius};
        c.length += p.length_[i] * radius;
    }
    return c;
}

ReedsSheppStateSpace::ReedsSheppPath ReedsSheppCodec::toPath(const CarCurve &c, double radius)
{
    double len[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i < c.count; ++i) len[i] = c.segments[std::size_t(i)].length / radius;
    int found = 0;  // the equal-poses curve (no segment): row 0 with lengths 0
    for (int row = 0; row < 18 && c.count > 0; ++row)
    {
        bool same = true;
        for (int i = 0; i < 5; ++i)
            same = same && ReedsSheppStateSpace::reedsSheppPathType[row][i] ==
                               (i < c.count ? rsOfSteer(c.segments[std::size_t(i)].steer) : ReedsSheppStateSpace::RS_NOP);
        if (same) found = row;
    }
    return ReedsSheppStateSpace::ReedsSheppPath(ReedsSheppStateSpace::reedsSheppPathType[found], len[0], len[1], len[2], len[3],
                                                len[4]);
}

CarCurve ReedsSheppCodec::fromPath(const ReedsSheppStateSpace::ReedsSheppPath &p, double radius)
{
    CarCurve c;
    c.radius = radius;
    c.length = 0.0;
    for (int i = 0; i < 5 && p.type_[i] != ReedsSheppStateSpace::RS_NOP; ++i)
    {
        const Steer s = p.type_[i] == ReedsSheppStateSpace::RS_LEFT ? Steer::Left
                        : p.type_[i] == ReedsSheppStateSpace::RS_RIGHT ? Steer::Right
                                                                        : Steer::Straight;
        c.segments[std::size_t(c.count++)] = {s, p.length_[i] * radius};
        c.length += std::abs(p.length_[i]) * radius;
    }
    return c;
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
        curve = dubinsCurve(poseOfSE2(a), poseOfSE2(b), carSpaceTurningRadius(space));
    else if (dynamic_cast<const ReedsSheppStateSpace *>(&space))
        curve = reedsSheppCurve(poseOfSE2(a), poseOfSE2(b), carSpaceTurningRadius(space));
    else
        return false;
    return !curve.empty();
}

std::vector<Pose2> carSpacePoses(const ompl::base::StateSpace &space, const ompl::geometric::PathGeometric &path,
                                 double step)
{
    std::vector<Pose2> out;
    if (path.getStateCount() == 0) return out;
    out.push_back(poseOfSE2(path.getState(0)));
    for (std::size_t i = 1; i < path.getStateCount(); ++i)
    {
        const Pose2 a = poseOfSE2(path.getState(i - 1)), b = poseOfSE2(path.getState(i));
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
