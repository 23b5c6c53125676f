#pragma once
/// @file FclShapes.h
/// @brief FCL objects of gridcar_core (private): boxes in the z = 0 plane, the vehicle body,
/// moving obstacles. One place builds them, for the footprint checker and the simulation.

#include "gridcar/vehicle/VehicleParams.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace gridcar::detail
{
/// An sx x sy box (height 1) centred at (cx, cy), rotated by @p yaw about z.
inline std::unique_ptr<fcl::CollisionObjectd> makeBox(double cx, double cy, double sx, double sy, double yaw = 0.0)
{
    auto geom = std::make_shared<fcl::Boxd>(sx, sy, 1.0);
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = fcl::Vector3d(cx, cy, 0.0);
    tf.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return std::make_unique<fcl::CollisionObjectd>(geom, tf);
}

/// The vehicle's rectangle with its reference point (rear-axle centre) at (x, y, yaw), grown by
/// @p margin on every side.
inline std::unique_ptr<fcl::CollisionObjectd> vehicleBox(const VehicleParams &v, double x, double y, double yaw,
                                                         double margin = 0.0)
{
    const double off = v.centreOffset();
    return makeBox(x + off * std::cos(yaw), y + off * std::sin(yaw), std::max(v.length + 2 * margin, 1e-3),
                   std::max(v.width + 2 * margin, 1e-3), yaw);
}

/// A vertical cylinder (height 1) of radius @p r at (x, y).
inline std::unique_ptr<fcl::CollisionObjectd> makeCylinder(double x, double y, double r)
{
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = fcl::Vector3d(x, y, 0.0);
    return std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::Cylinderd>(r, 1.0), tf);
}

}  // namespace gridcar::detail
