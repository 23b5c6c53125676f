#pragma once
/// @file VehicleParams.h
/// @brief Vehicle geometry and dynamics limits, with the papers' presets.

#include <array>
#include <string>
#include <vector>

namespace gridcar
{
/**
 * @brief A car-like vehicle: a rectangle whose reference point is the rear-axle centre, plus
 * the kinematic and dynamic limits the planners, objectives and simulator use.
 *
 * Body frame: x forward, y left. The rectangle spans x in [-rearOverhang, length - rearOverhang]
 * and y in [-width/2, width/2]. A vehicle with length == 0 and width == 0 is a point (plain
 * grid semantics: valid iff the cell under the point is free).
 *
 * A polygon footprint (Nav2's `footprint: [[x, y], ...]`, in the body frame, convex or not)
 * replaces the rectangle as the body: setFootprint() checks it and sets length, width and
 * rearOverhang to the rectangle around it (symmetric about the x axis), which the follower, the
 * simulation and the pictures' fast paths use as a conservative stand-in; collision checking
 * (FootprintChecker) is exact for the polygon itself.
 */
struct VehicleParams
{
    std::string name{"custom"};
    double length{4.5};            ///< m, bumper to bumper
    double width{1.8};             ///< m
    double wheelbase{2.7};         ///< m, rear to front axle
    double rearOverhang{0.9};      ///< m, rear bumper to rear axle (the reference point)
    double maxSteerDeg{35.0};      ///< deg, maximum front-wheel steering angle phi_max
    double maxSteerRateDeg{60.0};  ///< deg/s
    /// 1/m^2: how fast a path's curvature may change along it (`max_curvature_rate`); 0 = from
    /// the steering rate, curvatureRateLimit()
    double maxCurvatureRate{0.0};
    double maxSpeed{10.0};         ///< m/s
    /// m/s, speed limit driving backwards; 0 = the default of reverseSpeedLimit() (Dynamics.h)
    double maxReverseSpeed{0.0};
    double acceleration{2.0};      ///< m/s^2
    double deceleration{3.0};      ///< m/s^2 (positive number)
    double maxLateralAccel{2.0};   ///< m/s^2, sets cornering speed v = sqrt(a_lat r)
    double friction{0.7};          ///< tyre-road friction mu (v_max,corner = sqrt(mu g r))
    /// Optional recommended corner speeds for 45/90/135-degree grid corners (m/s); 0 = derive
    /// from the minimum turning radius and maxLateralAccel.
    double cornerSpeed45{0.0};
    double cornerSpeed90{0.0};
    double cornerSpeed135{0.0};

    /// The polygon footprint (counter-clockwise, body frame); empty: the rectangle.
    std::vector<std::array<double, 2>> footprint;

    bool isPoint() const { return length <= 0.0 && width <= 0.0; }
    bool hasPolygon() const { return !footprint.empty(); }
    /**
     * @brief Sets the polygon footprint: at least 3 finite vertices in the body frame, a simple
     * polygon (no edge crossing another, no repeated vertex) of positive area, in either
     * orientation (stored counter-clockwise); length, width and rearOverhang become the
     * rectangle around it. The reference point need not lie inside. Throws
     * std::invalid_argument naming what is wrong.
     */
    void setFootprint(std::vector<std::array<double, 2>> polygon);
    /// The body's outline, counter-clockwise in the body frame: the polygon, or the rectangle's
    /// four corners from rear-right; empty for a point.
    std::vector<std::array<double, 2>> outline() const;
    /// K_max = tan(phi_max) / wheelbase (paper I eq. 2), 1/m; +inf for a point vehicle.
    double maxCurvature() const;
    /// R_min = 1 / K_max, m.
    double minTurningRadius() const;
    /// Distance from the reference point to the rectangle's centre along x.
    double centreOffset() const { return length / 2.0 - rearOverhang; }
    /// Radius of the circle around the centre that contains the rectangle.
    double circumscribedRadius() const;
    /// Radius of the largest circle around the centre inside the rectangle.
    double inscribedRadius() const;
    /**
     * @brief sigma (1/m^2), the curvature rate the planners keep to: maxCurvatureRate when set,
     * else the rate the steering (maxSteerRateDeg, at the wheels' straight-ahead
     * sensitivity 1 / wheelbase) reaches at the speed of a turn at R_min,
     * sigma = (steer rate / wheelbase) / sqrt(a_lat R_min), so a transition from straight to full
     * lock takes K_max / sigma metres. Infinite for a point.
     */
    double curvatureRateLimit() const;

    /// Throws std::invalid_argument naming the first field that is negative, NaN or inconsistent.
    void validate() const;

    /**
     * @brief The same vehicle at scale @p k with the same timing: lengths, speeds and
     * accelerations (longitudinal and lateral) times k; angles and friction unchanged.
     *
     * Paper C drives a robot scaled down from its full-size car (30 m/s -> 0.6 m/s, 10 m/s
     * corners -> 0.2 m/s: k = 1/50). Distances derived from the dynamics scale by k too, e.g.
     * corner A*'s physics weights (CornerAStar::physicsWeights); the friction limit mu g does
     * not scale (gravity does not), so a cornering speed limited by friction rather than by
     * maxLateralAccel scales by sqrt(k) only. Throws std::invalid_argument unless k is finite
     * and positive.
     */
    VehicleParams scaled(double k) const;

    /// Named presets: paper-i, paper-c-car, paper-c-robot, point.
    static VehicleParams preset(const std::string &name);
    static std::vector<std::string> presetNames();
    /// A preset name, or a YAML file with the same field names (snake_case, see docs), an
    /// optional `preset:` to start from and an optional `scale:` applied last (scaled()).
    /// Throws std::invalid_argument (unknown preset) or MapLoadError (bad file).
    static VehicleParams fromNameOrFile(const std::string &nameOrPath);
    /// The same fields as a vehicle file, from YAML (or JSON) text; @p label names the vehicle
    /// and the source in errors (MapLoadError "<label>: <reason>").
    static VehicleParams fromYaml(const std::string &text, const std::string &label);
};

}  // namespace gridcar
