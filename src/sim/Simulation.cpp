// The kinematic bicycle and paper C's potential-field path follower.
#include "gridcar/sim/Simulation.h"

#include "sim/Follower.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{

// ------------------------------------------------------------------ vehicle model
VehicleState stepBicycle(const VehicleState &s, const VehicleParams &v, double steerCmd, double speedCmd, double dt)
{
    VehicleState n = s;
    const double phi = v.maxSteerDeg * M_PI / 180.0;
    const double maxDs = v.maxSteerRateDeg * M_PI / 180.0 * dt;
    const double target = std::clamp(steerCmd, -phi, phi);
    n.steer = std::clamp(s.steer + std::clamp(target - s.steer, -maxDs, maxDs), -phi, phi);
    const double vt = std::clamp(speedCmd, 0.0, v.maxSpeed);
    n.v = std::clamp(s.v + std::clamp(vt - s.v, -v.deceleration * dt, v.acceleration * dt), 0.0, v.maxSpeed);
    const double vm = 0.5 * (s.v + n.v);  // trapezoid in speed: exact distance under constant acceleration
    n.x = s.x + vm * std::cos(s.yaw) * dt;
    n.y = s.y + vm * std::sin(s.yaw) * dt;
    n.yaw = wrapAngle(s.yaw + vm * std::tan(n.steer) / std::max(v.wheelbase, 1e-6) * dt);
    return n;
}

std::string DriveResult::outcomeName(Outcome o)
{
    switch (o)
    {
        case Outcome::Reached: return "reached";
        case Outcome::Collided: return "collided";
        case Outcome::Stuck: return "stuck";
        default: return "timeout";
    }
}

// ------------------------------------------------------------------ the follower
DriveResult drivePath(const std::vector<Pose2> &pathIn, const FootprintChecker &checker, const Scenario &scenario,
                      const FollowerParams &prm)
{
    DriveResult res;
    const VehicleParams &veh = checker.vehicle();
    const detail::TrackedPath path(pathIn, checker);
    if (path.pts.size() < 2)
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "the path has no length";
        return res;
    }
    if (!(prm.dt > 0) || !(veh.maxSpeed > 0) || !(veh.acceleration > 0) || !(veh.deceleration > 0))
        throw std::invalid_argument("drivePath needs dt > 0 and a vehicle with max_speed, acceleration, deceleration > 0");
    res.pathLength = path.total;
    const double tol = prm.goalTolerance > 0 ? prm.goalTolerance : std::max(0.3, checker.field().resolution());
    const double tmax = prm.timeLimit > 0 ? prm.timeLimit : 60.0 + 5.0 * path.total / veh.maxSpeed;
    detail::Follower follower(path, checker, scenario, prm);
    VehicleState st;
    st.x = path.pts.front().x;
    st.y = path.pts.front().y;
    st.yaw = std::atan2(path.pts[1].y - path.pts[0].y, path.pts[1].x - path.pts[0].x);
    double t = 0.0, ctSum = 0.0;
    std::size_t steps = 0;
    res.minClearance = detail::kInf;
    auto record = [&] {
        if (prm.recordTrajectory) res.trajectory.push_back({t, st.x, st.y, st.yaw, st.v, st.steer});
    };
    record();
    for (;;)
    {
        const double crossTrack = follower.project(st);
        ctSum += crossTrack;
        res.crossTrackMax = std::max(res.crossTrackMax, crossTrack);
        ++steps;
        const Pose2 &end = path.pts.back();
        if (std::hypot(st.x - end.x, st.y - end.y) <= tol && (follower.progress() >= path.total - 1e-3 || st.v <= 1e-3))
        {
            res.outcome = DriveResult::Outcome::Reached;
            res.reason = "reached the goal";
            break;
        }
        if (t >= tmax)
        {
            res.outcome = DriveResult::Outcome::Timeout;
            res.reason = "time limit " + std::to_string(tmax) + " s reached";
            break;
        }
        if (!follower.recover(st, t, res)) break;
        const double L = prm.lookaheadMin + prm.lookaheadTime * st.v;
        double fx, fy, rhoMin;
        follower.force(st, t, L, fx, fy, rhoMin);
        const double err = wrapAngle(std::atan2(fy, fx) - st.yaw);
        const double steerCmd = prm.headingGain * err;
        const double vCmd = follower.speedCommand(st, t, err, steerCmd, rhoMin, tol);
        double steerUse, vUse;
        follower.safeCommand(st, t, steerCmd, vCmd, steerUse, vUse);
        const VehicleState next = stepBicycle(st, veh, steerUse, vUse, prm.dt);
        res.distanceDriven += std::hypot(next.x - st.x, next.y - st.y);
        st = next;
        t += prm.dt;
        record();
        double clearance;
        if (!follower.bodyFree(st, t, res, clearance)) break;
        res.minClearance = std::min(res.minClearance, clearance);
    }
    res.drivingTime = t;
    res.crossTrackMean = steps ? ctSum / double(steps) : 0.0;
    if (!std::isfinite(res.minClearance)) res.minClearance = checker.clearance(st.x, st.y, st.yaw);
    return res;
}

}  // namespace gridcar
