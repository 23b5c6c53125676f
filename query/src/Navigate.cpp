// The navigation loop: plan, drive, sense, update the working map in place, replan.
#include "gridcar/query/Navigate.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/vehicle/Dynamics.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
std::string NavigationResult::outcomeName(Outcome o)
{
    switch (o)
    {
        case Outcome::Reached: return "reached";
        case Outcome::GoalBlocked: return "goal blocked";
        case Outcome::NoPath: return "no path";
        case Outcome::Collided: return "collided";
        case Outcome::Stuck: return "stuck";
        default: return "timeout";
    }
}

struct Navigator::Impl
{
    std::shared_ptr<const OccupancyGrid> world;
    std::shared_ptr<const DistanceField> worldField;
    std::unique_ptr<FootprintChecker> worldChecker;
    WorkingMap working;
    std::shared_ptr<DistanceField> field;  ///< of the working map, updated in place
    GridSetup setup;
    ompl::base::PlannerPtr planner;
    NavigationOptions options;
    VehicleState car;  ///< the vehicle's state in the true world (its body's pose, speed, steering)

    Impl(const std::shared_ptr<const OccupancyGrid> &map, const VehicleParams &vehicle, const NavigationOptions &o,
         std::shared_ptr<const OccupancyGrid> truth)
      : world(truth ? std::move(truth) : map), working(std::make_shared<OccupancyGrid>(*map)), options(o)
    {
        if (!world->sameFrame(*map))
            throw std::invalid_argument("Navigator: the true map must have the map's size, resolution and origin");
        field = std::make_shared<DistanceField>(working.grid());
        field->prepareUpdates(working.grid());
        worldField = world == map ? nullptr : std::make_shared<const DistanceField>(*world);
        setup = makeGridSetup(working.gridPtr(), vehicle, o.setup, field);
        worldChecker = std::make_unique<FootprintChecker>(world, worldField ? worldField : std::make_shared<const DistanceField>(*world), vehicle);
        planner = configurePlanner(setup.ss->getSpaceInformation(), o.planner);
    }

    /// One scan; the working map's field and checker brought up to date. True when cells changed.
    bool sense(const Scenario &sc, double t, double x, double y, NavigationResult &res)
    {
        const CellWindow w = working.scan(*world, sc, t, x, y, options.sensor);
        if (w.empty()) return false;
        const auto t0 = std::chrono::steady_clock::now();
        setup.checker->cellsChanged(w, field->update(working.grid(), w));
        res.updateSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        return true;
    }

    /// Backs the vehicle up along the track driven (retreatPath()); false when there is no room.
    bool retreat(const Scenario &sc, NavigationResult &res, double &t, Pose2 &at);

    /// Brakes the vehicle rolling in state @p s to a standstill along @p path from pose @p from
    /// on (or straight on where the path has no more in its gear).
    DriveResult brake(const std::vector<Pose2> &path, std::size_t from, const VehicleState &s, const Scenario &sc,
                      NavigationResult &res, double &t, Pose2 &at);

    /// Drives @p path in the true world from time @p t on; the trajectory, time, distance and
    /// clearance added to @p res, @p t and @p at moved to where the car stopped.
    DriveResult drive(const std::vector<Pose2> &path, const FollowerParams &fpIn, const Scenario &sc, NavigationResult &res,
                      double &t, Pose2 &at)
    {
        // the car goes on as it stands or rolls: its heading and steering, not the path's
        FollowerParams fp = fpIn;
        if (!fp.startState) fp.startState = car;
        const DriveResult d = drivePath(path, *worldChecker, sc, fp);
        car = d.finalState;
        res.trajectory.insert(res.trajectory.end(), d.trajectory.begin(), d.trajectory.end());
        t += d.drivingTime;
        res.drivingTime = t;
        res.distanceDriven += d.distanceDriven;
        res.minClearance = std::min(res.minClearance, d.minClearance);
        at = {d.finalState.x, d.finalState.y, d.finalState.yaw};
        res.finalPose = at;
        return d;
    }
};

namespace
{
/// A plan that fails with cells the sensor added within this distance (m) of the body's reach
/// round the goal ends the run as GoalBlocked: what the map did not show stands at the goal.
constexpr double kGoalNear = 1.5;
/// A retreat backs up this many vehicle lengths plus a metre along the track driven.
constexpr double kRetreat = 2.0;

/// Index of the path pose nearest (x, y), searched from @p from on over the next 10 m.
std::size_t nearestAhead(const std::vector<Pose2> &path, std::size_t from, double x, double y)
{
    std::size_t best = from;
    double bestD = std::hypot(path[from].x - x, path[from].y - y), along = 0.0;
    for (std::size_t i = from + 1; i < path.size() && along <= 10.0; ++i)
    {
        along += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
        const double d = std::hypot(path[i].x - x, path[i].y - y);
        if (d < bestD) best = i, bestD = d;
    }
    return best;
}

/// The way back along the track driven (the trajectory's poses from its end, 5 cm apart at
/// the least), as long as the body is free in the working map at each pose, up to @p length m:
/// a path that retraces the drive in the other gear.
std::vector<Pose2> retreatPath(const std::vector<TrajectorySample> &track, const FootprintChecker &work, double length)
{
    std::vector<Pose2> out;
    double along = 0.0;
    for (std::size_t i = track.size(); i-- > 0 && along < length;)
    {
        const Pose2 p{track[i].x, track[i].y, track[i].yaw};
        if (!work.isValid(p)) break;
        if (!out.empty())
        {
            const double d = std::hypot(p.x - out.back().x, p.y - out.back().y);
            if (d < 0.05) continue;
            along += d;
        }
        out.push_back(p);
    }
    return out;
}

/// A path the vehicle rolling in state @p s can drive on into without stopping: its first piece
/// in the gear it rolls in, longer than its stopping distance and a half metre, with no curve so
/// near that the car must brake below 70 % of its speed to take it (the profile from its speed).
bool canDriveOn(const std::vector<Pose2> &path, const VehicleState &s, const VehicleParams &vehicle)
{
    const std::vector<PathPiece> pieces = splitAtCusps(path);
    if (pieces.empty() || pieces.front().backward != (s.v < 0)) return false;
    const double speed = std::abs(s.v);
    const std::vector<Pose2> &first = pieces.front().poses;
    double length = 0.0;
    for (std::size_t i = 1; i < first.size(); ++i) length += std::hypot(first[i].x - first[i - 1].x, first[i].y - first[i - 1].y);
    if (length < speed * speed / (2.0 * vehicle.deceleration) + 0.5) return false;
    VehicleParams v = vehicle;
    if (pieces.front().backward) v.maxSpeed = reverseSpeedLimit(vehicle);
    DrivingTimeParams dp;
    dp.startSpeed = speed;
    const VelocityProfile profile = velocityProfile(first, v, dp);
    return !profile.v.empty() && profile.v.front() >= 0.7 * speed;
}

/// Within the tolerance of the goal: the position within the larger of the tolerance and the
/// follower's (the path ends within the one, the car within the other of the path's end), the
/// heading within its tolerance.
bool arrived(const Pose2 &at, const Pose2 &goal, bool freeHeading, const GoalTolerance &tol, double followerTol)
{
    if (std::hypot(at.x - goal.x, at.y - goal.y) > std::max(tol.position, followerTol) + 1e-9) return false;
    return freeHeading || std::abs(wrapAngle(at.yaw - goal.yaw)) <= tol.yaw + 1e-9;
}
}  // namespace

bool Navigator::Impl::retreat(const Scenario &sc, NavigationResult &res, double &t, Pose2 &at)
{
    const FootprintChecker &work = *setup.checker;
    const std::vector<Pose2> back = retreatPath(res.trajectory, work, kRetreat * work.vehicle().length + 1.0);
    if (back.size() < 2) return false;
    ++res.retreats;
    FollowerParams fp = options.follower;
    fp.startTime = t;
    drive(back, fp, sc, res, t, at);
    sense(sc, t, at.x, at.y, res);
    return true;
}

DriveResult Navigator::Impl::brake(const std::vector<Pose2> &path, std::size_t from, const VehicleState &s, const Scenario &sc,
                                   NavigationResult &res, double &t, Pose2 &at)
{
    const bool backward = s.v < 0;
    std::vector<Pose2> along;
    if (from < path.size())
    {
        const std::vector<PathPiece> pieces = splitAtCusps(std::vector<Pose2>(path.begin() + std::ptrdiff_t(from), path.end()));
        if (!pieces.empty() && pieces.front().backward == backward) along = pieces.front().poses;
    }
    // the stopping distance and a metre: a piece that ends sooner is carried on straight
    const double need = s.v * s.v / (2.0 * setup.checker->vehicle().deceleration) + 1.0;
    double length = 0.0;
    for (std::size_t i = 1; i < along.size(); ++i) length += std::hypot(along[i].x - along[i - 1].x, along[i].y - along[i - 1].y);
    if (along.empty()) along.push_back({s.x, s.y, s.yaw});
    if (length < need)
    {
        const Pose2 e = along.back();
        const double sign = backward ? -1.0 : 1.0, go = need - length;
        along.push_back({e.x + sign * go * std::cos(e.yaw), e.y + sign * go * std::sin(e.yaw), e.yaw});
    }
    FollowerParams fp = options.follower;
    fp.startTime = t;
    fp.startState = s;
    fp.interrupt = [](const VehicleState &, double) { return true; };
    return drive(along, fp, sc, res, t, at);
}

Navigator::Navigator(std::shared_ptr<const OccupancyGrid> map, const VehicleParams &vehicle, const NavigationOptions &options,
                     std::shared_ptr<const OccupancyGrid> world)
{
    if (!map) throw std::invalid_argument("Navigator needs a map");
    impl_ = std::make_unique<Impl>(map, vehicle, options, std::move(world));
}

Navigator::~Navigator() = default;
const OccupancyGrid &Navigator::workingMap() const { return impl_->working.grid(); }
const FootprintChecker &Navigator::worldChecker() const { return *impl_->worldChecker; }
GridSetup &Navigator::setup() { return impl_->setup; }

NavigationResult Navigator::run(const Pose2 &start, const Pose2 &goal, bool freeGoalHeading, const Scenario &scenario)
{
    Impl &m = *impl_;
    NavigationResult res;
    const FootprintChecker &work = *m.setup.checker;
    Pose2 at = start;
    double t = 0.0, pendingUpdate = 0.0;
    res.finalPose = start;
    m.car = VehicleState{start.x, start.y, start.yaw, 0.0, 0.0};
    std::size_t updatesSeen = 0, ahead = 0;
    m.sense(scenario, t, at.x, at.y, res);
    auto finish = [&](NavigationResult::Outcome o, std::string why) {
        res.outcome = o;
        res.reason = std::move(why);
        res.sensedCells = m.working.sensedCells();
        return res;
    };
    for (;;)
    {
        for (; updatesSeen < res.updateSeconds.size(); ++updatesSeen) pendingUpdate += res.updateSeconds[updatesSeen];
        if (!work.isValid(at))
            return finish(NavigationResult::Outcome::Stuck, "the vehicle's pose " + std::to_string(at.x) + ", " +
                                                                std::to_string(at.y) + " collides in the working map: no plan from it");
        // the tolerance shared between the plan and the follower, so that a plan to its edge
        // followed within the follower's part stops inside it: the follower stops within
        // followTol of the path's end (its own tolerance, or the goal's where that is smaller)
        // and half the heading tolerance; the plan ends within the rest
        const GoalTolerance &tol = m.options.goalTolerance;
        const double ownTol = m.options.follower.goalTolerance > 0 ? m.options.follower.goalTolerance : std::max(0.3, m.field->resolution());
        const double followTol = tol.position > 0 ? std::min(tol.position, ownTol) : ownTol;
        const GoalTolerance planTol{tol.position > 0 ? tol.position - followTol : 0.0, tol.yaw / 2};
        const QueryResult q = runQuery(m.setup, m.planner, at, goal, m.options.planTimeLimit, freeGoalHeading, planTol);
        if (!res.plans.empty()) res.replanSeconds.push_back(pendingUpdate + q.seconds);
        pendingUpdate = 0.0;
        if (std::abs(m.car.v) > 1e-9)  // planned while rolling
        {
            const bool driveOn = q.status == ompl::base::PlannerStatus::EXACT_SOLUTION && canDriveOn(q.path, m.car, work.vehicle());
            if (!driveOn)  // a stop first (a gear change, a bend too near, no plan from here): then plan again
            {
                const DriveResult b = m.brake(res.plans.back(), ahead, m.car, scenario, res, t, at);
                if (b.outcome == DriveResult::Outcome::Collided) return finish(NavigationResult::Outcome::Collided, b.reason);
                m.sense(scenario, t, at.x, at.y, res);
                ++res.replans;
                continue;
            }
            ++res.rollingReplans;
        }
        if (q.status != ompl::base::PlannerStatus::EXACT_SOLUTION)
        {
            // the goal in or beside what the map did not show: seen from its sides, an obstacle
            // over the goal leaves the goal's pose free in the working map but no way to it
            const bool goalFree = freeGoalHeading ? work.fitsAtSomeHeading(goal.x, goal.y, 72) : work.isValid(goal);
            if (!goalFree || m.working.sensedWithin(goal.x, goal.y, work.reach() + kGoalNear))
            {
                if (!q.path.empty()) res.nearestReachable = q.path.back(), res.hasNearestReachable = true;
                return finish(NavigationResult::Outcome::GoalBlocked,
                              "the goal is blocked by an obstacle the map did not show" +
                                  std::string(res.hasNearestReachable ? "; the nearest pose reached is reported" : ""));
            }
            // no plan from where the car stands (its nose in a corner the map did not show):
            // back up along the track driven and plan again from roomier ground
            if (!res.plans.empty() && res.retreats < m.options.maxStalls && m.retreat(scenario, res, t, at)) continue;
            return finish(NavigationResult::Outcome::NoPath, "the planner found no path from (" + std::to_string(at.x) + ", " +
                                                                 std::to_string(at.y) + "): " + q.status.asString() +
                                                                 (q.notExactBecause.empty() ? "" : " (" + q.notExactBecause + ")"));
        }
        if (res.replans > m.options.maxReplans)
            return finish(NavigationResult::Outcome::Stuck, "replanned " + std::to_string(res.replans) + " times");
        res.plans.push_back(q.path);
        const std::vector<Pose2> &path = res.plans.back();
        ahead = 0;
        double lastScan = t;
        FollowerParams fp = m.options.follower;
        fp.startTime = t;
        fp.interruptRolling = m.options.replanRolling;
        fp.goalTolerance = followTol;
        if (tol.yaw > 0 && !freeGoalHeading) fp.goalYawTolerance = tol.yaw / 2;
        fp.interrupt = [&](const VehicleState &s, double now) {
            if (now - lastScan < m.options.sensor.period - 1e-9) return false;
            lastScan = now;
            ahead = nearestAhead(path, ahead, s.x, s.y);
            if (!m.sense(scenario, now, s.x, s.y, res)) return false;
            for (std::size_t i = ahead; i < path.size(); ++i)
                if (!work.isValid(path[i])) return true;
            return false;
        };
        const DriveResult d = m.drive(path, fp, scenario, res, t, at);
        switch (d.outcome)
        {
            case DriveResult::Outcome::Reached:
                if (tol.exact() || arrived(at, goal, freeGoalHeading, tol, followTol))
                    return finish(NavigationResult::Outcome::Reached, d.reason);
                break;  // stopped short of the tolerance: plan again from here
            case DriveResult::Outcome::Collided: return finish(NavigationResult::Outcome::Collided, d.reason);
            case DriveResult::Outcome::Timeout: return finish(NavigationResult::Outcome::Timeout, d.reason);
            case DriveResult::Outcome::Stuck:
                if (++res.stalls > m.options.maxStalls)
                    return finish(NavigationResult::Outcome::Stuck, d.reason + " (" + std::to_string(res.stalls) + " stalls)");
                m.sense(scenario, t, at.x, at.y, res);
                break;
            default: break;  // interrupted: the path ahead is blocked in the working map (rolling or at a standstill)
        }
        ++res.replans;
    }
}

}  // namespace gridcar
