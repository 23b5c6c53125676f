#pragma once
/// @file Dynamics.h
/// @brief What follows from a vehicle's dynamics limits, in one place: the lateral
/// acceleration limit, speed limits through heading changes, corner speeds and the distance /
/// time a corner costs (from which corner A*'s physics weights come: planners/CornerWeights.h; the
/// driving-time objective), and the
/// velocity profile and driving time of a path (the benchmark, the simulation).

#include "gridcar/core/Pose2.h"
#include "gridcar/vehicle/VehicleParams.h"

#include <vector>

namespace gridcar
{
/// The lateral acceleration the vehicle may use in a turn: min(mu g, max_lateral_accel), m/s^2.
double lateralAccelLimit(const VehicleParams &v);

/// Speeds (m/s) at which a vehicle takes 45-, 90- and 135-degree grid corners.
struct CornerSpeeds
{
    double v45{0.0}, v90{0.0}, v135{0.0};
};

/// The corner speeds v_c of 45-, 90- and 135-degree grid corners (m/s): the vehicle's
/// `corner_speed_*` if set, else sqrt(lateralAccelLimit() r) with r = R_min / tan(theta / 2);
/// never above v_max.
CornerSpeeds cornerSpeeds(const VehicleParams &v);

/// Distance (m) lost driving through a corner taken at @p cornerSpeed instead of v_max: v_max
/// x the time lost braking to it and accelerating again, (v_max - v_c)^2 / 2 x (1/a + 1/d).
double cornerDistanceLost(const VehicleParams &v, double cornerSpeed);

/// The manoeuvring speed (m/s): the speed limit on an arc of R_min,
/// min(v_max, sqrt(lateralAccelLimit() R_min)), where a car reverses and changes gear.
double manoeuvringSpeed(const VehicleParams &v);

/// Speed limit driving backwards (m/s): VehicleParams::maxReverseSpeed when set (at most v_max),
/// else v_max / 3 and at most 2 m/s (a car backs out or into a slot at walking pace).
double reverseSpeedLimit(const VehicleParams &v);

/// Distance (m) a gear change costs: the manoeuvring speed v_m x the time lost stopping from it
/// and starting again, v_m^2 / 2 x (1/a + 1/d) (cornerDistanceLost() at v_m down to 0). The
/// default cusp penalty of the car lattice.
double gearChangeDistance(const VehicleParams &v);

/// Seconds lost for a heading change of @p thetaRad (0 for none): cornerDistanceLost() / v_max
/// at the speed limit of a turn of R_min opened up by 1 / tan(theta / 2).
double cornerTimeLost(const VehicleParams &v, double thetaRad);

/// Options of the velocity profile (drivingTime()).
struct DrivingTimeParams
{
    double sampleStep{0.25};  ///< m between profile samples
    double window{2.0};       ///< m, chord before / after a sample for its heading change
    bool stopAtEnds{true};    ///< start from rest and stop at the goal
    /// m/s at the start when stopAtEnds (a vehicle already rolling into the path): the profile
    /// starts from this speed, not from rest (it still brakes where the path asks for less)
    double startSpeed{0.0};
    /// A path that reverses: a stop at each cusp (splitAtCusps()), each piece from rest to rest,
    /// a piece driven backwards within reverseSpeedLimit().
    bool reversing{false};
};

/// The speed limit of @p v through a heading change of @p thetaRad over a window of arc
/// length 2 x @p window: sqrt(a_lat r) with r = max(2 window / theta, R_min) (a_lat = min(mu g,
/// max_lateral_accel)); for a vehicle with corner speeds (paper C's), also at most its corner
/// speed for the angle (interpolated linearly between 0 (v_max), 45, 90 and 135 degrees); at
/// most v_max. A sharp polyline corner thus costs the speed of a turn at R_min (the vehicle
/// follows the path), a smooth curve of radius r the speed sqrt(a_lat r): paper C's 6 m/s at
/// 90 degrees is the speed on its 15 m radius.
double speedLimit(const VehicleParams &v, double thetaRad, double window);

/// A speed profile along a path: samples at arc length s (m) with position and speed (m/s).
struct VelocityProfile
{
    std::vector<double> s, x, y, v;
    double time{0.0};  ///< s, driving time of the whole profile
    /// Speed at arc length @p at (linear between samples; 0 outside).
    double speedAt(double at) const;
};

/// The profile drivingTime() integrates (see there).
VelocityProfile velocityProfile(const std::vector<Pose2> &path, const VehicleParams &v,
                                const DrivingTimeParams &params = DrivingTimeParams());

/**
 * @brief Time (s) the vehicle needs to drive @p path: the path is resampled every
 * DrivingTimeParams::sampleStep; each sample gets a speed limit from the heading change between
 * the chords over the window before and after it (speedLimit()), so a sharp grid corner, a
 * smooth curve of the same turn and a grid staircase along a straight line (no net heading
 * change) are treated alike; a forward pass (acceleration) and a backward pass (deceleration)
 * give the fastest profile under those limits, from and to rest; time = sum of
 * 2 ds / (v_i + v_i+1) (exact for constant acceleration between samples).
 */
double drivingTime(const std::vector<Pose2> &path, const VehicleParams &v,
                   const DrivingTimeParams &params = DrivingTimeParams());

}  // namespace gridcar
