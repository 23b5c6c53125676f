#pragma once
/// @file Simulation.h
/// @brief Kinematic bicycle simulation with scripted moving obstacles, and paper C's
/// potential-field path follower.

#include "gridcar/collision/FootprintChecker.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gridcar
{
/// A scripted moving obstacle: a disc or an axis-aligned box moving through waypoints at
/// constant speed (or standing still with one waypoint). Before its start time it waits at the
/// first waypoint; after the last waypoint it stays there (or loops back when `loop`).
struct MovingObstacle
{
    std::string name{"obstacle"};
    enum class Shape { Disc, Box } shape{Shape::Disc};
    double radius{0.3};                 ///< disc radius, m
    double sizeX{1.0}, sizeY{1.0};      ///< box extents, m
    std::vector<std::pair<double, double>> waypoints;  ///< world x, y
    double speed{1.0};                  ///< m/s along the waypoints
    double startTime{0.0};              ///< s
    bool loop{false};
    /// Centre at time t.
    void positionAt(double t, double &x, double &y) const;
    /// Distance from (x, y) to the obstacle's boundary (negative inside), m.
    double distanceFrom(double x, double y, double t) const;
    /// Component @p axis (0: x, 1: y) of its velocity as a sensor would measure it at time t:
    /// the displacement over the last @p dt seconds (0 before it starts moving), m/s.
    double velocityEstimate(double t, double dt, int axis) const;
};

/// Moving obstacles of a run, from a scenario file.
struct Scenario
{
    std::vector<MovingObstacle> obstacles;
    /**
     * @brief Reads a YAML scenario:
     * `obstacles: [{name, shape: disc|box, radius | size: [sx, sy], waypoints: [[x, y], ...],
     * speed, start_time, loop}]`. Throws MapLoadError ("<file>: <reason>") on bad input.
     */
    static Scenario load(const std::string &file);
};

/// State of the kinematic bicycle (reference point: rear-axle centre, like Pose2).
struct VehicleState
{
    double x{0}, y{0}, yaw{0};
    double v{0};      ///< m/s (negative driving backwards)
    double steer{0};  ///< front-wheel angle, rad
};

/**
 * @brief One step of the kinematic bicycle: steering moves towards @p steerCmd at most
 * max_steer_rate x dt and stays within +-phi_max; speed towards @p speedCmd within the
 * acceleration / deceleration limits and [0, v_max]; then x += v cos(yaw) dt,
 * y += v sin(yaw) dt, yaw += v tan(steer) / wheelbase dt (explicit Euler, deterministic).
 */
VehicleState stepBicycle(const VehicleState &s, const VehicleParams &v, double steerCmd, double speedCmd, double dt);

/// Gains and limits of the potential-field follower (paper C, section 3; Khatib 1986).
struct FollowerParams
{
    double dt{0.05};            ///< s, simulation step
    double xi{1.0};             ///< attractive gain (force per metre towards the via-point)
    double eta{0.6};            ///< repulsive gain
    double rho0{1.5};           ///< m, influence distance of obstacles (beyond the body's half width)
    double lookaheadMin{2.0};   ///< m, via-point distance along the path at standstill
    double lookaheadTime{1.0};  ///< s, plus this many seconds of travel
    double headingGain{2.0};    ///< steering command = gain x heading error (rad / rad)
    /// On a path within K_max: steering also gets -atan(gain x cross-track error / (|v| + 0.5 m/s))
    /// (1/s; Stanley's term), so a lateral offset is steered back at any look-ahead. 0: off
    double crossTrackGain{1.0};
    double goalTolerance{0.0};  ///< m; 0 = max(0.3 m, a cell)
    /// rad: a run that stops at the goal with its heading further than this from the path's
    /// last pose ends Stuck, not Reached; 0: the heading is not checked
    double goalYawTolerance{0.0};
    double stuckWindow{6.0};    ///< s without progress along the path before a recovery
    int maxRecoveries{3};       ///< recoveries before the run is declared stuck
    double timeLimit{0.0};      ///< s; 0 = 50 s + per piece 10 s + max(5 x length / v_max, 3 x planned driving time)
    bool recordTrajectory{true};
    /// Simulated time at the first step, s (the scenario's clock: a run that goes on from an
    /// earlier one starts where it stopped). Trajectory times count from it; drivingTime does not.
    double startTime{0.0};
    /// Asked before every step with the vehicle's state (its body's pose; v negative while
    /// reversing) and the time: true stops the run, the car braking to a standstill on its
    /// course, and it ends as Interrupted (a navigation loop's "the path ahead is blocked").
    std::function<bool(const VehicleState &, double)> interrupt;
    /// With true, an interrupt ends the run at once, the vehicle still rolling (finalState keeps
    /// its speed and steering): the caller goes on from that state on a new path (startState)
    /// or brakes it to a standstill. false: it brakes to a standstill first.
    bool interruptRolling{false};
    /// The vehicle's state at the start when it goes on from an earlier run, rolling (its body's
    /// pose, speed, negative in reverse, and steering): the path's first piece must be in that
    /// gear (std::invalid_argument otherwise) and its profile starts from that speed. Unset: at
    /// rest on the path's first pose, heading along it.
    std::optional<VehicleState> startState;
};

/// One simulated step, for the trajectory CSV and pictures.
struct TrajectorySample
{
    double t, x, y, yaw, v, steer;
};

/// How a run ended and what it measured.
struct DriveResult
{
    enum class Outcome { Reached, Collided, Stuck, Timeout, Interrupted } outcome{Outcome::Timeout};
    std::string reason;             ///< one line: what was hit, where it stopped, ...
    double drivingTime{0.0};        ///< s of simulated time until the end
    double pathLength{0.0};         ///< m, of the followed path
    double distanceDriven{0.0};     ///< m
    double crossTrackMean{0.0};     ///< m, distance of the reference point to the path
    double crossTrackMax{0.0};
    double minClearance{0.0};       ///< m, footprint clearance (static map and moving obstacles)
    int recoveries{0};
    /// Where the vehicle stands (or rolls) at the end: its body's pose, v negative in reverse
    VehicleState finalState;
    std::vector<TrajectorySample> trajectory;
    static std::string outcomeName(Outcome o);
};

/**
 * @brief Drives @p path with paper C's potential-field follower in the kinematic simulation.
 *
 * Each step: the via-point is the point a look-ahead distance (lookaheadMin + lookaheadTime x v)
 * ahead of the vehicle's projection on the path (the nearest point from the last projection on,
 * not beyond the point where the path has turned by 270 degrees: a circle in the path is driven
 * round, not cut across), except that the path's next corner (a turning
 * point turning by more than 10 degrees) is the via-point until the vehicle is within half the
 * look-ahead of it (paper C: corners as successive sub-goals). Attractive force
 * F_att = xi (q_via - q), saturated at xi x look-ahead; repulsive force from the static map
 * F_rep = eta (1/rho - 1/rho0) / rho^2 grad rho for rho <= rho0, rho = d_O - half width at the
 * body's centre and front (DistanceField distance and gradient), and the same from every moving
 * obstacle (rho = distance to its boundary - half width). The force's direction is the desired
 * heading (steering = headingGain x error, limited); the desired speed is the path's velocity
 * profile at the projection (velocityProfile(): braking before corners and curvature, v_max,
 * lateral acceleration), scaled down by cos(heading error) and near obstacles
 * (rho / rho0), and never asking the car to turn tighter than a_lat allows.
 *
 * Every step is checked with the FCL footprint checker against the map and the moving
 * obstacles: a collision ends the run (Collided, with what was hit). Local minima and
 * oscillation: when progress along the path stalls for stuckWindow seconds, a virtual
 * obstacle is placed where the vehicle is and the via-point jumps ahead by a look-ahead; after
 * maxRecoveries recoveries without progress the run ends as Stuck. The time limit ends it as
 * Timeout. Deterministic for the same input.
 */
DriveResult drivePath(const std::vector<Pose2> &path, const FootprintChecker &checker, const Scenario &scenario,
                      const FollowerParams &params = FollowerParams());

}  // namespace gridcar
