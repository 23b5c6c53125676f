// The kinematic bicycle and paper C's potential-field path follower.
#include "gridcar/sim/Simulation.h"

#include "sim/Follower.h"

#include "gridcar/path/Cusps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

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
namespace
{
/// A car driven backwards is, kinematically, a car driven forwards with its heading turned
/// round, its steering negated and its overhangs swapped (the rear axle stays the reference
/// point; the body covers the same ground): the follower drives reverse pieces that way.
VehicleParams mirrored(const VehicleParams &v)
{
    VehicleParams m = v;
    m.rearOverhang = v.length - v.rearOverhang;
    m.maxSpeed = reverseSpeedLimit(v);
    m.cornerSpeed45 = std::min(m.cornerSpeed45, m.maxSpeed);
    m.cornerSpeed90 = std::min(m.cornerSpeed90, m.maxSpeed);
    m.cornerSpeed135 = std::min(m.cornerSpeed135, m.maxSpeed);
    m.name = v.name + " (reversing)";
    return m;
}

VehicleState turnedRound(VehicleState s)
{
    s.yaw = wrapAngle(s.yaw + M_PI);
    s.steer = -s.steer;
    s.v = -s.v;
    return s;
}

/// What the loop over a path's pieces shares.
struct DriveRun
{
    const Scenario &scenario;
    const FollowerParams &prm;
    double tol, tmax;
    DriveResult &res;
    double t{0.0}, ctSum{0.0};
    std::size_t steps{0};

    void record(const VehicleState &st, bool backward)
    {
        if (!prm.recordTrajectory) return;
        const VehicleState s = backward ? turnedRound(st) : st;
        res.trajectory.push_back({t, s.x, s.y, s.yaw, s.v, s.steer});
    }

    /// Drives one piece (forwards, on @p fc's vehicle) from @p st; true when its end is reached
    /// (and, unless it is the @p last, the vehicle stands still), false when the run ended (res
    /// says why).
    bool piece(const detail::TrackedPath &path, const FootprintChecker &fc, VehicleState &st, bool backward, bool last)
    {
        const VehicleParams &veh = fc.vehicle();
        detail::Follower follower(path, fc, scenario, prm);
        // a piece ending at a cusp ends where the next one starts: much closer than the goal
        // tolerance, or the next piece starts off its path with no steering reserve
        const double tolHere = last ? tol : std::min(tol, 0.1);
        // from rest, the wheels are turned to the path's curvature before the car moves (a
        // car steers at a standstill; starting to roll with the wheels on the last piece's lock
        // puts it off a path that may be at full lock from its first metre)
        if (path.followable && std::abs(st.v) < 1e-9)
        {
            const double want = std::atan(veh.wheelbase * path.kappa.front());
            for (int k = 0; k < int(3.0 / prm.dt) && std::abs(st.steer - want) > 1e-3; ++k)
                if (!step(follower, veh, st, want, 0.0, backward)) return false;
        }
        follower.startAt(t);
        for (;;)
        {
            const double crossTrack = follower.project(st);
            ctSum += crossTrack;
            res.crossTrackMax = std::max(res.crossTrackMax, crossTrack);
            ++steps;
            const Pose2 &end = path.pts.back();
            const double toEnd = std::hypot(st.x - end.x, st.y - end.y);
            // a cusp: within 0.1 m, or within the goal tolerance once stopped at the end
            if ((toEnd <= tolHere && (follower.progress() >= path.total - 1e-3 || st.v <= 1e-3)) ||
                (toEnd <= tol && follower.progress() >= path.total - 1e-3 && st.v <= 1e-3))
            {
                if (last) return true;
                // a cusp: stand still before the gear changes
                while (st.v > 1e-9)
                    if (!step(follower, veh, st, st.steer, 0.0, backward)) return false;
                return true;
            }
            if (t >= tmax)
            {
                res.outcome = DriveResult::Outcome::Timeout;
                res.reason = "time limit " + std::to_string(tmax) + " s reached at " + follower.where(st);
                return false;
            }
            if (!follower.recover(st, t, res)) return false;
            const double L = prm.lookaheadMin + prm.lookaheadTime * st.v;
            double fx, fy, rhoMin;
            follower.force(st, t, L, fx, fy, rhoMin);
            // on a path the car can drive (curvature within K_max): the via-point lies off
            // the path's tangent by the bend between them, which a car on the path sees too, so
            // only the rest is an error, and the path's own curvature steers forward (a car that
            // waits for the error to build up cuts every bend); at a kink (a grid path's corner)
            // paper C's rule alone: steer at the force
            const double s = follower.progress();
            const std::size_t sg = path.segmentAt(s), ahead = path.segmentAt(s + std::max(0.2, 0.3 * st.v));
            double bend = 0.0, feedForward = 0.0, crossTerm = 0.0, headingTerm = 0.0;
            if (path.followable)
            {
                double vx, vy, px, py;
                follower.viaPoint(st, L, vx, vy);
                path.pointAt(s, px, py);
                if (std::hypot(vx - px, vy - py) > 1e-6) bend = wrapAngle(std::atan2(vy - py, vx - px) - path.heading[sg]);
                feedForward = std::atan(veh.wheelbase * path.kappa[ahead]);
                // the cross-track error steered back directly (Stanley's term): the via-point
                // alone sees a lateral offset only as a small angle at a long look-ahead
                crossTerm = -std::atan(prm.crossTrackGain * follower.lateral() / (std::abs(st.v) + 0.5));
                headingTerm = wrapAngle(path.heading[sg] - st.yaw);
            }
            const double err = wrapAngle(std::atan2(fy, fx) - st.yaw - bend);
            const double steerCmd = feedForward + prm.headingGain * err + crossTerm;
            const double vCmd = follower.speedCommand(st, t, err, steerCmd, rhoMin, tolHere);
            double steerUse, vUse;
            follower.safeCommand(st, t, steerCmd, vCmd, steerUse, vUse,
                                 path.followable ? feedForward + headingTerm + crossTerm : steerCmd);
            if (!step(follower, veh, st, steerUse, vUse, backward)) return false;
        }
    }

    /// One simulated step with these commands, recorded and checked: false when the body hit
    /// something (res says what).
    bool step(const detail::Follower &follower, const VehicleParams &veh, VehicleState &st, double steer, double speed,
              bool backward)
    {
        const VehicleState next = stepBicycle(st, veh, steer, speed, prm.dt);
        res.distanceDriven += std::hypot(next.x - st.x, next.y - st.y);
        st = next;
        t += prm.dt;
        record(st, backward);
        double clearance;
        if (!follower.bodyFree(st, t, res, clearance)) return false;
        res.minClearance = std::min(res.minClearance, clearance);
        return true;
    }
};
}  // namespace

DriveResult drivePath(const std::vector<Pose2> &pathIn, const FootprintChecker &checker, const Scenario &scenario,
                      const FollowerParams &prm)
{
    DriveResult res;
    const VehicleParams &veh = checker.vehicle();
    if (!(prm.dt > 0) || !(veh.maxSpeed > 0) || !(veh.acceleration > 0) || !(veh.deceleration > 0))
        throw std::invalid_argument("drivePath needs dt > 0 and a vehicle with max_speed, acceleration, deceleration > 0");
    // the pieces between cusps, each in its gear (a forward-only path is one piece)
    std::vector<PathPiece> pieces;
    for (PathPiece &p : splitAtCusps(pathIn))
    {
        double len = 0;
        for (std::size_t i = 1; i < p.poses.size(); ++i)
            len += std::hypot(p.poses[i].x - p.poses[i - 1].x, p.poses[i].y - p.poses[i - 1].y);
        if (len > 1e-9) pieces.push_back(std::move(p));
    }
    if (pieces.empty())
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "the path has no length";
        return res;
    }
    std::unique_ptr<FootprintChecker> reverseChecker;  // the mirrored vehicle, when a piece reverses
    std::vector<std::unique_ptr<detail::TrackedPath>> tracked;
    double budget = 0.0;
    for (PathPiece &p : pieces)
    {
        if (p.backward && !reverseChecker)
            reverseChecker = std::make_unique<FootprintChecker>(checker.gridPtr(), checker.fieldPtr(), mirrored(veh));
        const FootprintChecker &fc = p.backward ? *reverseChecker : checker;
        if (p.backward)
            for (Pose2 &q : p.poses) q.yaw = wrapAngle(q.yaw + M_PI);
        tracked.push_back(std::make_unique<detail::TrackedPath>(p.poses, fc));
        res.pathLength += tracked.back()->total;
        // three times the piece's planned driving time (its velocity profile, corners and the
        // steering-rate cap included): 5 x length / v_max timed out a 30 m/s car on a campus
        budget += 10.0 + std::max(5.0 * tracked.back()->total / fc.vehicle().maxSpeed, 3.0 * tracked.back()->profile.time);
    }
    const double tol = prm.goalTolerance > 0 ? prm.goalTolerance : std::max(0.3, checker.field().resolution());
    DriveRun run{scenario, prm, tol, prm.timeLimit > 0 ? prm.timeLimit : 50.0 + budget, res};
    res.minClearance = detail::kInf;
    VehicleState st;
    st.x = pieces.front().poses.front().x;
    st.y = pieces.front().poses.front().y;
    const auto &p0 = tracked.front()->pts;
    st.yaw = std::atan2(p0[1].y - p0[0].y, p0[1].x - p0[0].x);  // turned round already for a reverse piece
    run.record(st, pieces.front().backward);
    bool ok = true;
    for (std::size_t k = 0; k < pieces.size() && ok; ++k)
    {
        if (k > 0 && pieces[k].backward != pieces[k - 1].backward) st = turnedRound(st);
        const FootprintChecker &fc = pieces[k].backward ? *reverseChecker : checker;
        ok = run.piece(*tracked[k], fc, st, pieces[k].backward, k + 1 == pieces.size());
    }
    if (ok)
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "reached the goal";
    }
    if (pieces.back().backward) st = turnedRound(st);
    res.drivingTime = run.t;
    res.crossTrackMean = run.steps ? run.ctSum / double(run.steps) : 0.0;
    if (!std::isfinite(res.minClearance)) res.minClearance = checker.clearance(st.x, st.y, st.yaw);
    return res;
}

}  // namespace gridcar
