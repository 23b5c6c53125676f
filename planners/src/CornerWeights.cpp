#include "gridcar/planners/CornerWeights.h"

#include "gridcar/vehicle/Dynamics.h"

namespace gridcar
{
CornerWeights physicsCornerWeights(const VehicleParams &v)
{
    auto lost = [&](double vc) { return cornerDistanceLost(v, vc); };
    const CornerSpeeds vc = cornerSpeeds(v);
    CornerWeights w;
    w.w45 = lost(vc.v45);
    w.w90 = lost(vc.v90);
    w.w135 = lost(vc.v135);
    return w;
}

}  // namespace gridcar
