#pragma once
// The state and the pieces of one step of paper C's potential-field follower (private to
// gridcar_core; drivePath() in Simulation.cpp runs the loop).
#include "gridcar/core/Angles.h"
#include "gridcar/path/PostProcess.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/vehicle/Dynamics.h"

#include "collision/detail/FclShapes.h"
#include "sim/Prediction.h"
#include "sim/TrackedPath.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace gridcar::detail
{
inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// The obstacle as an FCL object at time t (height 1, in the z = 0 plane like the vehicle).
inline std::unique_ptr<fcl::CollisionObjectd> fclObject(const MovingObstacle &o, double t)
{
    double x, y;
    o.positionAt(t, x, y);
    if (o.shape == MovingObstacle::Shape::Disc) return makeCylinder(x, y, o.radius);
    return makeBox(x, y, o.sizeX, o.sizeY);
}

/// The follower's state between steps and the pieces of one step (see drivePath()).
class Follower
{
public:
    Follower(const TrackedPath &path, const FootprintChecker &checker, const Scenario &scenario, const FollowerParams &prm)
      : path_(path), checker_(checker), veh_(checker.vehicle()), field_(checker.field()), scenario_(scenario), prm_(prm)
    {
        halfWidth_ = veh_.width / 2;
        aLat_ = lateralAccelLimit(veh_);
        creep_ = std::min(0.1 * veh_.maxSpeed, 0.5);  // a crawl, not 3 m/s for a 30 m/s car (it must stop at a cusp)
        frontOffset_ = std::max(veh_.length - veh_.rearOverhang, 0.0);
        brakeRange_ = veh_.maxSpeed * veh_.maxSpeed / (2.0 * veh_.deceleration) + prm_.rho0 + 1.0;
    }

    /// Projects the vehicle on the path (nearest point on segments near the last one, never far
    /// back); returns the cross-track distance. The scan stops where the path has turned by
    /// more than 270 degrees since the current segment: where a path turns a circle and comes
    /// back past the car, the later pass is the path still to drive, not where the car is
    /// (projected there, a car a little outside a circle as it began to turn cut across it).
    /// A corner or a hairpin (up to 180 degrees) the car cuts is still caught up with.
    double project(const VehicleState &st)
    {
        const auto &p = path_.pts;
        double best = kInf, bestS = sProj_, turned = 0.0;
        for (std::size_t i = seg_; i + 1 < p.size() && path_.cum[i] <= sProj_ + 3.0 * (prm_.lookaheadMin + 2.0); ++i)
        {
            if (i > seg_ && std::abs(turned += wrapAngle(path_.heading[i] - path_.heading[i - 1])) > 1.5 * M_PI) break;
            const double ax = p[i].x, ay = p[i].y, bx = p[i + 1].x, by = p[i + 1].y;
            const double len2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
            const double f = len2 > 0 ? std::clamp(((st.x - ax) * (bx - ax) + (st.y - ay) * (by - ay)) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(st.x - (ax + f * (bx - ax)), st.y - (ay + f * (by - ay)));
            if (d < best - 1e-12)
            {
                best = d;
                bestS = path_.cum[i] + f * std::sqrt(len2);
                // left of the path (seen along it) positive
                lateral_ = (bx - ax) * (st.y - ay) - (by - ay) * (st.x - ax) >= 0 ? d : -d;
            }
        }
        sProj_ = std::max(sProj_, bestS);
        while (seg_ + 2 < p.size() && path_.cum[seg_ + 1] <= sProj_) ++seg_;
        return best;
    }

    double progress() const { return sProj_; }
    /// "(x, y), s m of L m along the path" for messages.
    std::string where(const VehicleState &st) const
    {
        char buf[128];
        std::snprintf(buf, sizeof buf, "(%.2f, %.2f), %.2f m of %.2f m along the path", st.x, st.y, sProj_, path_.total);
        return buf;
    }
    /// Signed distance of the vehicle from the path at the last projection (left positive).
    double lateral() const { return lateral_; }
    /// The time the follower starts (a later piece of a path with cusps): progress is judged
    /// from then on.
    void startAt(double t) { markTime_ = t; }
    /// Takes the progress back to @p s at time @p t (the car backed up along the path to
    /// approach again), with the speed capped at @p vCap until @p capUntil along the path.
    void rewind(double s, double t, double capUntil, double vCap)
    {
        sProj_ = progressMark_ = std::clamp(s, 0.0, path_.total);
        seg_ = path_.segmentAt(sProj_);
        markTime_ = t;
        viaBoost_ = 0.0;
        capS_ = capUntil;
        capV_ = vCap;
    }
    /// Caps every speed command of this piece (a back-up manoeuvre is driven at a crawl).
    void capSpeed(double v)
    {
        capS_ = kInf;
        capV_ = v;
    }
    /// The crawl: the speed floor away from the end of the path, and the speed of manoeuvres.
    double crawl() const { return creep_; }
    /// The safety rollout found no command that keeps the body free (the last safeCommand()).
    bool blocked() const { return blocked_; }

    /// Progress bookkeeping and recovery: when progress along the path stalls for stuckWindow
    /// seconds, a virtual obstacle where the vehicle is and a via-point further on; false (and
    /// the reason in @p res) once maxRecoveries did not help.
    bool recover(const VehicleState &st, double t, DriveResult &res)
    {
        if (sProj_ > progressMark_ + std::max(0.2, 0.05 * prm_.lookaheadMin))
        {
            progressMark_ = sProj_;
            markTime_ = t;
            viaBoost_ = 0.0;
        }
        else if (t - markTime_ > prm_.stuckWindow)
        {
            if (res.recoveries >= prm_.maxRecoveries)
            {
                res.outcome = DriveResult::Outcome::Stuck;
                res.reason = "no progress along the path for " + std::to_string(int(prm_.stuckWindow)) + " s after " +
                             std::to_string(res.recoveries) + " recoveries, at " + where(st) + ": " +
                             (limit_.empty() ? std::string("a local minimum or oscillation of the potential field") : limit_);
                return false;
            }
            ++res.recoveries;
            virtualObstacles_.push_back(
                {st.x + veh_.centreOffset() * std::cos(st.yaw), st.y + veh_.centreOffset() * std::sin(st.yaw)});
            viaBoost_ += prm_.lookaheadMin + prm_.lookaheadTime * veh_.maxSpeed;
            markTime_ = t;
        }
        return true;
    }

    /// Via-point: look-ahead @p L along the path, the next corner as a sub-goal until the
    /// vehicle is within L / 2 of it.
    void viaPoint(const VehicleState &st, double L, double &vx, double &vy) const
    {
        // past the end of a path the car can follow, the via-point runs on along the end's
        // heading: aimed at the end point itself, the last metres would be driven at the point
        // (the heading off by the path's last bend, at a cusp the next piece's start off too)
        double viaS = path_.followable ? sProj_ + L + viaBoost_ : std::min(path_.total, sProj_ + L + viaBoost_);
        for (double cs : path_.cornerS)
            if (cs > sProj_ && cs < viaS)
            {
                double cx, cy;
                path_.pointAt(cs, cx, cy);
                if (std::hypot(cx - st.x, cy - st.y) > L / 2) viaS = cs;
                break;
            }
        path_.pointAt(std::min(viaS, path_.total), vx, vy);
        if (viaS > path_.total)
        {
            vx += (viaS - path_.total) * std::cos(path_.heading.back());
            vy += (viaS - path_.total) * std::sin(path_.heading.back());
        }
    }

    /// Attraction to the via-point (saturated) plus repulsion at the body's centre and front;
    /// @p rhoMin receives the least obstacle distance seen.
    void force(const VehicleState &st, double t, double L, double &fx, double &fy, double &rhoMin) const
    {
        double vx, vy;
        viaPoint(st, L, vx, vy);
        fx = prm_.xi * (vx - st.x), fy = prm_.xi * (vy - st.y);
        const double fa = std::hypot(fx, fy), fmax = prm_.xi * std::max(L, 1e-3);
        if (fa > fmax)
        {
            fx *= fmax / fa;
            fy *= fmax / fa;
        }
        // the map's influence distance shrinks to what the path itself leaves (its clearance at
        // the body point): where the planner threads a narrow passage, full-range repulsion would
        // only push the vehicle off the path into a local minimum (paper C's known weakness)
        const std::size_t at = std::min(seg_ + 1, path_.pts.size() - 1);
        rhoMin = kInf;
        const double off = veh_.centreOffset();
        const double frontOff = veh_.length - veh_.rearOverhang - halfWidth_;
        for (double o : {off, std::max(off, frontOff)})
        {
            const double own = o == off ? path_.clearCentre[at] : path_.clearFront[at];
            // (a path the car cannot follow exactly, a grid path's corners, keeps the margin)
            const double rho0Static = path_.followable ? std::clamp(std::min(own, path_.clear[at] + 0.3), 0.05, prm_.rho0)
                                                       : std::clamp(path_.clear[at] + 0.3, 0.3, prm_.rho0);
            const double px = st.x + o * std::cos(st.yaw), py = st.y + o * std::sin(st.yaw);
            auto push = [&](double rho, double gx, double gy, double r0) {
                rho = std::max(rho, 0.05);
                rhoMin = std::min(rhoMin, rho);
                if (rho >= r0) return;
                const double gn = std::hypot(gx, gy);
                if (gn < 1e-9) return;
                const double mag = prm_.eta * (1.0 / rho - 1.0 / r0) / (rho * rho);
                fx += mag * gx / gn;
                fy += mag * gy / gn;
            };
            double gx, gy;
            field_.gradient(px, py, gx, gy);
            push(field_.distance(px, py) - halfWidth_, gx, gy, rho0Static);
            for (const MovingObstacle &m : scenario_.obstacles)
            {
                double mx, my;
                m.positionAt(t, mx, my);
                push(m.distanceFrom(px, py, t) - halfWidth_, px - mx, py - my, prm_.rho0);
            }
            for (const auto &vo : virtualObstacles_)
                push(std::hypot(px - vo.first, py - vo.second) - 0.5 - halfWidth_, px - vo.first, py - vo.second, prm_.rho0);
        }
    }

    /// The speed command (see drivePath()).
    double speedCommand(const VehicleState &st, double t, double err, double steerCmd, double rhoMin, double tol) const
    {
        const double total = path_.total;
        const VelocityProfile &profile = path_.profile;
        // the path's profile where the vehicle will be after this step (braking follows the
        // profile, never above it), the profile a little ahead to start from rest
        const double nextS = sProj_ + std::max(st.v * prm_.dt, 1e-3);
        const double ahead = std::max(0.5, 2.0 * st.v * prm_.dt);
        const double startV = profile.speedAt(std::min(sProj_ + ahead, total)) >= profile.speedAt(sProj_)
                                  ? profile.speedAt(std::min(sProj_ + ahead, total)) : 0.0;
        const double toGoal = std::max(total - nextS, 0.0);
        const double floorV = toGoal > tol ? creep_ : 0.0;  // no creeping floor on the last metres: stop at the goal
        double vCmd = std::max({profile.speedAt(std::min(nextS, total)), startV, floorV});
        vCmd *= std::clamp(std::cos(err), 0.2, 1.0);
        if (rhoMin < prm_.rho0) vCmd *= std::clamp(rhoMin / prm_.rho0, 0.5, 1.0);
        const double phi = veh_.maxSteerDeg * M_PI / 180.0;
        const double tanSteer = std::abs(std::tan(std::clamp(steerCmd, -phi, phi)));
        if (tanSteer > 1e-6 && aLat_ > 0) vCmd = std::min(vCmd, std::sqrt(aLat_ * veh_.wheelbase / tanSteer));
        vCmd = std::min(vCmd, std::max(std::sqrt(2.0 * veh_.deceleration * toGoal), floorV));
        // never faster than lets the vehicle stop before what is straight ahead in its lane,
        // v <= sqrt(2 d (free - margin)): for moving obstacles down to a standstill (yield);
        // for the map and virtual obstacles down to a crawl, since the vehicle may be turning
        // away (the rollout keeps the body free)
        double freeMoving;
        const double freeStatic = freeAhead(st, t, freeMoving);
        const double margin = 0.1 + st.v * prm_.dt;
        const double crawl = std::min(0.2 * veh_.maxSpeed, 0.5);
        const double vStatic = std::max(std::sqrt(2.0 * veh_.deceleration * std::max(freeStatic - margin, 0.0)), crawl);
        const double vMoving = std::sqrt(2.0 * veh_.deceleration * std::max(freeMoving - margin, 0.0));
        char buf[160];
        if (vMoving < vCmd && vMoving <= vStatic)
        {
            std::snprintf(buf, sizeof buf, "a moving obstacle %.2f m ahead in the lane (the stopping-distance rule)", freeMoving);
            limit_ = buf;
        }
        else if (vStatic < vCmd)
        {
            std::snprintf(buf, sizeof buf, "the map or a virtual obstacle %.2f m ahead in the lane (the stopping-distance rule)",
                          freeStatic);
            limit_ = buf;
        }
        else if (rhoMin < prm_.rho0 && rhoMin < 0.2)
        {
            std::snprintf(buf, sizeof buf, "the repulsion of an obstacle %.2f m from the body (the potential field)", rhoMin);
            limit_ = buf;
        }
        else
            limit_.clear();
        if (sProj_ < capS_) vCmd = std::min(vCmd, capV_);
        return std::min({vCmd, vStatic, vMoving});
    }

    /// Safety filter: a car's body swings when it steers (the rear overhang moves the other
    /// way), so the commands are rolled out for a short horizon and softened until the rollout
    /// stays free; if nothing does, the vehicle brakes (and may end as stuck), with the
    /// command's steering if that braking stays free to the stop, else at speed with the
    /// steering whose braking stays free the longest.
    /// @p steerTrack: the steering that follows the path alone (feed-forward and the path's
    /// heading and cross-track errors, no potential field), tried right after the command
    /// itself: where the path passes an obstacle closely, softening a command the field has bent
    /// does not bring the body back to the path the planner checked.
    void safeCommand(const VehicleState &st, double t, double steerCmd, double vCmd, double &steerUse, double &vUse,
                     double steerTrack) const;

    /// True if the body at @p r keeps clear of every obstacle of the scenario at time @p t, by
    /// discs that cover its rectangle (conservative: a false answer may still be free).
    bool clearOfObstacles(const VehicleState &r, double t) const;

    /// Collision of the body with the map (FCL footprint checker) or a moving obstacle (FCL):
    /// false with the reason in @p res; else @p clearance is the body's clearance.
    bool bodyFree(const VehicleState &st, double t, DriveResult &res, double &clearance) const;

private:
    /// Free distance ahead of the front bumper in a lane of the body's width: of the map and
    /// the virtual obstacles (returned), and of the moving obstacles (@p freeMoving).
    double freeAhead(const VehicleState &q, double time, double &freeMoving) const
    {
        const double cx = std::cos(q.yaw), cy = std::sin(q.yaw);
        const double fx0 = q.x + frontOffset_ * cx, fy0 = q.y + frontOffset_ * cy;
        double free = brakeRange_;
        for (double sr = 0.0; sr < free;)
        {
            const double d = field_.distance(fx0 + sr * cx, fy0 + sr * cy);
            if (d <= halfWidth_ + 0.02)
            {
                free = sr;
                break;
            }
            sr += std::max(d - halfWidth_, 0.5 * field_.resolution());
        }
        auto lane = [&](double ox, double oy, double r, double &f) {
            const double along = (ox - fx0) * cx + (oy - fy0) * cy, lateral = std::abs(-(ox - fx0) * cy + (oy - fy0) * cx);
            if (along > -r && lateral < halfWidth_ + r) f = std::min(f, std::max(along - r, 0.0));
        };
        for (const auto &vo : virtualObstacles_) lane(vo.first, vo.second, 0.5, free);
        freeMoving = brakeRange_;
        for (const MovingObstacle &m : scenario_.obstacles)
        {
            double mx, my;
            m.positionAt(time, mx, my);
            const double r = m.shape == MovingObstacle::Shape::Disc ? m.radius : 0.5 * std::hypot(m.sizeX, m.sizeY);
            if (m.shape == MovingObstacle::Shape::Disc)
                lane(mx, my, r, freeMoving);
            else  // a box as it is (its circumscribed disc closes a lane that passes a long box's end)
                for (double sr = 0.0; sr < freeMoving;)
                {
                    const double d = m.distanceFrom(fx0 + sr * cx, fy0 + sr * cy, time);
                    if (d <= halfWidth_)
                    {
                        freeMoving = sr;
                        break;
                    }
                    sr += std::max(d - halfWidth_, 0.5 * field_.resolution());
                }
            const double vx = m.velocityEstimate(time, prm_.dt, 0), vy = m.velocityEstimate(time, prm_.dt, 1);
            const double horizon =
                std::min(20.0, std::max({6.0, q.v / veh_.deceleration + 2.0, brakeRange_ / std::max(q.v, 0.1)}));
            freeMoving = std::min(freeMoving, courseAhead(path_, seg_, sProj_, brakeRange_, veh_, mx, my, r, vx, vy, horizon));
        }
        return free;
    }

    const TrackedPath &path_;
    const FootprintChecker &checker_;
    const VehicleParams &veh_;
    const DistanceField &field_;
    const Scenario &scenario_;
    const FollowerParams &prm_;
    double halfWidth_, aLat_, creep_, frontOffset_, brakeRange_;
    double sProj_{0.0}, progressMark_{0.0}, markTime_{0.0}, viaBoost_{0.0}, lateral_{0.0};
    double capS_{-1.0}, capV_{kInf};  ///< speed cap up to this arc length (rewind(), capSpeed())
    mutable bool blocked_{false};
    std::size_t seg_{0};
    std::vector<std::pair<double, double>> virtualObstacles_;
    /// The rule that last held the vehicle back (empty: none), for the stop message.
    mutable std::string limit_;
};
}  // namespace gridcar::detail
