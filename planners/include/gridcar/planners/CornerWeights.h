#pragma once
/// @file CornerWeights.h
/// @brief Corner-weighted A*'s corner weights (paper C): the metres of lost distance a heading
/// change of 45, 90 or 135 degrees costs, paper C's values or from the vehicle's dynamics.

#include "gridcar/planners/Settings.h"
#include "gridcar/vehicle/VehicleParams.h"

#include <vector>

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

/// Corner weight (m) of a heading change of @p rad radians under @p w: linear in the turn angle
/// between the table's 0 / 45 / 90 / 135 degrees, and in proportion beyond 135.
double turnWeight(const CornerWeights &w, double rad);

/// corner A*'s weight settings, which both its planners (CornerAStar, CornerAStarGrid) declare:
/// `corner_weight_45`, `corner_weight_90`, `corner_weight_135` (m, >= 0) and `weights`
/// (paper | physics).
struct CornerWeightSettings
{
    CornerWeights weights;                    ///< as set (paper C's values until set)
    bool weightSet[3]{false, false, false};   ///< which were set explicitly (45, 90, 135)
    bool physics{false};                      ///< `weights` = physics
    /// The weights in use for vehicle @p v: each set explicitly as given, the others paper C's
    /// or, with `weights = physics`, physicsCornerWeights(v).
    CornerWeights resolve(const VehicleParams &v) const;
};

/// The table of the corner-weight settings (Settings.h).
const std::vector<SettingField<CornerWeightSettings>> &cornerWeightFields();

}  // namespace gridcar
