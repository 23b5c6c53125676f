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
    for (const auto &cand : candidates)
    {
        const double steer = cand[0] * (cand[2] > 0 ? steerTrack : steerCmd);
        VehicleState r = st;
        bool ok = true;
        double travelled = 0.0;
        for (int k = 1; k <= horizon && ok; ++k)
        {
            const double vStop = std::sqrt(2.0 * veh_.deceleration * std::max(remaining - travelled, 0.0));
            const VehicleState before = r;
            r = stepBicycle(r, veh_, steer, std::min(cand[1] * vCmd, vStop), prm_.dt);
            travelled += std::hypot(r.x - before.x, r.y - before.y);
            // every step: the body can swing into a corner between two checks further apart
            ok = checker_.isValid(r.x, r.y, r.yaw);
            for (const MovingObstacle &m : scenario_.obstacles)
            {
                if (!ok) break;
                double mx, my;
                m.positionAt(t + k * prm_.dt, mx, my);
                ok = m.distanceFrom(r.x + veh_.centreOffset() * std::cos(r.yaw), r.y + veh_.centreOffset() * std::sin(r.yaw),
                                    t + k * prm_.dt) > veh_.circumscribedRadius();
            }
        }
        if (ok)
        {
            steerUse = steer;
            vUse = cand[1] * vCmd;
            return;
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
