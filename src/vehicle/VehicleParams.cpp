#include "gridcar/vehicle/VehicleParams.h"

#include "gridcar/core/Errors.h"
#include "gridcar/core/Files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

namespace gridcar
{
double VehicleParams::maxCurvature() const
{
    if (isPoint()) return std::numeric_limits<double>::infinity();
    return std::tan(maxSteerDeg * M_PI / 180.0) / wheelbase;
}

double VehicleParams::minTurningRadius() const
{
    const double k = maxCurvature();
    return std::isinf(k) ? 0.0 : 1.0 / k;
}

double VehicleParams::circumscribedRadius() const { return 0.5 * std::hypot(length, width); }

double VehicleParams::inscribedRadius() const { return 0.5 * std::min(length, width); }

void VehicleParams::validate() const
{
    auto check = [](double v, const char *field, bool positive) {
        if (!std::isfinite(v) || v < 0.0 || (positive && v == 0.0))
            throw std::invalid_argument(std::string("vehicle field '") + field + "' must be " +
                                        (positive ? "positive" : "non-negative") + " and finite");
    };
    check(length, "length", false);
    check(width, "width", false);
    if ((length == 0.0) != (width == 0.0))
        throw std::invalid_argument("vehicle length and width must both be zero (point) or both positive");
    check(wheelbase, "wheelbase", true);
    if (hasPolygon())
    {
        // the rectangle around the polygon, as setFootprint() set it (the reference point may lie outside)
        VehicleParams box;
        box.setFootprint(footprint);
        if (std::abs(box.length - length) > 1e-9 || std::abs(box.width - width) > 1e-9 ||
            std::abs(box.rearOverhang - rearOverhang) > 1e-9)
            throw std::invalid_argument("vehicle length, width and rear_overhang must be the footprint's bounding box "
                                        "(set them with setFootprint)");
    }
    else
    {
        check(rearOverhang, "rear_overhang", false);
        if (!isPoint() && rearOverhang > length)
            throw std::invalid_argument("vehicle rear_overhang must not exceed length");
    }
    check(maxSteerDeg, "max_steer_deg", true);
    if (maxSteerDeg >= 90.0) throw std::invalid_argument("vehicle max_steer_deg must be below 90");
    check(maxSteerRateDeg, "max_steer_rate_deg", true);
    check(maxCurvatureRate, "max_curvature_rate", false);
    check(maxSpeed, "max_speed", true);
    check(maxReverseSpeed, "max_reverse_speed", false);
    check(acceleration, "acceleration", true);
    check(deceleration, "deceleration", true);
    check(maxLateralAccel, "max_lateral_accel", true);
    check(friction, "friction", true);
    check(cornerSpeed45, "corner_speed_45", false);
    check(cornerSpeed90, "corner_speed_90", false);
    check(cornerSpeed135, "corner_speed_135", false);
    if (length > 1000.0 || width > 1000.0) throw std::invalid_argument("vehicle larger than 1 km is absurd");
}

double VehicleParams::curvatureRateLimit() const
{
    if (isPoint()) return HUGE_VAL;
    if (maxCurvatureRate > 0) return maxCurvatureRate;
    const double aLat = std::min(friction * 9.81, maxLateralAccel);
    const double v = std::sqrt(aLat * minTurningRadius());
    return (maxSteerRateDeg * M_PI / 180.0 / wheelbase) / std::max(v, 1e-3);
}

std::vector<std::string> VehicleParams::presetNames() { return {"paper-i", "paper-c-car", "paper-c-robot", "point"}; }

VehicleParams VehicleParams::preset(const std::string &name)
{
    VehicleParams v;
    v.name = name;
    if (name == "paper-i")
    {
        // Paper I: l = 1.56 m wheelbase, D = 1.835 m wide, L = 5.555 m long (as printed),
        // phi_max = 40 deg. Overhang split evenly; speeds are a campus car's (not in the paper).
        v.length = 5.555;
        v.width = 1.835;
        v.wheelbase = 1.56;
        v.rearOverhang = (5.555 - 1.56) / 2.0;
        v.maxSteerDeg = 40.0;
        v.maxSpeed = 5.0;
        v.acceleration = 1.0;
        v.deceleration = 1.5;
        v.maxLateralAccel = 1.5;
        v.maxCurvatureRate = 0.4;  // curvatureRateLimit(): 60 deg/s / 1.56 m at 1.67 m/s
    }
    else if (name == "paper-c-car")
    {
        // Paper C's full-size vehicle: 30 m/s (100 km/h), 3 m/s^2, recommended corner speeds
        // 10 m/s (45 deg, r ~ 25 m) and 6 m/s (90 deg, r = 15 m). Body of a mid-size car.
        v.length = 4.5;
        v.width = 1.8;
        v.wheelbase = 2.7;
        v.rearOverhang = 0.9;
        v.maxSteerDeg = 35.0;
        v.maxSpeed = 30.0;
        v.acceleration = 3.0;
        v.deceleration = 3.0;
        v.maxLateralAccel = 2.4;  // 6^2 / 15
        v.friction = 0.7;
        v.cornerSpeed45 = 10.0;
        v.cornerSpeed90 = 6.0;
        v.cornerSpeed135 = 4.0;
        v.maxCurvatureRate = 0.13;  // curvatureRateLimit(): 60 deg/s / 2.7 m at 3.04 m/s
    }
    else if (name == "paper-c-robot")
    {
        // Paper C's scaled pseudo-UGV: 0.6 m/s, corners at 0.2 m/s. The paper gives no body
        // size; we assume a small 0.5 m x 0.4 m car-like robot (wheelbase 0.32 m, 30 deg).
        v.length = 0.5;
        v.width = 0.4;
        v.wheelbase = 0.32;
        v.rearOverhang = 0.09;
        v.maxSteerDeg = 30.0;
        v.maxSpeed = 0.6;
        v.acceleration = 0.3;
        v.deceleration = 0.3;
        v.maxLateralAccel = 0.2 * 0.2 / 0.55;  // 0.2 m/s on a ~0.55 m radius corner
        v.cornerSpeed45 = 0.3;
        v.cornerSpeed90 = 0.2;
        v.cornerSpeed135 = 0.15;
        v.maxCurvatureRate = 16.0;  // curvatureRateLimit(): 60 deg/s / 0.32 m at 0.2 m/s
    }
    else if (name == "point")
    {
        v.length = 0.0;
        v.width = 0.0;
        v.wheelbase = 1.0;
        v.rearOverhang = 0.0;
        v.maxSteerDeg = 89.0;
        v.maxSpeed = 1.0;
        v.acceleration = 1.0;
        v.deceleration = 1.0;
        v.maxLateralAccel = 1.0;
    }
    else
    {
        std::string names;
        for (const auto &n : presetNames()) names += (names.empty() ? "" : ", ") + n;
        throw std::invalid_argument("unknown vehicle preset '" + printable(name) + "' (known: " + names + ", or a YAML file)");
    }
    return v;
}

VehicleParams VehicleParams::scaled(double k) const
{
    if (!std::isfinite(k) || k <= 0.0)
        throw std::invalid_argument("vehicle scale must be positive and finite, got " + std::to_string(k));
    VehicleParams v = *this;
    for (double *len : {&v.length, &v.width, &v.wheelbase, &v.rearOverhang})
        *len *= k;
    for (auto &p : v.footprint)
        for (double &c : p) c *= k;
    for (double *rate : {&v.maxSpeed, &v.maxReverseSpeed, &v.acceleration, &v.deceleration, &v.maxLateralAccel, &v.cornerSpeed45,
                         &v.cornerSpeed90, &v.cornerSpeed135})
        *rate *= k;
    v.maxCurvatureRate /= k * k;  // 1/m^2
    std::ostringstream name;
    name << this->name << " x " << k;
    v.name = name.str();
    return v;
}

namespace
{
/// Nav2's footprint: a list [[x, y], ...] or the same as a string ("[[0.5, 0.3], [0.5, -0.3], ...]").
std::vector<std::array<double, 2>> readFootprint(const std::string &file, YAML::Node fp)
{
    if (fp.IsScalar())
    {
        try
        {
            fp = YAML::Load(fp.Scalar());
        }
        catch (const YAML::Exception &)
        {
            throw MapLoadError(file, "field 'footprint' must be a list of [x, y] points");
        }
    }
    if (!fp.IsSequence()) throw MapLoadError(file, "field 'footprint' must be a list of [x, y] points");
    std::vector<std::array<double, 2>> poly;
    for (std::size_t i = 0; i < fp.size(); ++i)
    {
        const YAML::Node p = fp[i];
        if (!p.IsSequence() || p.size() != 2)
            throw MapLoadError(file, "footprint point " + std::to_string(i + 1) + " must be [x, y]");
        try
        {
            poly.push_back({p[0].as<double>(), p[1].as<double>()});
        }
        catch (const YAML::Exception &)
        {
            throw MapLoadError(file, "footprint point " + std::to_string(i + 1) + " must hold two numbers");
        }
    }
    return poly;
}
}  // namespace

/// The vehicle of a YAML mapping (a file's or a text's); @p s names it in errors and becomes its name.
VehicleParams vehicleFromYamlNode(const YAML::Node &root, const std::string &s);

VehicleParams VehicleParams::fromNameOrFile(const std::string &s)
{
    for (const auto &n : presetNames())
        if (n == s) return preset(s);
    const bool looksLikeFile = s.find('/') != std::string::npos || s.find('.') != std::string::npos;
    std::error_code ec;
    if (!looksLikeFile && !std::filesystem::exists(s, ec)) return preset(s);  // throws "unknown vehicle preset" with the list
    requireReadableFile(s, "vehicle file");
    YAML::Node root;
    try
    {
        root = YAML::LoadFile(s);
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(s, std::string("YAML syntax error: ") + e.what());
    }
    return vehicleFromYamlNode(root, s);
}

VehicleParams VehicleParams::fromYaml(const std::string &text, const std::string &label)
{
    YAML::Node root;
    try
    {
        root = YAML::Load(text);
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(label, std::string("YAML syntax error: ") + e.what());
    }
    return vehicleFromYamlNode(root, label);
}

VehicleParams vehicleFromYamlNode(const YAML::Node &root, const std::string &s)
{
    if (!root.IsMap()) throw MapLoadError(s, "expected a YAML mapping of vehicle fields");
    VehicleParams v;
    if (root["preset"])
    {
        if (!root["preset"].IsScalar()) throw MapLoadError(s, "field 'preset' must be a preset name");
        v = VehicleParams::preset(root["preset"].as<std::string>());
    }
    v.name = s;
    double scale = 1.0;
    struct Field
    {
        const char *key;
        double *ptr;
    } fields[] = {{"length", &v.length},
                  {"width", &v.width},
                  {"wheelbase", &v.wheelbase},
                  {"rear_overhang", &v.rearOverhang},
                  {"max_steer_deg", &v.maxSteerDeg},
                  {"max_steer_rate_deg", &v.maxSteerRateDeg},
                  {"max_curvature_rate", &v.maxCurvatureRate},
                  {"max_speed", &v.maxSpeed},
                  {"max_reverse_speed", &v.maxReverseSpeed},
                  {"acceleration", &v.acceleration},
                  {"deceleration", &v.deceleration},
                  {"max_lateral_accel", &v.maxLateralAccel},
                  {"friction", &v.friction},
                  {"corner_speed_45", &v.cornerSpeed45},
                  {"corner_speed_90", &v.cornerSpeed90},
                  {"corner_speed_135", &v.cornerSpeed135}};
    bool boxGiven = false;
    for (const auto &kv : root)
    {
        if (!kv.first.IsScalar()) throw MapLoadError(s, "field names must be plain words, not lists or mappings");
        const std::string key = kv.first.as<std::string>();
        if (key == "preset" || key == "name" || key == "footprint") continue;
        if (key == "length" || key == "width" || key == "rear_overhang") boxGiven = true;
        bool known = false;
        if (key == "scale")
        {
            known = true;
            try
            {
                scale = kv.second.as<double>();
            }
            catch (const YAML::Exception &)
            {
                throw MapLoadError(s, "field 'scale' must be a number");
            }
            if (!std::isfinite(scale) || scale <= 0.0) throw MapLoadError(s, "field 'scale' must be positive and finite");
        }
        for (auto &f : fields)
            if (key == f.key)
            {
                known = true;
                try
                {
                    *f.ptr = kv.second.as<double>();
                }
                catch (const YAML::Exception &)
                {
                    throw MapLoadError(s, "field '" + key + "' must be a number");
                }
            }
        if (!known) throw MapLoadError(s, "unknown vehicle field '" + key + "'");
    }
    if (const YAML::Node fp = root["footprint"])
    {
        if (boxGiven)
            throw MapLoadError(s, "give either 'footprint' or length / width / rear_overhang: the footprint sets them");
        v.footprint.clear();
        try
        {
            v.setFootprint(readFootprint(s, fp));
        }
        catch (const std::invalid_argument &e)
        {
            throw MapLoadError(s, e.what());
        }
    }
    if (scale != 1.0)
    {
        v = v.scaled(scale);
        v.name = s;
    }
    try
    {
        v.validate();
    }
    catch (const std::invalid_argument &e)
    {
        throw MapLoadError(s, e.what());
    }
    return v;
}

}  // namespace gridcar
