// Scripted moving obstacles and their scenario files.
#include "gridcar/sim/Simulation.h"

#include "gridcar/core/Errors.h"
#include "gridcar/core/Files.h"

#include <yaml-cpp/yaml.h>

#include <cmath>

namespace gridcar
{
void MovingObstacle::positionAt(double t, double &x, double &y) const
{
    if (waypoints.empty())
    {
        x = y = 0.0;
        return;
    }
    x = waypoints.front().first;
    y = waypoints.front().second;
    if (waypoints.size() == 1 || speed <= 0.0 || t <= startTime) return;
    std::vector<std::pair<double, double>> pts = waypoints;
    if (loop) pts.push_back(waypoints.front());
    double total = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
        total += std::hypot(pts[i].first - pts[i - 1].first, pts[i].second - pts[i - 1].second);
    double travel = (t - startTime) * speed;
    if (loop && total > 0) travel = std::fmod(travel, total);
    for (std::size_t i = 1; i < pts.size(); ++i)
    {
        const double len = std::hypot(pts[i].first - pts[i - 1].first, pts[i].second - pts[i - 1].second);
        if (travel <= len && len > 0)
        {
            const double f = travel / len;
            x = pts[i - 1].first + f * (pts[i].first - pts[i - 1].first);
            y = pts[i - 1].second + f * (pts[i].second - pts[i - 1].second);
            return;
        }
        travel -= len;
    }
    x = pts.back().first;
    y = pts.back().second;
}

double MovingObstacle::velocityEstimate(double t, double dt, int axis) const
{
    double x1, y1, x0, y0;
    positionAt(t, x1, y1);
    positionAt(std::max(0.0, t - dt), x0, y0);
    if (!(dt > 0)) return 0.0;
    return (axis == 0 ? x1 - x0 : y1 - y0) / dt;
}

double MovingObstacle::distanceFrom(double px, double py, double t) const
{
    double x, y;
    positionAt(t, x, y);
    if (shape == Shape::Disc) return std::hypot(px - x, py - y) - radius;
    const double dx = std::abs(px - x) - sizeX / 2, dy = std::abs(py - y) - sizeY / 2;
    if (dx <= 0 && dy <= 0) return std::max(dx, dy);
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
}

Scenario Scenario::load(const std::string &file)
{
    Scenario sc;
    YAML::Node y;
    requireReadableFile(file, "scenario file");
    try
    {
        y = YAML::LoadFile(file);
    }
    catch (const YAML::BadFile &)
    {
        throw MapLoadError(file, "cannot open the scenario file");
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(file, "not valid YAML (" + std::string(e.what()) + ")");
    }
    if (!y.IsMap() || !y["obstacles"] || !y["obstacles"].IsSequence())
        throw MapLoadError(file, "expected 'obstacles:' with a list of moving obstacles");
    std::size_t i = 0;
    for (const auto &n : y["obstacles"])
    {
        ++i;
        const std::string where = "obstacle " + std::to_string(i) + ": ";
        MovingObstacle o;
        try
        {
            o.name = n["name"] ? n["name"].as<std::string>() : "obstacle " + std::to_string(i);
            const std::string shape = n["shape"] ? n["shape"].as<std::string>() : "disc";
            if (shape == "disc")
            {
                o.shape = MovingObstacle::Shape::Disc;
                if (n["radius"]) o.radius = n["radius"].as<double>();
            }
            else if (shape == "box")
            {
                o.shape = MovingObstacle::Shape::Box;
                if (!n["size"] || !n["size"].IsSequence() || n["size"].size() != 2)
                    throw MapLoadError(file, where + "a box needs size: [sx, sy]");
                o.sizeX = n["size"][0].as<double>();
                o.sizeY = n["size"][1].as<double>();
            }
            else
                throw MapLoadError(file, where + "shape must be disc or box, got '" + shape + "'");
            if (!n["waypoints"] || !n["waypoints"].IsSequence() || n["waypoints"].size() == 0)
                throw MapLoadError(file, where + "needs waypoints: [[x, y], ...]");
            for (const auto &w : n["waypoints"])
            {
                if (!w.IsSequence() || w.size() != 2) throw MapLoadError(file, where + "a waypoint must be [x, y]");
                o.waypoints.push_back({w[0].as<double>(), w[1].as<double>()});
            }
            if (n["speed"]) o.speed = n["speed"].as<double>();
            if (n["start_time"]) o.startTime = n["start_time"].as<double>();
            if (n["loop"]) o.loop = n["loop"].as<bool>();
        }
        catch (const YAML::Exception &e)
        {
            throw MapLoadError(file, where + "bad value (" + std::string(e.what()) + ")");
        }
        auto finite = [](double v) { return std::isfinite(v); };
        bool ok = finite(o.radius) && o.radius > 0 && finite(o.sizeX) && o.sizeX > 0 && finite(o.sizeY) && o.sizeY > 0 &&
                  finite(o.speed) && o.speed >= 0 && finite(o.startTime);
        for (const auto &w : o.waypoints) ok = ok && finite(w.first) && finite(w.second);
        if (!ok) throw MapLoadError(file, where + "sizes must be positive and all numbers finite");
        sc.obstacles.push_back(o);
    }
    return sc;
}

}  // namespace gridcar
