// The navigation loop: plan, drive, sense, update the working map in place, replan.
#include "gridcar/query/Navigate.h"

#include "NavigatePaths.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Cusps.h"
#include "gridcar/path/PathMetrics.h"

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

namespace
{
/// m/s: a car slower than this at the end of a drive stands (a step's least advance, 1 mm, at the end)
constexpr double kStanding = 0.02;
}  // namespace

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
    std::size_t blockedAt{0};  ///< the first pose of the last plan found blocked in the working map
    std::vector<std::array<double, 2>> outline;  ///< the body's, in its frame (VehicleParams::outline())
    std::vector<std::array<double, 2>> body;     ///< the body's at the last scan, in the world

    Impl(const std::shared_ptr<const OccupancyGrid> &map, const VehicleParams &vehicle, const NavigationOptions &o,
         std::shared_ptr<const OccupancyGrid> truth)
      : world(truth ? std::move(truth) : map), working(std::make_shared<OccupancyGrid>(*map)), options(o),
        outline(vehicle.outline())
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

    /// One scan from the vehicle at (x, y, yaw), the cells its body overlaps kept clear
    /// (WorkingMap::scan()); the working map's field and checker brought up to date. True when
    /// cells changed.
    bool sense(const Scenario &sc, double t, double x, double y, double yaw, NavigationResult &res)
    {
        const double c = std::cos(yaw), s = std::sin(yaw);
        body.clear();
        for (const auto &p : outline) body.push_back({x + c * p[0] - s * p[1], y + s * p[0] + c * p[1]});
        const CellWindow w = working.scan(*world, sc, t, x, y, options.sensor, body.size() >= 3 ? &body : nullptr);
        if (w.empty()) return false;
        const auto t0 = std::chrono::steady_clock::now();
        setup.checker->cellsChanged(w, field->update(working.grid(), w));
        res.updateSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        return true;
    }

    /// Backs the vehicle up along the track driven (retreatPath()); false when there is no room.
    bool retreat(const Scenario &sc, NavigationResult &res, double &t, Pose2 &at);

    enum class Handover { DriveOn, PlanAgain, Collided, CouldNotBrake };
    /// After plan @p q made while rolling (from pose @p ahead of the last plan on): the car rolls
    /// on along the last plan for @p latency s; then DriveOn with @p q's path cut to start where
    /// the car joins it, or it brakes to a standstill there (PlanAgain; Collided or
    /// CouldNotBrake with @p why).
    Handover handOver(QueryResult &q, double latency, std::size_t ahead, const Scenario &sc, NavigationResult &res, double &t,
                      Pose2 &at, std::string &why);

    /// The vehicle, rolling, goes on along @p path from pose @p from on (or straight on where the
    /// path has no more in its gear), scanning: for @p rollFor seconds and then still rolling, or
    /// (rollFor < 0) braking to a standstill at once.
    DriveResult goOn(const std::vector<Pose2> &path, std::size_t from, double rollFor, const Scenario &sc, NavigationResult &res,
                     double &t, Pose2 &at);

    /// Drives @p path in the true world from time @p t on; the trajectory, time, distance and
    /// clearance added to @p res, @p t and @p at moved to where the car stopped.
    DriveResult drive(const std::vector<Pose2> &path, const FollowerParams &fpIn, const Scenario &sc, NavigationResult &res,
                      double &t, Pose2 &at)
    {
        // the car goes on as it stands or rolls: its heading and steering, not the path's
        FollowerParams fp = fpIn;
        fp.startState = car;
        const DriveResult d = drivePath(path, *worldChecker, sc, fp);
        car = d.finalState;
        // a run that ends at the goal creeps its last millimetre (a step's least advance): the car stands
        if (std::abs(car.v) < kStanding) car.v = 0.0;
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
using detail::canDriveOn;
using detail::joinAt;
using detail::nearestAhead;
using detail::retreatPath;

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
    sense(sc, t, at.x, at.y, at.yaw, res);
    return true;
}

DriveResult Navigator::Impl::goOn(const std::vector<Pose2> &path, std::size_t from, double rollFor, const Scenario &sc,
                                  NavigationResult &res, double &t, Pose2 &at)
{
    const VehicleState s = car;
    const bool backward = s.v < 0;
    const double stopping = s.v * s.v / (2.0 * setup.checker->vehicle().deceleration);
    std::vector<Pose2> along;
    // where the car is on the path now (it may have rolled on since @p from was found)
    if (from < path.size()) from = nearestAhead(path, from, s.x, s.y, 60.0);
    // rolling on: along the path up to a metre short of where it is blocked (its profile stops
    // there); with less room than it needs to stop, it brakes at once
    std::size_t to = std::min(path.size(), std::max(blockedAt, from));
    for (double back = 0.0; rollFor >= 0 && to > from + 1 && back < 1.0; --to)
        back += std::hypot(path[to - 1].x - path[to - 2].x, path[to - 1].y - path[to - 2].y);
    if (rollFor < 0) to = path.size();
    if (from + 1 < to)
    {
        const std::vector<PathPiece> pieces =
            splitAtCusps(std::vector<Pose2>(path.begin() + std::ptrdiff_t(from), path.begin() + std::ptrdiff_t(to)));
        if (!pieces.empty() && pieces.front().backward == backward) along = pieces.front().poses;
    }
    const double length = pathLength(along);
    if (rollFor >= 0 && length < stopping + 0.5) return goOn(path, from, -1.0, sc, res, t, at);
    // braking: its stopping distance and a metre; a piece that ends sooner is carried on straight
    const double need = stopping + 1.0;
    if (along.empty()) along.push_back({s.x, s.y, s.yaw});
    if (rollFor < 0 && length < need)
    {
        const Pose2 e = along.back();
        const double sign = backward ? -1.0 : 1.0, go = need - length;
        along.push_back({e.x + sign * go * std::cos(e.yaw), e.y + sign * go * std::sin(e.yaw), e.yaw});
    }
    FollowerParams fp = options.follower;
    fp.startTime = t;
    fp.interruptRolling = rollFor >= 0;
    const double until = t + rollFor;
    double lastScan = t;
    fp.interrupt = [&](const VehicleState &st, double now) {
        if (now - lastScan >= options.sensor.period - 1e-9)
        {
            lastScan = now;
            sense(sc, now, st.x, st.y, st.yaw, res);
        }
        return now >= until - 1e-9;
    };
    return drive(along, fp, sc, res, t, at);
}

Navigator::Impl::Handover Navigator::Impl::handOver(QueryResult &q, double latency, std::size_t ahead, const Scenario &sc,
                                                    NavigationResult &res, double &t, Pose2 &at, std::string &why)
{
    const std::vector<Pose2> &old = res.plans.back();
    const double t0 = t;
    const DriveResult o = goOn(old, ahead, latency, sc, res, t, at);
    if (o.outcome == DriveResult::Outcome::Collided) return why = o.reason, Handover::Collided;
    if (t < t0 + latency) res.drivingTime = t = t0 + latency;  // stopped short: it waits for the plan
    const std::size_t j = options.replanRolling && q.status == ompl::base::PlannerStatus::EXACT_SOLUTION
                              ? joinAt(q.path, car, std::abs(car.v) * latency + 2.0) : std::string::npos;
    if (j != std::string::npos)  // the new path from where the car joins it
    {
        q.path.erase(q.path.begin(), q.path.begin() + std::ptrdiff_t(j));
        q.path.front() = at;
    }
    if (j != std::string::npos && car.v != 0.0 && canDriveOn(q.path, car, setup.checker->vehicle())) return Handover::DriveOn;
    // a stop first (a gear change, a bend too near, no plan from here): then plan again
    if (car.v == 0.0) return Handover::PlanAgain;
    DriveResult b = goOn(old, ahead, -1.0, sc, res, t, at);
    if (b.outcome != DriveResult::Outcome::Collided && car.v != 0.0)  // past the old path's end: straight on
        b = goOn(old, old.size(), -1.0, sc, res, t, at);
    if (b.outcome == DriveResult::Outcome::Collided) return why = b.reason, Handover::Collided;
    if (car.v != 0.0) return why = b.reason, Handover::CouldNotBrake;
    return Handover::PlanAgain;
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
    m.sense(scenario, t, at.x, at.y, at.yaw, res);
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
        QueryResult q = runQuery(m.setup, m.planner, at, goal, m.options.planTimeLimit, freeGoalHeading, planTol);
        const double latency = m.options.planLatency >= 0 ? m.options.planLatency : pendingUpdate + q.seconds;
        if (!res.plans.empty()) res.replanSeconds.push_back(pendingUpdate + q.seconds);
        pendingUpdate = 0.0;
        if (m.car.v != 0.0)  // planned while rolling: the car rolled on along its old path meanwhile
        {
            std::string why;
            const Impl::Handover h = m.handOver(q, latency, ahead, scenario, res, t, at, why);
            if (h == Impl::Handover::Collided) return finish(NavigationResult::Outcome::Collided, why);
            if (h == Impl::Handover::CouldNotBrake) return finish(NavigationResult::Outcome::Stuck, "could not brake: " + why);
            if (h == Impl::Handover::PlanAgain)
            {
                if (++res.replans > m.options.maxReplans)
                    return finish(NavigationResult::Outcome::Stuck, "replanned " + std::to_string(res.replans) + " times");
                continue;
            }
            ++res.rollingReplans;
        }
        else if (!res.plans.empty() && latency > 0)  // the car waits for the plan
        {
            t += latency;
            res.drivingTime = t;
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
        m.blockedAt = path.size();
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
            if (!m.sense(scenario, now, s.x, s.y, s.yaw, res)) return false;
            for (std::size_t i = ahead; i < path.size(); ++i)
                if (!work.isValid(path[i])) return m.blockedAt = i, true;
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
            // a drive past its time limit (backing up and trying again on a short piece until
            // then) is stuck too: planned again from where the car stands, as a stall
            case DriveResult::Outcome::Timeout:
            case DriveResult::Outcome::Stuck:
                if (++res.stalls > m.options.maxStalls)
                    return finish(d.outcome == DriveResult::Outcome::Timeout ? NavigationResult::Outcome::Timeout
                                                                              : NavigationResult::Outcome::Stuck,
                                  d.reason + " (" + std::to_string(res.stalls) + " stalls)");
                m.sense(scenario, t, at.x, at.y, at.yaw, res);
                break;
            default: break;  // interrupted: the path ahead is blocked in the working map (rolling or at a standstill)
        }
        ++res.replans;
    }
}

}  // namespace gridcar
