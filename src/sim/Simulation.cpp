// The kinematic bicycle and paper C's potential-field path follower.
#include "gridcar/sim/Simulation.h"

#include "sim/Follower.h"
#include "sim/SteeringCuts.h"

#include "gridcar/core/Cusps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
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
        case Outcome::Interrupted: return "interrupted";
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
    if (v.hasPolygon())  // the polygon turned round with the heading
    {
        std::vector<std::array<double, 2>> turned = v.footprint;
        for (auto &q : turned) q = {-q[0], -q[1]};
        m.setFootprint(std::move(turned));
    }
    return m;
}

VehicleState turnedRound(VehicleState s)
{
    s.yaw = wrapAngle(s.yaw + M_PI);
    s.steer = -s.steer;
    s.v = -s.v;
    return s;
}

/// How far beside a cusp (m) a car stopped at the end of its piece may change gear and go on.
constexpr double kCuspReach = 1.0;

/// What the loop over a path's pieces shares.
struct DriveRun
{
    const Scenario &scenario;
    const FollowerParams &prm;
    double tol, tmax;
    DriveResult &res;
    double t{0.0}, ctSum{0.0};
    std::size_t steps{0};
    const FootprintChecker *car{nullptr};              ///< the vehicle driving forwards
    std::unique_ptr<FootprintChecker> *mirror{nullptr};  ///< the vehicle reversing (made on first use)
    bool manoeuvring{false};                            ///< inside a back-up manoeuvre

    /// The checker of the vehicle in the gear @p backward.
    const FootprintChecker &checkerFor(bool backward)
    {
        if (!backward) return *car;
        if (!*mirror) *mirror = std::make_unique<FootprintChecker>(car->gridPtr(), car->fieldPtr(), mirrored(car->vehicle()));
        return **mirror;
    }

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
        if (manoeuvring) follower.capSpeed(follower.crawl());
        double blockedSince = -1.0;
        int backUps = 0;
        bool stopping = false;  // interrupted, braking
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
            // interrupted: brake to a standstill, still steering along the path (a car braking
            // from speed with its wheels held leaves a curved road), or with interruptRolling
            // end the run at once, rolling
            if (!stopping && prm.interrupt && prm.interrupt(backward ? turnedRound(st) : st, t))
            {
                if (prm.interruptRolling) return interrupted(follower, st);
                stopping = true;
            }
            if (stopping && std::abs(st.v) <= 1e-9) return interrupted(follower, st);
            const Pose2 &end = path.pts.back();
            const double toEnd = std::hypot(st.x - end.x, st.y - end.y);
            // a cusp: within 0.1 m, or once stopped at the end beside it (the speed command stops
            // a step's minimum advance, 1 mm, short of the end). Beside a cusp the car cannot get
            // closer along this piece: the next piece, in the other gear, steers the offset back
            // (short pieces of a path that saws back and forth add up their offsets otherwise)
            if ((toEnd <= tolHere && (follower.progress() >= path.total - 1e-3 || st.v <= 1e-3)) ||
                (toEnd <= (last ? tol : kCuspReach) && follower.progress() >= path.total - 0.01 && st.v <= 1e-3))
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
            const double vCmd = stopping ? 0.0 : follower.speedCommand(st, t, err, steerCmd, rhoMin, tolHere);
            double steerUse, vUse;
            follower.safeCommand(st, t, steerCmd, vCmd, steerUse, vUse,
                                 path.followable ? feedForward + headingTerm + crossTerm : steerCmd);
            // standing still with every command refused by the safety rollout (the body off the
            // path beside an obstacle, its heading lagging at a corner): back up along the path
            // and approach again at a crawl, as a driver would, before the stuck rules apply
            if (follower.blocked() && std::abs(st.v) <= 1e-3)
            {
                if (blockedSince < 0) blockedSince = t;
                if (t - blockedSince >= 1.0 && !manoeuvring && backUps < prm.maxRecoveries)
                {
                    ++backUps;
                    blockedSince = -1.0;
                    if (!backUp(path, follower, st, backward)) return false;
                    continue;
                }
            }
            else
                blockedSince = -1.0;
            if (!step(follower, veh, st, steerUse, vUse, backward)) return false;
        }
    }

    /// The run interrupted, the car at a standstill (or rolling, with interruptRolling): false
    /// (res says Interrupted).
    bool interrupted(const detail::Follower &follower, const VehicleState &st)
    {
        res.outcome = DriveResult::Outcome::Interrupted;
        res.reason = "interrupted at " + follower.where(st);
        return false;
    }

    /// Backs the car up along the part of @p path it has driven (in the other gear, at a crawl)
    /// by max(1 m, half its length), then takes @p follower's progress back to where it stands
    /// and caps the speed up to a metre past the point where it stood blocked. False only when
    /// the run ended (a collision or the time limit: res says why); a back-up that does not get
    /// far leaves the car where it stopped and the follower's recoveries go on.
    bool backUp(const detail::TrackedPath &path, detail::Follower &follower, VehicleState &st, bool backward)
    {
        const double s0 = follower.progress();
        const double back = std::min(s0, std::max(1.0, 0.5 * car->vehicle().length));
        if (back < 0.2) return true;
        std::vector<Pose2> rev;
        double x, y;
        path.pointAt(s0, x, y);
        // the driven stretch backwards, the body turned round (the other gear's mirrored car)
        rev.push_back({x, y, wrapAngle(path.heading[path.segmentAt(s0)] + M_PI)});
        for (std::size_t i = path.pts.size(); i-- > 0;)
            if (path.cum[i] < s0 - 1e-6 && path.cum[i] > s0 - back + 1e-6)
                rev.push_back({path.pts[i].x, path.pts[i].y, wrapAngle(path.heading[i] + M_PI)});
        path.pointAt(s0 - back, x, y);
        rev.push_back({x, y, wrapAngle(path.heading[path.segmentAt(s0 - back)] + M_PI)});
        const FootprintChecker &other = checkerFor(!backward);
        const detail::TrackedPath backPath(rev, other);
        if (backPath.pts.size() < 2) return true;
        VehicleState b = turnedRound(st);
        const DriveResult::Outcome outcome = res.outcome;
        const std::string reason = res.reason;
        const int recoveries = res.recoveries;
        manoeuvring = true;
        const bool ok = piece(backPath, other, b, !backward, false);
        manoeuvring = false;
        if (!ok && res.outcome != DriveResult::Outcome::Stuck)
        {
            st = turnedRound(b);  // the run ends where the back-up got to (rolling, if interrupted)
            return false;
        }
        res.outcome = outcome, res.reason = reason, res.recoveries = recoveries;
        st = turnedRound(b);
        follower.rewind(std::max(0.0, s0 - back - 0.5), t, s0 + 1.0, follower.crawl());
        return true;
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
    // the pieces between cusps, each in its gear (a forward-only path is one piece), each cut
    // again where the car steers at a standstill (cutAtSteeringJumps)
    std::vector<PathPiece> pieces;
    for (PathPiece &p : splitAtCusps(pathIn))
    {
        double len = 0;
        for (std::size_t i = 1; i < p.poses.size(); ++i)
            len += std::hypot(p.poses[i].x - p.poses[i - 1].x, p.poses[i].y - p.poses[i - 1].y);
        if (len <= 1e-9) continue;
        for (std::vector<Pose2> &cut : detail::cutAtSteeringJumps(p.poses, checker)) pieces.push_back({std::move(cut), p.backward});
    }
    if (pieces.empty())
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "the path has no length";
        if (prm.startState)
            res.finalState = *prm.startState;  // nothing to drive: where it is (a rolling car is the caller's to brake)
        else if (!pathIn.empty())
            res.finalState = {pathIn.front().x, pathIn.front().y, pathIn.front().yaw, 0.0, 0.0};
        return res;
    }
    std::unique_ptr<FootprintChecker> reverseChecker;  // the mirrored vehicle, when a piece reverses or backs up
    const double tol = prm.goalTolerance > 0 ? prm.goalTolerance : std::max(0.3, checker.field().resolution());
    DriveRun run{scenario, prm, tol, 0.0, res};
    run.t = prm.startTime;
    run.car = &checker;
    run.mirror = &reverseChecker;
    // a rolling start: in the first piece's gear, its profile from the speed the car has
    const double rollIn = prm.startState ? std::abs(prm.startState->v) : 0.0;
    if (rollIn > 1e-9 && (prm.startState->v < 0) != pieces.front().backward)
        throw std::invalid_argument("drivePath: the vehicle rolls " + std::string(prm.startState->v < 0 ? "backwards" : "forwards") +
                                    " at " + std::to_string(rollIn) + " m/s into a path whose first piece is driven the other way");
    std::vector<std::unique_ptr<detail::TrackedPath>> tracked;
    double budget = 0.0;
    for (PathPiece &p : pieces)
    {
        const FootprintChecker &fc = run.checkerFor(p.backward);
        if (p.backward)
            for (Pose2 &q : p.poses) q.yaw = wrapAngle(q.yaw + M_PI);
        tracked.push_back(std::make_unique<detail::TrackedPath>(p.poses, fc, tracked.empty() ? rollIn : 0.0));
        res.pathLength += tracked.back()->total;
        // three times the piece's planned driving time (its velocity profile, corners and the
        // steering-rate cap included): 5 x length / v_max timed out a 30 m/s car on a campus
        budget += 10.0 + std::max(5.0 * tracked.back()->total / fc.vehicle().maxSpeed, 3.0 * tracked.back()->profile.time);
    }
    run.tmax = prm.startTime + (prm.timeLimit > 0 ? prm.timeLimit : 50.0 + budget);
    res.minClearance = detail::kInf;
    VehicleState st;
    if (prm.startState)  // in the first piece's frame (turned round for a reverse piece)
        st = pieces.front().backward ? turnedRound(*prm.startState) : *prm.startState;
    else
    {
        st.x = pieces.front().poses.front().x;
        st.y = pieces.front().poses.front().y;
        const auto &p0 = tracked.front()->pts;
        st.yaw = std::atan2(p0[1].y - p0[0].y, p0[1].x - p0[0].x);  // turned round already for a reverse piece
    }
    run.record(st, pieces.front().backward);
    bool ok = true, backward = pieces.front().backward;
    for (std::size_t k = 0; k < pieces.size() && ok; ++k)
    {
        if (k > 0 && pieces[k].backward != pieces[k - 1].backward) st = turnedRound(st);
        backward = pieces[k].backward;
        ok = run.piece(*tracked[k], run.checkerFor(backward), st, backward, k + 1 == pieces.size());
    }
    if (backward) st = turnedRound(st);
    const double headingOff = std::abs(wrapAngle(st.yaw - pathIn.back().yaw));
    if (ok && prm.goalYawTolerance > 0 && headingOff > prm.goalYawTolerance)
    {
        char buf[200];
        std::snprintf(buf, sizeof buf, "stopped at the goal with the heading %.1f deg off the path's end (goal yaw tolerance %.1f deg)",
                      headingOff * 180 / M_PI, prm.goalYawTolerance * 180 / M_PI);
        res.outcome = DriveResult::Outcome::Stuck;
        res.reason = buf;
    }
    else if (ok)
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "reached the goal";
    }
    res.finalState = st;
    res.drivingTime = run.t - prm.startTime;
    res.crossTrackMean = run.steps ? run.ctSum / double(run.steps) : 0.0;
    if (!std::isfinite(res.minClearance)) res.minClearance = checker.clearance(st.x, st.y, st.yaw);
    return res;
}

}  // namespace gridcar
