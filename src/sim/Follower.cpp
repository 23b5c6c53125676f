// The follower's safety rollout and body check (see Follower.h; drivePath() in Simulation.cpp
// runs the loop).
#include "sim/Follower.h"

namespace gridcar::detail
{
void Follower::safeCommand(const VehicleState &st, double t, double steerCmd, double vCmd, double &steerUse, double &vUse,
                          double steerTrack) const
{
    steerUse = steerCmd, vUse = 0.0;
    blocked_ = false;
    // {steering factor, speed factor, follow the path alone}
    const double candidates[][3] = {{1.0, 1.0, 0}, {1.0, 1.0, 1}, {1.0, 0.5, 1}, {0.5, 1.0, 0}, {0.0, 1.0, 0},
                                    {1.0, 0.5, 0}, {0.5, 0.5, 0}, {0.0, 0.5, 0}, {-0.5, 0.5, 0}};
    const int horizon = std::max(2, int(std::ceil(0.6 / prm_.dt)));
    // the rollout brakes for the end of the path (a cusp or the goal) as the speed command
    // does: rolled on at a constant speed it would run past the end of a piece that stops
    // short of a wall, and refuse every command on the last few decimetres into a tight slot
    const double remaining = std::max(path_.total - sProj_, 0.0);
    // steps of dt for which holding @p steer at speed command @p v keeps the body free (and
    // clear of the moving obstacles), at most @p steps
    const auto freeSteps = [&](double steer, double v, int steps) {
        VehicleState r = st;
        double travelled = 0.0;
        for (int k = 1; k <= steps; ++k)
        {
            const double vStop = std::sqrt(2.0 * veh_.deceleration * std::max(remaining - travelled, 0.0));
            const VehicleState before = r;
            r = stepBicycle(r, veh_, steer, std::min(v, vStop), prm_.dt);
            travelled += std::hypot(r.x - before.x, r.y - before.y);
            // every step: the body can swing into a corner between two checks further apart
            if (!checker_.isValid(r.x, r.y, r.yaw) || !clearOfObstacles(r, t + k * prm_.dt)) return k - 1;
        }
        return steps;
    };
    for (const auto &cand : candidates)
    {
        const double steer = cand[0] * (cand[2] > 0 ? steerTrack : steerCmd);
        if (freeSteps(steer, cand[1] * vCmd, horizon) == horizon)
        {
            steerUse = steer;
            vUse = cand[1] * vCmd;
            return;
        }
    }
    // Nothing keeps the body free for the horizon: brake, with the command's steering if the
    // braking stays free with it, else with the steering (the path's own, straight, half and
    // full lock either way) whose braking stays free the longest: braking with the refused
    // command swung a fast car's body into what the rollout saw (a pinch point taken 3 degrees
    // behind the path's heading at 5.5 m/s).
    if (st.v > 1e-3)
    {
        const double phi = veh_.maxSteerDeg * M_PI / 180.0;
        const int stop = std::max(2, int(std::ceil((st.v / std::max(veh_.deceleration, 1e-3) + 0.3) / prm_.dt)));
        int best = -1;
        for (const double steer : {steerCmd, steerTrack, 0.0, 0.5 * phi, -0.5 * phi, phi, -phi})
        {
            const int k = freeSteps(steer, 0.0, stop);
            if (k > best) best = k, steerUse = steer;
            if (k == stop) break;
        }
    }
    if (vCmd > 0)
    {
        blocked_ = true;
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "the safety rollout: no softened command keeps the body free for 0.6 s (steering %.2f rad asked, "
                      "body clearance %.2f m)",
                      steerCmd, checker_.clearance(st.x, st.y, st.yaw));
        limit_ = buf;
    }
}

bool Follower::clearOfObstacles(const VehicleState &r, double t) const
{
    if (scenario_.obstacles.empty()) return true;
    // the body's rectangle covered by n discs along its axis, each reaching the corners of its
    // slice (at most a width long, for bodies up to 32 widths long): an obstacle farther than a disc's radius from every centre
    // is clear of the body. The circumscribed disc alone refused every command of paper I's car
    // (2.9 m radius) with a box standing 2 m beside it; its discs reach 1.2 m
    const double len = std::max(veh_.length, 0.0), w = std::max(veh_.width, 0.0);
    const int n = int(std::clamp(std::ceil(len / std::max(w, 1e-6) - 1e-9), 1.0, 32.0));  // (a needle-thin body: 32)
    const double s = len / n, radius = std::hypot(w / 2, s / 2);
    const double c = std::cos(r.yaw), sn = std::sin(r.yaw);
    for (const MovingObstacle &m : scenario_.obstacles)
        for (int i = 0; i < n; ++i)
        {
            const double along = -veh_.rearOverhang + s * (i + 0.5);
            if (!(m.distanceFrom(r.x + along * c, r.y + along * sn, t) > radius)) return false;
        }
    return true;
}

bool Follower::bodyFree(const VehicleState &st, double t, DriveResult &res, double &clearance) const
{
    if (!checker_.isValid(st.x, st.y, st.yaw))
    {
        res.outcome = DriveResult::Outcome::Collided;
        res.reason = "hit the map at " + where(st);
        return false;
    }
    clearance = checker_.clearance(st.x, st.y, st.yaw);
    if (scenario_.obstacles.empty()) return true;
    auto body = vehicleBox(veh_, st.x, st.y, st.yaw);
    for (const MovingObstacle &m : scenario_.obstacles)
    {
        auto obj = fclObject(m, t);
        fcl::CollisionRequestd creq;
        fcl::CollisionResultd cres;
        if (fcl::collide(body.get(), obj.get(), creq, cres) > 0)
        {
            res.outcome = DriveResult::Outcome::Collided;
            res.reason = "hit moving obstacle '" + m.name + "' at t = " + std::to_string(t) + " s, at " + where(st);
            return false;
        }
        fcl::DistanceRequestd dreq;
        fcl::DistanceResultd dres;
        fcl::distance(body.get(), obj.get(), dreq, dres);
        clearance = std::min(clearance, dres.min_distance);
    }
    return true;
}

}  // namespace gridcar::detail
