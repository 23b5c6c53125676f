#pragma once
/// @file CornerWeights.h
/// @brief Corner-weighted A*'s corner weights (paper C): the metres of lost distance a heading
/// change of 45, 90 or 135 degrees costs, paper C's values or from the vehicle's dynamics.

#include "gridcar/vehicle/VehicleParams.h"

namespace gridcar
{
/// Corner weights of corner-weighted A* (metres of lost distance per heading change).
struct CornerWeights
{
    double w45{2.7};   ///< paper C's value
    double w90{7.0};   ///< paper C's value
    double w135{11.3}; ///< our choice (see CornerAStar)
};

/// Corner A*'s `physics` weights: cornerDistanceLost() at each of cornerSpeeds() (m; both in
/// gridcar/vehicle/Dynamics.h).
CornerWeights physicsCornerWeights(const VehicleParams &v);

}  // namespace gridcar
