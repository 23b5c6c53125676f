#pragma once
/// @file Navigate.h
/// @brief The navigation loop: plan on the working map, drive with paper C's follower while a
/// range sensor watches the true world, and replan from where the vehicle stands when the path
/// ahead becomes blocked or the follower stalls.

#include "gridcar/query/PlanQuery.h"
#include "gridcar/sim/Sensing.h"
#include "gridcar/sim/Simulation.h"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gridcar
{
/// Settings of Navigator (plain values with defaults).
struct NavigationOptions
{
    PlannerConfig planner{"corner-astar", {}, false, false};  ///< the planner and its settings
    SetupOptions setup;             ///< the space it plans on
    double planTimeLimit{5.0};      ///< s per plan
    /// How near the goal counts as arrived (default exact: the path ends at the goal, the
    /// follower within max(0.3 m, a cell) of it). Otherwise the tolerance is shared: the
    /// follower stops within f = min(tolerance.position, max(0.3 m, a cell)) of the path's end
    /// and within tolerance.yaw / 2 of its heading, each plan ends within tolerance.position - f
    /// and tolerance.yaw / 2 of the goal; a run that stops outside the tolerance (or further
    /// than f) plans again from there.
    GoalTolerance goalTolerance;
    RangeSensorParams sensor;
    /// Its startTime, startState, interrupt and interruptRolling are the navigator's
    FollowerParams follower;
    int maxReplans{30};             ///< replans before the run ends as Stuck
    int maxStalls{3};               ///< drives ending stuck or past their time limit (each followed by a replan) before it ends as Stuck (Timeout); retreats as many
    /// Replan while rolling: when the path ahead becomes blocked, plan at once from where the
    /// vehicle is while it rolls on along the old path for the plan's latency (up to a metre
    /// short of where that is blocked, or braking at once with less room), then drive on
    /// into the new path from where it has got to, without stopping, when that path starts in its
    /// gear, longer than its stopping distance and a half metre, with no bend that asks it to
    /// brake below 70 % of its speed at once or its wheels to turn faster than they can; otherwise (or with no plan) brake to a standstill
    /// along the old path and plan again from there. false: always brake to a standstill first.
    bool replanRolling{true};
    /// Simulated time (s) a replan takes: the vehicle waits that long at a standstill, or rolls
    /// on along its old path. < 0: each plan's own wall time (update + search). The first plan
    /// is made before the clock starts.
    double planLatency{-1.0};
};

/// How a navigation ended and what it measured.
struct NavigationResult
{
    enum class Outcome { Reached, GoalBlocked, NoPath, Collided, Stuck, Timeout } outcome{Outcome::NoPath};
    std::string reason;                      ///< one line
    double drivingTime{0.0};                 ///< s of simulated time, stops and waits for replanning included
    double distanceDriven{0.0};              ///< m
    double minClearance{std::numeric_limits<double>::infinity()};  ///< m, of the body in the true world
    /// Plans after the first (a plan made while rolling that the vehicle could not drive on into
    /// counts, and so does the one made once it has braked)
    int replans{0};
    int stalls{0};                           ///< drives that ended stuck or past their time limit, each planned again
    /// Times no plan started from where the vehicle stood and it backed up along its track
    /// (two vehicle lengths and a metre, as far as the working map is free) to plan again
    int retreats{0};
    /// Replans made while rolling that the vehicle drove on into without stopping
    int rollingReplans{0};
    std::vector<double> replanSeconds;       ///< wall time of each replan: the map updates since the last plan + solve()
    std::vector<double> updateSeconds;       ///< wall time of each working-map update (distance field + checker)
    std::vector<std::vector<Pose2>> plans;   ///< every path planned, in order
    std::vector<TrajectorySample> trajectory;
    Pose2 finalPose;                         ///< where the vehicle stopped
    /// With GoalBlocked: the pose nearest the goal the planner reached (its approximate answer)
    Pose2 nearestReachable;
    bool hasNearestReachable{false};
    std::size_t sensedCells{0};              ///< cells of the working map marked by the sensor at the end
    static std::string outcomeName(Outcome o);
};

/**
 * @brief Plans on a working map and drives in the true world, replanning as it learns.
 *
 * The working map starts as the map given; the true world is that map (or another one of the
 * same size: what the map did not show) plus a Scenario's obstacles, standing or moving. Every
 * RangeSensorParams::period the sensor scans the true world (WorkingMap::scan()); changed cells
 * update the working map's distance field and footprint checker in place
 * (DistanceField::update(), FootprintChecker::cellsChanged()), so the planner kept between plans
 * pays a search, not a set-up. When the path ahead of the vehicle (from its projection on, every
 * pose at its own heading) collides in the working map, the planner plans again from the pose
 * the vehicle rolls through while it rolls on along the old path for the plan's latency
 * (NavigationOptions::replanRolling, planLatency), and the vehicle drives on into the new path
 * from where it got to at its speed when that path lets it (canDriveOn); otherwise it brakes to
 * a standstill along the old path and plans again from there. Every drive starts from the
 * vehicle's own state (pose, speed, steering). A drive that ends stuck (the follower's
 * recoveries spent) is replanned too. Obstacles moving faster than RangeSensorParams::stationarySpeed are left
 * to the follower's potential field (paper C: robustness to dynamic obstacles), as a driver
 * waits for a pedestrian to cross. A plan that fails where the goal's pose collides in the
 * working map, or where the sensor added cells within 1.5 m of the body's reach round the goal
 * (an obstacle over the goal, seen from its sides), ends the run as GoalBlocked with the pose
 * nearest the goal the planner reached. Any other failed replan first backs the vehicle up along
 * the track it drove (as far as the working map is free, two vehicle lengths and a metre: its
 * nose may stand in a corner of what the map did not show) and plans again, up to maxStalls
 * times; then the run ends as NoPath. (Backing up after a stuck drive too was measured on
 * bench_navigate and gained nothing: it is not done.)
 */
class Navigator
{
public:
    /// @p map: the map the vehicle is given; @p world: the true map (null: the same map).
    Navigator(std::shared_ptr<const OccupancyGrid> map, const VehicleParams &vehicle,
              const NavigationOptions &options = NavigationOptions(), std::shared_ptr<const OccupancyGrid> world = nullptr);
    ~Navigator();
    Navigator(const Navigator &) = delete;
    Navigator &operator=(const Navigator &) = delete;

    /// Navigates start -> goal (a pose, or with @p freeGoalHeading a position) among @p scenario's
    /// obstacles. The working map keeps what was seen between runs.
    NavigationResult run(const Pose2 &start, const Pose2 &goal, bool freeGoalHeading, const Scenario &scenario);

    const OccupancyGrid &workingMap() const;
    /// The true world's checker (the vehicle against the true map; not the scenario).
    const FootprintChecker &worldChecker() const;
    /// The set-up the planner plans on (the working map).
    GridSetup &setup();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gridcar
