// Paths as CSV, YAML or JSON files, the angle unit named in the file.
#include "gridcar/path/PathIO.h"

#include "gridcar/core/Angles.h"
#include "gridcar/core/Errors.h"
#include "gridcar/core/Files.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gridcar
{
namespace
{
std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string trim(const std::string &s)
{
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

double toRadians(double yaw, AngleUnit unit) { return unit == AngleUnit::Degrees ? yaw * M_PI / 180.0 : yaw; }

std::string number(double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

/// Header columns of a CSV path: the index of x, y and the yaw (-1: none) and the yaw's unit.
struct CsvColumns
{
    int x{0}, y{1}, yaw{2};
    AngleUnit unit{AngleUnit::Radians};
};

CsvColumns readHeader(const std::string &file, const std::string &line)
{
    CsvColumns c;
    c.x = c.y = c.yaw = -1;
    std::stringstream ss(line);
    std::string item;
    for (int i = 0; std::getline(ss, item, ','); ++i)
    {
        const std::string h = lower(trim(item));
        if (h == "x") c.x = i;
        else if (h == "y") c.y = i;
        else if (h == "yaw" || h == "yaw_rad") c.yaw = i;
        else if (h == "yaw_deg")
        {
            c.yaw = i;
            c.unit = AngleUnit::Degrees;
        }
    }
    if (c.x < 0 || c.y < 0)
        throw MapLoadError(file, "line 1: the header '" + printable(line) + "' names no x and y columns (x,y,yaw_rad or x,y,yaw_deg)");
    return c;
}

std::vector<Pose2> readCsv(const std::string &file)
{
    std::ifstream f(file);
    if (!f) throw MapLoadError(file, "cannot open the path file");
    std::vector<Pose2> path;
    CsvColumns cols;
    std::string line;
    for (int n = 1; std::getline(f, line); ++n)
    {
        line = trim(line);
        if (line.empty() || line[0] == '#') continue;
        if (n == 1 && !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-' || line[0] == '+' || line[0] == '.'))
        {
            cols = readHeader(file, line);
            continue;
        }
        std::vector<double> v;
        std::stringstream ss(line);
        std::string item;
        while (std::getline(ss, item, ','))
        {
            const std::string t = trim(item);
            std::size_t used = 0;
            double d = 0;
            try
            {
                d = std::stod(t, &used);
            }
            catch (const std::exception &)
            {
                used = 0;
            }
            if (used == 0 || used != t.size())
                throw MapLoadError(file, "line " + std::to_string(n) + ": '" + printable(t) + "' is not a number");
            v.push_back(d);
        }
        const int need = std::max({cols.x, cols.y, cols.yaw}) + 1;
        const bool yawGiven = cols.yaw >= 0 && int(v.size()) > cols.yaw;
        if (int(v.size()) < std::max(cols.x, cols.y) + 1 || int(v.size()) > std::max(need, 3))
            throw MapLoadError(file, "line " + std::to_string(n) + ": expected " + std::to_string(need) + " values (x,y[,yaw])");
        Pose2 p{v[cols.x], v[cols.y], yawGiven ? toRadians(v[cols.yaw], cols.unit) : 0.0};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw))
            throw MapLoadError(file, "line " + std::to_string(n) + ": values must be finite");
        p.yaw = wrapYaw(p.yaw);
        path.push_back(p);
    }
    return path;
}

double finiteNumber(const std::string &file, const YAML::Node &n, const std::string &where)
{
    if (!n || !n.IsScalar()) throw MapLoadError(file, where + " is missing or not a number");
    double v = 0;
    try
    {
        v = n.as<double>();
    }
    catch (const YAML::Exception &)
    {
        throw MapLoadError(file, where + ": '" + printable(n.Scalar()) + "' is not a number");
    }
    if (!std::isfinite(v)) throw MapLoadError(file, where + " must be finite");
    return v;
}

std::vector<Pose2> readStructured(const std::string &file)
{
    YAML::Node root;
    try
    {
        root = YAML::LoadFile(file);
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(file, std::string("not valid YAML / JSON: ") + e.what());
    }
    if (!root.IsMap()) throw MapLoadError(file, "expected a map {frame_id, angle_unit, poses}");
    AngleUnit unit = AngleUnit::Degrees;
    if (const YAML::Node u = root["angle_unit"])
    {
        const std::string s = u.IsScalar() ? lower(u.Scalar()) : "";
        if (s == "deg" || s == "degrees") unit = AngleUnit::Degrees;
        else if (s == "rad" || s == "radians") unit = AngleUnit::Radians;
        else throw MapLoadError(file, "angle_unit must be deg or rad, got '" + printable(u.IsScalar() ? u.Scalar() : "(not a word)") + "'");
    }
    else
        throw MapLoadError(file, "angle_unit (deg or rad) is missing: the yaw's unit must be named");
    const YAML::Node poses = root["poses"];
    if (!poses || !poses.IsSequence()) throw MapLoadError(file, "'poses' must be a list of {x, y, yaw}");
    std::vector<Pose2> path;
    for (std::size_t i = 0; i < poses.size(); ++i)
    {
        const std::string where = "pose " + std::to_string(i + 1);
        const YAML::Node p = poses[i];
        if (!p.IsMap()) throw MapLoadError(file, where + ": must be a map {x, y, yaw}");
        const double yaw = p["yaw"] ? finiteNumber(file, p["yaw"], where + " yaw") : 0.0;
        path.push_back({finiteNumber(file, p["x"], where + " x"), finiteNumber(file, p["y"], where + " y"),
                        wrapYaw(toRadians(yaw, unit))});
    }
    return path;
}
}  // namespace

std::string pathFormatOf(const std::string &file)
{
    const auto dot = file.find_last_of('.');
    const auto slash = file.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    const std::string ext = lower(file.substr(dot + 1));
    if (ext == "csv") return "csv";
    if (ext == "yaml" || ext == "yml") return "yaml";
    if (ext == "json") return "json";
    return "";
}

void writePath(const std::string &file, const std::vector<Pose2> &path, AngleUnit unit, const std::string &frameId)
{
    const std::string format = pathFormatOf(file);
    if (format.empty())
        throw std::invalid_argument("path file '" + file + "': the extension must be .csv, .yaml, .yml or .json");
    std::ofstream f(file);
    if (!f) throw MapLoadError(file, "cannot write the path file");
    const bool deg = unit == AngleUnit::Degrees;
    const auto yawOf = [deg](const Pose2 &p) { return number(deg ? p.yaw * 180.0 / M_PI : p.yaw); };
    if (format == "csv")
    {
        f << (deg ? "x,y,yaw_deg\n" : "x,y,yaw_rad\n");
        for (const Pose2 &p : path) f << number(p.x) << "," << number(p.y) << "," << yawOf(p) << "\n";
    }
    else if (format == "yaml")
    {
        f << "# x, y in metres in the frame below; yaw counter-clockwise from +x\n";
        f << "frame_id: " << frameId << "\nangle_unit: " << (deg ? "deg" : "rad") << "\nposes:\n";
        for (const Pose2 &p : path) f << "  - {x: " << number(p.x) << ", y: " << number(p.y) << ", yaw: " << yawOf(p) << "}\n";
    }
    else
    {
        f << "{\"frame_id\": \"" << frameId << "\", \"angle_unit\": \"" << (deg ? "deg" : "rad") << "\", \"poses\": [";
        for (std::size_t i = 0; i < path.size(); ++i)
            f << (i ? ",\n  " : "\n  ") << "{\"x\": " << number(path[i].x) << ", \"y\": " << number(path[i].y)
              << ", \"yaw\": " << yawOf(path[i]) << "}";
        f << "\n]}\n";
    }
    if (!f) throw MapLoadError(file, "cannot write the path file");
}

std::vector<Pose2> readPath(const std::string &file)
{
    requireReadableFile(file, "path file");
    const std::string format = pathFormatOf(file);
    std::vector<Pose2> path = format == "yaml" || format == "json" ? readStructured(file) : readCsv(file);
    if (path.size() < 2) throw MapLoadError(file, "a path needs at least two poses");
    return path;
}

}  // namespace gridcar
