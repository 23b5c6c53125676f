// gridcar vehicle: a vehicle's parameters and what follows from them.
#include "Cli.h"

#include "gridcar/planners/CornerWeights.h"
#include "gridcar/vehicle/Dynamics.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

namespace gridcar::cli
{
namespace
{
struct VehicleOptions
{
    std::string vehicle{"paper-i"};
    double scale{1.0};
    bool json{false};
};

/// Prints a vehicle's parameters, what follows from them (K_max, R_min, corner speeds) and the
/// corner A* weights (paper and physics).
int runVehicle(const VehicleOptions &o)
{
    VehicleParams v = VehicleParams::fromNameOrFile(o.vehicle);
    if (o.scale != 1.0)
    {
        try
        {
            v = v.scaled(o.scale);
            v.validate();
        }
        catch (const std::invalid_argument &e)
        {
            throw InputError(std::string("--scale: ") + e.what());
        }
    }
    const CornerSpeeds vc = cornerSpeeds(v);
    const CornerWeights physics = physicsCornerWeights(v);
    const CornerWeights paper;
    if (o.json)
    {
        nlohmann::json j;
        j["name"] = v.name;
        j["length"] = v.length;
        j["width"] = v.width;
        j["wheelbase"] = v.wheelbase;
        j["rear_overhang"] = v.rearOverhang;
        if (v.hasPolygon()) j["footprint"] = v.footprint;
        j["max_steer_deg"] = v.maxSteerDeg;
        j["max_speed"] = v.maxSpeed;
        j["acceleration"] = v.acceleration;
        j["deceleration"] = v.deceleration;
        j["max_lateral_accel"] = v.maxLateralAccel;
        j["friction"] = v.friction;
        j["max_curvature"] = v.isPoint() ? nlohmann::json(nullptr) : nlohmann::json(v.maxCurvature());
        j["min_turning_radius"] = v.minTurningRadius();
        j["max_steer_rate_deg"] = v.maxSteerRateDeg;
        j["max_curvature_rate"] = v.isPoint() ? nlohmann::json(nullptr) : nlohmann::json(v.curvatureRateLimit());
        j["corner_speeds"] = {vc.v45, vc.v90, vc.v135};
        j["physics_weights"] = {physics.w45, physics.w90, physics.w135};
        j["paper_weights"] = {paper.w45, paper.w90, paper.w135};
        printJson(j.dump(2));
        return 0;
    }
    std::printf("vehicle %s\n", v.name.c_str());
    if (v.isPoint())
        std::printf("  body: a point (plain grid semantics)\n");
    else
        std::printf("  body: %.3g m x %.3g m, wheelbase %.3g m, rear overhang %.3g m\n", v.length, v.width, v.wheelbase,
                    v.rearOverhang);
    if (v.hasPolygon())
    {
        std::printf("  footprint: polygon of %zu vertices (the body above is the rectangle around it):", v.footprint.size());
        for (const auto &p : v.footprint) std::printf(" [%.3g, %.3g]", p[0], p[1]);
        std::printf("\n");
    }
    std::printf("  steering: max %.3g deg -> K_max %.4g 1/m, R_min %.4g m\n", v.maxSteerDeg, v.maxCurvature(),
                v.minTurningRadius());
    std::printf("  speed: max %.4g m/s, acceleration %.4g m/s^2, deceleration %.4g m/s^2, lateral %.4g m/s^2, "
                "friction %.3g\n",
                v.maxSpeed, v.acceleration, v.deceleration, v.maxLateralAccel, v.friction);
    std::printf("  corner speeds: %.4g / %.4g / %.4g m/s (45 / 90 / 135 deg)\n", vc.v45, vc.v90, vc.v135);
    std::printf("corner-astar weights (m)       45 deg    90 deg   135 deg\n");
    std::printf("  weights=paper (defaults)  %9.2f %9.2f %9.2f\n", paper.w45, paper.w90, paper.w135);
    std::printf("  weights=physics           %9.2f %9.2f %9.2f\n", physics.w45, physics.w90, physics.w135);
    std::printf("physics weight = (v_max - v_c)^2 / 2 x (1/a + 1/d): v_max x the time lost braking for the corner and "
                "accelerating again\n");
    return 0;
}
}  // namespace

Command addVehicleCommand(CLI::App &app)
{
    auto o = std::make_shared<VehicleOptions>();
    auto *c = app.add_subcommand("vehicle", "Print a vehicle's parameters, its K_max, R_min and corner speeds, and the "
                                            "corner-astar weights (paper defaults and weights=physics) it implies");
    addVehicleOption(c, o->vehicle);
    c->add_option("--scale", o->scale,
                  "Scale the vehicle by K with the same timing: lengths, speeds and accelerations x K (paper C's robot is "
                  "its car at K = 0.6 / 30 = 0.02)")
        ->capture_default_str();
    c->add_flag("--json", o->json,
                "Print one JSON object: the fields, max_curvature, min_turning_radius, corner_speeds, physics_weights and "
                "paper_weights ([45, 90, 135 deg])");
    return {c, [o] { return runVehicle(*o); }};
}

}  // namespace gridcar::cli
