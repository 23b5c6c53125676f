#include "gridcar/planners/CornerWeights.h"

#include "gridcar/vehicle/Dynamics.h"

#include <cmath>
#include <string>

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

double turnWeight(const CornerWeights &w, double rad)
{
    const double deg = std::abs(rad) * 180.0 / M_PI;
    const double table[4] = {0.0, w.w45, w.w90, w.w135};
    if (deg >= 135.0) return w.w135 * deg / 135.0;
    const int k = int(deg / 45.0);
    const double t = deg / 45.0 - k;
    return table[k] + t * (table[k + 1] - table[k]);
}

CornerWeights CornerWeightSettings::resolve(const VehicleParams &v) const
{
    const CornerWeights base = physics ? physicsCornerWeights(v) : CornerWeights();
    CornerWeights w;
    w.w45 = weightSet[0] ? weights.w45 : base.w45;
    w.w90 = weightSet[1] ? weights.w90 : base.w90;
    w.w135 = weightSet[2] ? weights.w135 : base.w135;
    return w;
}

namespace
{
using S = CornerWeightSettings;

/// The field of one corner weight (index 0, 1, 2: 45, 90, 135 degrees).
SettingField<S> weightField(const char *name, double CornerWeights::*member, int index, const char *range)
{
    return {name, range, "corner weight, m of lost distance (unset: per `weights`)",
            [=](S &s, const std::string &v) {
                s.weights.*member = settings::real(name, v, 0.0, 1e9, "a finite number >= 0 (metres)");
                s.weightSet[index] = true;
            },
            [=](const S &s) { return settings::print(s.weights.*member); }};
}

std::vector<SettingField<S>> makeFields()
{
    return {weightField("corner_weight_45", &CornerWeights::w45, 0, "0.:0.1:50."),
            weightField("corner_weight_90", &CornerWeights::w90, 1, "0.:0.1:100."),
            weightField("corner_weight_135", &CornerWeights::w135, 2, "0.:0.1:200."),
            {"weights", "paper,physics", "the weights not set: paper C's, or from the vehicle's dynamics",
             [](S &s, const std::string &v) {
                 s.physics = settings::oneOf("weights", v, {"paper", "physics"}, "paper or physics") == 1;
             },
             [](const S &s) { return std::string(s.physics ? "physics" : "paper"); }}};
}
}  // namespace

const std::vector<SettingField<CornerWeightSettings>> &cornerWeightFields()
{
    static const std::vector<SettingField<S>> fields = makeFields();
    return fields;
}

}  // namespace gridcar
