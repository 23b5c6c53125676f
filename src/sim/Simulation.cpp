#include "gridcar/sim/Simulation.h"

#include "gridcar/io/Image.h"
#include "gridcar/objectives/Objectives.h"
#include "gridcar/path/PostProcess.h"

#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
double wrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

/// The obstacle as an FCL object at time t (height 1, in the z = 0 plane like the vehicle).
std::unique_ptr<fcl::CollisionObjectd> fclObject(const MovingObstacle &o, double t)
{
    double x, y;
    o.positionAt(t, x, y);
    std::shared_ptr<fcl::CollisionGeometryd> g;
    if (o.shape == MovingObstacle::Shape::Disc)
        g = std::make_shared<fcl::Cylinderd>(o.radius, 1.0);
    else
        g = std::make_shared<fcl::Boxd>(o.sizeX, o.sizeY, 1.0);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = fcl::Vector3d(x, y, 0.0);
    return std::make_unique<fcl::CollisionObjectd>(g, tf);
}

std::unique_ptr<fcl::CollisionObjectd> vehicleObject(const VehicleParams &v, double x, double y, double yaw)
{
    auto g = std::make_shared<fcl::Boxd>(std::max(v.length, 1e-3), std::max(v.width, 1e-3), 1.0);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    const double off = v.centreOffset();
    tf.translation() = fcl::Vector3d(x + off * std::cos(yaw), y + off * std::sin(yaw), 0.0);
    tf.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return std::make_unique<fcl::CollisionObjectd>(g, tf);
}
}  // namespace

// ------------------------------------------------------------------ moving obstacles
void MovingObstacle::positionAt(double t, double &x, double &y) const
{
    if (waypoints.empty())
    {
        x = y = 0.0;
        return;
    }
    x = waypoints.front().first;
    y = waypoints.front().second;
    if (waypoints.size() == 1 || speed <= 0.0 || t <= startTime) return;
    std::vector<std::pair<double, double>> pts = waypoints;
    if (loop) pts.push_back(waypoints.front());
    double total = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
        total += std::hypot(pts[i].first - pts[i - 1].first, pts[i].second - pts[i - 1].second);
    double travel = (t - startTime) * speed;
    if (loop && total > 0) travel = std::fmod(travel, total);
    for (std::size_t i = 1; i < pts.size(); ++i)
    {
        const double len = std::hypot(pts[i].first - pts[i - 1].first, pts[i].second - pts[i - 1].second);
        if (travel <= len && len > 0)
        {
            const double f = travel / len;
            x = pts[i - 1].first + f * (pts[i].first - pts[i - 1].first);
            y = pts[i - 1].second + f * (pts[i].second - pts[i - 1].second);
            return;
        }
        travel -= len;
    }
    x = pts.back().first;
    y = pts.back().second;
}

double MovingObstacle::distanceFrom(double px, double py, double t) const
{
    double x, y;
    positionAt(t, x, y);
    if (shape == Shape::Disc) return std::hypot(px - x, py - y) - radius;
    const double dx = std::abs(px - x) - sizeX / 2, dy = std::abs(py - y) - sizeY / 2;
    if (dx <= 0 && dy <= 0) return std::max(dx, dy);
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
}

Scenario Scenario::load(const std::string &file)
{
    Scenario sc;
    YAML::Node y;
    try
    {
        y = YAML::LoadFile(file);
    }
    catch (const YAML::BadFile &)
    {
        throw MapLoadError(file, "cannot open the scenario file");
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(file, "not valid YAML (" + std::string(e.what()) + ")");
    }
    if (!y.IsMap() || !y["obstacles"] || !y["obstacles"].IsSequence())
        throw MapLoadError(file, "expected 'obstacles:' with a list of moving obstacles");
    std::size_t i = 0;
    for (const auto &n : y["obstacles"])
    {
        ++i;
        const std::string where = "obstacle " + std::to_string(i) + ": ";
        MovingObstacle o;
        try
        {
            o.name = n["name"] ? n["name"].as<std::string>() : "obstacle " + std::to_string(i);
            const std::string shape = n["shape"] ? n["shape"].as<std::string>() : "disc";
            if (shape == "disc")
            {
                o.shape = MovingObstacle::Shape::Disc;
                if (n["radius"]) o.radius = n["radius"].as<double>();
            }
            else if (shape == "box")
            {
                o.shape = MovingObstacle::Shape::Box;
                if (!n["size"] || !n["size"].IsSequence() || n["size"].size() != 2)
                    throw MapLoadError(file, where + "a box needs size: [sx, sy]");
                o.sizeX = n["size"][0].as<double>();
                o.sizeY = n["size"][1].as<double>();
            }
            else
                throw MapLoadError(file, where + "shape must be disc or box, got '" + shape + "'");
            if (!n["waypoints"] || !n["waypoints"].IsSequence() || n["waypoints"].size() == 0)
                throw MapLoadError(file, where + "needs waypoints: [[x, y], ...]");
            for (const auto &w : n["waypoints"])
            {
                if (!w.IsSequence() || w.size() != 2) throw MapLoadError(file, where + "a waypoint must be [x, y]");
                o.waypoints.push_back({w[0].as<double>(), w[1].as<double>()});
            }
            if (n["speed"]) o.speed = n["speed"].as<double>();
            if (n["start_time"]) o.startTime = n["start_time"].as<double>();
            if (n["loop"]) o.loop = n["loop"].as<bool>();
        }
        catch (const YAML::Exception &e)
        {
            throw MapLoadError(file, where + "bad value (" + std::string(e.what()) + ")");
        }
        auto finite = [](double v) { return std::isfinite(v); };
        bool ok = finite(o.radius) && o.radius > 0 && finite(o.sizeX) && o.sizeX > 0 && finite(o.sizeY) && o.sizeY > 0 &&
                  finite(o.speed) && o.speed >= 0 && finite(o.startTime);
        for (const auto &w : o.waypoints) ok = ok && finite(w.first) && finite(w.second);
        if (!ok) throw MapLoadError(file, where + "sizes must be positive and all numbers finite");
        sc.obstacles.push_back(o);
    }
    return sc;
}

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
    const DistanceField &field = checker.field();
    std::vector<Pose2> path;
    for (const Pose2 &p : pathIn)
        if (path.empty() || std::hypot(p.x - path.back().x, p.y - path.back().y) > 1e-9) path.push_back(p);
    if (path.size() < 2)
    {
        res.outcome = DriveResult::Outcome::Reached;
        res.reason = "the path has no length";
        return res;
    }
    if (!(prm.dt > 0) || !(veh.maxSpeed > 0) || !(veh.acceleration > 0) || !(veh.deceleration > 0))
        throw std::invalid_argument("drivePath needs dt > 0 and a vehicle with max_speed, acceleration, deceleration > 0");
    // arc length of the path's vertices
    std::vector<double> cum{0.0};
    for (std::size_t i = 1; i < path.size(); ++i)
        cum.push_back(cum.back() + std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y));
    const double total = cum.back();
    res.pathLength = total;
    auto pointAt = [&](double s, double &x, double &y) {
        s = std::clamp(s, 0.0, total);
        const std::size_t i = std::min<std::size_t>(path.size() - 1,
                                                    std::size_t(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin()));
        const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? 1 : i;
        const double len = cum[b] - cum[a];
        const double f = len > 0 ? (s - cum[a]) / len : 0.0;
        x = path[a].x + f * (path[b].x - path[a].x);
        y = path[a].y + f * (path[b].y - path[a].y);
    };
    // corners (sub-goals): turning points that turn by more than 10 degrees
    std::vector<double> cornerS;
    {
        const std::vector<Pose2> tp = turningPoints(path);
        std::size_t j = 0;
        for (std::size_t i = 1; i + 1 < tp.size(); ++i)
        {
            const double h0 = std::atan2(tp[i].y - tp[i - 1].y, tp[i].x - tp[i - 1].x);
            const double h1 = std::atan2(tp[i + 1].y - tp[i].y, tp[i + 1].x - tp[i].x);
            while (j < path.size() && (path[j].x != tp[i].x || path[j].y != tp[i].y)) ++j;
            if (j < path.size() && std::abs(wrapAngle(h1 - h0)) > 10.0 * M_PI / 180.0) cornerS.push_back(cum[j]);
        }
    }
    const VelocityProfile profile = velocityProfile(path, veh);
    std::vector<double> pathClear;  // d_O - half width at the path's vertices (min with the previous one)
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        const double c = field.distance(path[i].x, path[i].y) - veh.width / 2;
        pathClear.push_back(i ? std::min(c, field.distance(path[i - 1].x, path[i - 1].y) - veh.width / 2) : c);
    }
    const double halfWidth = veh.width / 2;
    const double tol = prm.goalTolerance > 0 ? prm.goalTolerance : std::max(0.3, field.resolution());
    const double tmax = prm.timeLimit > 0 ? prm.timeLimit : 60.0 + 5.0 * total / veh.maxSpeed;
    const double aLat = std::min(veh.friction * 9.81, veh.maxLateralAccel);
    const double creep = 0.1 * veh.maxSpeed;

    std::vector<std::pair<double, double>> virtualObstacles;
    const double frontOffset = std::max(veh.length - veh.rearOverhang, 0.0);
    const double brakeRange = veh.maxSpeed * veh.maxSpeed / (2.0 * veh.deceleration) + prm.rho0 + 1.0;
    // free distance ahead of the front bumper in a lane of the body's width: of the map and
    // the virtual obstacles (static), and of the moving obstacles
    auto freeAhead = [&](const VehicleState &q, double time, double &freeMoving) {
        const double cx = std::cos(q.yaw), cy = std::sin(q.yaw);
        const double fx0 = q.x + frontOffset * cx, fy0 = q.y + frontOffset * cy;
        double free = brakeRange;
        for (double sr = 0.0; sr < free;)
        {
            const double d = field.distance(fx0 + sr * cx, fy0 + sr * cy);
            if (d <= halfWidth + 0.02)
            {
                free = sr;
                break;
            }
            sr += std::max(d - halfWidth, 0.5 * field.resolution());
        }
        auto lane = [&](double ox, double oy, double r, double &f) {
            const double along = (ox - fx0) * cx + (oy - fy0) * cy, lateral = std::abs(-(ox - fx0) * cy + (oy - fy0) * cx);
            if (along > -r && lateral < halfWidth + r) f = std::min(f, std::max(along - r, 0.0));
        };
        for (const auto &vo : virtualObstacles) lane(vo.first, vo.second, 0.5, free);
        freeMoving = brakeRange;
        for (const MovingObstacle &m : scenario.obstacles)
        {
            double mx, my;
            m.positionAt(time, mx, my);
            lane(mx, my, m.shape == MovingObstacle::Shape::Disc ? m.radius : 0.5 * std::hypot(m.sizeX, m.sizeY), freeMoving);
        }
        return free;
    };
    VehicleState st;
    st.x = path.front().x;
    st.y = path.front().y;
    st.yaw = std::atan2(path[1].y - path[0].y, path[1].x - path[0].x);
    double t = 0.0, sProj = 0.0, progressMark = 0.0, markTime = 0.0, viaBoost = 0.0, ctSum = 0.0;
    std::size_t seg = 0, steps = 0;
    res.minClearance = kInf;
    auto record = [&] {
        if (prm.recordTrajectory) res.trajectory.push_back({t, st.x, st.y, st.yaw, st.v, st.steer});
    };
    record();
    for (;;)
    {
        // projection on the path: nearest point on segments near the last one (never far back)
        double best = kInf, bestS = sProj;
        for (std::size_t i = seg; i + 1 < path.size() && cum[i] <= sProj + 3.0 * (prm.lookaheadMin + 2.0); ++i)
        {
            const double ax = path[i].x, ay = path[i].y, bx = path[i + 1].x, by = path[i + 1].y;
            const double len2 = (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
            const double f = len2 > 0 ? std::clamp(((st.x - ax) * (bx - ax) + (st.y - ay) * (by - ay)) / len2, 0.0, 1.0) : 0.0;
            const double d = std::hypot(st.x - (ax + f * (bx - ax)), st.y - (ay + f * (by - ay)));
            if (d < best - 1e-12)
            {
                best = d;
                bestS = cum[i] + f * std::sqrt(len2);
            }
        }
        sProj = std::max(sProj, bestS);
        while (seg + 2 < path.size() && cum[seg + 1] <= sProj) ++seg;
        ctSum += best;
        res.crossTrackMax = std::max(res.crossTrackMax, best);
        ++steps;

        // outcome checks
        if (std::hypot(st.x - path.back().x, st.y - path.back().y) <= tol && (sProj >= total - 1e-3 || st.v <= 1e-3))
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
        if (sProj > progressMark + std::max(0.2, 0.05 * prm.lookaheadMin))
        {
            progressMark = sProj;
            markTime = t;
            viaBoost = 0.0;
        }
        else if (t - markTime > prm.stuckWindow)
        {
            if (res.recoveries >= prm.maxRecoveries)
            {
                res.outcome = DriveResult::Outcome::Stuck;
                res.reason = "no progress along the path for " + std::to_string(int(prm.stuckWindow)) + " s after " +
                             std::to_string(res.recoveries) + " recoveries (local minimum or oscillation)";
                break;
            }
            // recovery: a virtual obstacle where the vehicle is stuck, and a via-point further on
            ++res.recoveries;
            virtualObstacles.push_back({st.x + veh.centreOffset() * std::cos(st.yaw), st.y + veh.centreOffset() * std::sin(st.yaw)});
            viaBoost += prm.lookaheadMin + prm.lookaheadTime * veh.maxSpeed;
            markTime = t;
        }

        // via-point: look-ahead along the path, the next corner as a sub-goal
        const double L = prm.lookaheadMin + prm.lookaheadTime * st.v;
        double viaS = std::min(total, sProj + L + viaBoost);
        for (double cs : cornerS)
            if (cs > sProj && cs < viaS)
            {
                double cx, cy;
                pointAt(cs, cx, cy);
                if (std::hypot(cx - st.x, cy - st.y) > L / 2) viaS = cs;
                break;
            }
        double vx, vy;
        pointAt(viaS, vx, vy);
        double fx = prm.xi * (vx - st.x), fy = prm.xi * (vy - st.y);
        const double fa = std::hypot(fx, fy), fmax = prm.xi * std::max(L, 1e-3);
        if (fa > fmax)
        {
            fx *= fmax / fa;
            fy *= fmax / fa;
        }
        // repulsion at the body's centre and front; the map's influence distance shrinks to what
        // the path itself leaves (its clearance here + 0.3 m): where the planner threads a
        // narrow passage, full-range repulsion would only push the vehicle off the path into a
        // local minimum (paper C's known weakness in narrow passages)
        const double rho0Static = std::clamp(pathClear[std::min(seg + 1, path.size() - 1)] + 0.3, 0.3, prm.rho0);
        double rhoMin = kInf;
        const double off = veh.centreOffset();
        const double frontOff = veh.length - veh.rearOverhang - halfWidth;
        for (double o : {off, std::max(off, frontOff)})
        {
            const double px = st.x + o * std::cos(st.yaw), py = st.y + o * std::sin(st.yaw);
            auto push = [&](double rho, double gx, double gy, double r0) {
                rho = std::max(rho, 0.05);
                rhoMin = std::min(rhoMin, rho);
                if (rho >= r0) return;
                const double gn = std::hypot(gx, gy);
                if (gn < 1e-9) return;
                const double mag = prm.eta * (1.0 / rho - 1.0 / r0) / (rho * rho);
                fx += mag * gx / gn;
                fy += mag * gy / gn;
            };
            double gx, gy;
            field.gradient(px, py, gx, gy);
            push(field.distance(px, py) - halfWidth, gx, gy, rho0Static);
            for (const MovingObstacle &m : scenario.obstacles)
            {
                double mx, my;
                m.positionAt(t, mx, my);
                push(m.distanceFrom(px, py, t) - halfWidth, px - mx, py - my, prm.rho0);
            }
            for (const auto &vo : virtualObstacles)
                push(std::hypot(px - vo.first, py - vo.second) - 0.5 - halfWidth, px - vo.first, py - vo.second, prm.rho0);
        }
        const double desired = std::atan2(fy, fx);
        const double err = wrapAngle(desired - st.yaw);
        const double steerCmd = prm.headingGain * err;
        // speed: the path's profile where the vehicle will be after this step (braking follows
        // the profile, never above it), the profile a little ahead to start from rest
        const double nextS = sProj + std::max(st.v * prm.dt, 1e-3);
        const double ahead = std::max(0.5, 2.0 * st.v * prm.dt);
        const double startV = profile.speedAt(std::min(sProj + ahead, total)) >= profile.speedAt(sProj)
                                  ? profile.speedAt(std::min(sProj + ahead, total)) : 0.0;
        const double toGoal = std::max(total - nextS, 0.0);
        const double floorV = toGoal > tol ? creep : 0.0;  // no creeping floor on the last metres: stop at the goal
        double vCmd = std::max({profile.speedAt(std::min(nextS, total)), startV, floorV});
        vCmd *= std::clamp(std::cos(err), 0.2, 1.0);
        if (rhoMin < prm.rho0) vCmd *= std::clamp(rhoMin / prm.rho0, 0.5, 1.0);
        const double phi = veh.maxSteerDeg * M_PI / 180.0;
        const double tanSteer = std::abs(std::tan(std::clamp(steerCmd, -phi, phi)));
        if (tanSteer > 1e-6 && aLat > 0) vCmd = std::min(vCmd, std::sqrt(aLat * veh.wheelbase / tanSteer));
        vCmd = std::min(vCmd, std::max(std::sqrt(2.0 * veh.deceleration * toGoal), floorV));
        // never faster than lets the vehicle stop before what is straight ahead in its lane,
        // v <= sqrt(2 d (free - margin)): for moving obstacles down to a standstill (yield);
        // for the map and virtual obstacles down to a crawl, since the vehicle may be turning
        // away (the rollout below keeps the body free)
        double freeMoving;
        const double freeStatic = freeAhead(st, t, freeMoving);
        const double margin = 0.1 + st.v * prm.dt;
        const double crawl = std::min(0.2 * veh.maxSpeed, 0.5);
        vCmd = std::min(vCmd, std::max(std::sqrt(2.0 * veh.deceleration * std::max(freeStatic - margin, 0.0)), crawl));
        vCmd = std::min(vCmd, std::sqrt(2.0 * veh.deceleration * std::max(freeMoving - margin, 0.0)));

        // safety filter: a car's body swings when it steers (the rear overhang moves the other
        // way), so the commands are rolled out for a short horizon and softened until the
        // rollout stays free; if nothing does, the vehicle stops (and may end as stuck)
        double steerUse = steerCmd, vUse = 0.0;
        {
            const double candidates[][2] = {{1.0, 1.0}, {0.5, 1.0}, {0.0, 1.0}, {1.0, 0.5}, {0.5, 0.5}, {0.0, 0.5}, {-0.5, 0.5}};
            const int horizon = std::max(2, int(std::ceil(0.6 / prm.dt)));
            for (const auto &cand : candidates)
            {
                VehicleState r = st;
                bool ok = true;
                for (int k = 1; k <= horizon && ok; ++k)
                {
                    r = stepBicycle(r, veh, cand[0] * steerCmd, cand[1] * vCmd, prm.dt);
                    if (k % (horizon / 2) != 0) continue;
                    ok = checker.isValid(r.x, r.y, r.yaw);
                    for (const MovingObstacle &m : scenario.obstacles)
                    {
                        if (!ok) break;
                        double mx, my;
                        m.positionAt(t + k * prm.dt, mx, my);
                        ok = m.distanceFrom(r.x + veh.centreOffset() * std::cos(r.yaw), r.y + veh.centreOffset() * std::sin(r.yaw),
                                            t + k * prm.dt) > veh.circumscribedRadius();
                    }
                }
                if (ok)
                {
                    steerUse = cand[0] * steerCmd;
                    vUse = cand[1] * vCmd;
                    break;
                }
            }
        }
        const VehicleState next = stepBicycle(st, veh, steerUse, vUse, prm.dt);
        res.distanceDriven += std::hypot(next.x - st.x, next.y - st.y);
        st = next;
        t += prm.dt;
        record();
        // collision: static map (FCL footprint checker), then the moving obstacles (FCL)
        if (!checker.isValid(st.x, st.y, st.yaw))
        {
            res.outcome = DriveResult::Outcome::Collided;
            res.reason = "hit the map at (" + std::to_string(st.x) + ", " + std::to_string(st.y) + ")";
            break;
        }
        double clearance = checker.clearance(st.x, st.y, st.yaw);
        if (!scenario.obstacles.empty())
        {
            auto body = vehicleObject(veh, st.x, st.y, st.yaw);
            bool hit = false;
            for (const MovingObstacle &m : scenario.obstacles)
            {
                auto obj = fclObject(m, t);
                fcl::CollisionRequestd creq;
                fcl::CollisionResultd cres;
                if (fcl::collide(body.get(), obj.get(), creq, cres) > 0)
                {
                    res.outcome = DriveResult::Outcome::Collided;
                    res.reason = "hit moving obstacle '" + m.name + "' at t = " + std::to_string(t) + " s";
                    hit = true;
                    break;
                }
                fcl::DistanceRequestd dreq;
                fcl::DistanceResultd dres;
                fcl::distance(body.get(), obj.get(), dreq, dres);
                clearance = std::min(clearance, dres.min_distance);
            }
            if (hit) break;
        }
        res.minClearance = std::min(res.minClearance, clearance);
    }
    res.drivingTime = t;
    res.crossTrackMean = steps ? ctSum / double(steps) : 0.0;
    if (!std::isfinite(res.minClearance)) res.minClearance = checker.clearance(st.x, st.y, st.yaw);
    return res;
}

}  // namespace gridcar
