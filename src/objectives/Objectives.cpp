#include "gridcar/objectives/Objectives.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/SE2StateSpace.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace ob = ompl::base;

ObstacleDistanceObjective::ObstacleDistanceObjective(const ob::SpaceInformationPtr &si,
                                                     std::shared_ptr<const DistanceField> field, double delta,
                                                     bool voronoi)
  : ob::StateCostIntegralObjective(si, true), field_(std::move(field)), delta_(delta), voronoi_(voronoi)
{
    if (!field_) throw std::invalid_argument("ObstacleDistanceObjective needs a distance field");
    if (!std::isfinite(delta) || delta < 0) throw std::invalid_argument("obstacle cost delta must be finite and >= 0");
    description_ = "obstacle distance (delta / d_O integrated along the path)";
}

ob::Cost ObstacleDistanceObjective::stateCost(const ob::State *s) const
{
    const auto *se2 = s->as<ob::SE2StateSpace::StateType>();
    if (voronoi_) return ob::Cost(delta_ * field_->voronoiField(se2->getX(), se2->getY()));
    const double d = std::max(field_->distance(se2->getX(), se2->getY()), 0.5 * field_->resolution());
    return ob::Cost(delta_ / d);
}

double speedLimit(const VehicleParams &v, double theta, double window)
{
    const double V = v.maxSpeed;
    theta = std::abs(theta);
    if (theta < 1e-9) return V;
    // curvature: the radius the heading change implies over the window, never below R_min
    const double alat = std::min(v.friction * 9.81, v.maxLateralAccel);
    const double r = std::max(window > 0 ? 2.0 * window / theta : 0.0, v.minTurningRadius());
    double lim = alat > 0 ? std::sqrt(alat * r) : V;
    if (v.cornerSpeed45 > 0 || v.cornerSpeed90 > 0 || v.cornerSpeed135 > 0)
    {
        // the vehicle's corner speeds cap the speed through a corner of this angle
        const double deg = std::min(theta * 180.0 / M_PI, 180.0);
        const double pts[4] = {V, v.cornerSpeed45 > 0 ? v.cornerSpeed45 : V, v.cornerSpeed90 > 0 ? v.cornerSpeed90 : V,
                               v.cornerSpeed135 > 0 ? v.cornerSpeed135 : (v.cornerSpeed90 > 0 ? v.cornerSpeed90 : V)};
        const double k = std::min(deg / 45.0, 3.0);
        const int i = std::min(int(k), 2);
        lim = std::min(lim, pts[i] + (pts[i + 1] - pts[i]) * (k - i));
    }
    return std::clamp(lim, 1e-3, V);
}

double VelocityProfile::speedAt(double at) const
{
    if (s.empty() || at < s.front() || at > s.back()) return 0.0;
    const auto it = std::upper_bound(s.begin(), s.end(), at);
    if (it == s.end()) return v.back();
    const std::size_t i = std::size_t(it - s.begin());
    if (i == 0) return v.front();
    const double t = (at - s[i - 1]) / std::max(s[i] - s[i - 1], 1e-12);
    return v[i - 1] + t * (v[i] - v[i - 1]);
}

double drivingTime(const std::vector<Pose2> &path, const VehicleParams &v, const DrivingTimeParams &p)
{
    return velocityProfile(path, v, p).time;
}

VelocityProfile velocityProfile(const std::vector<Pose2> &path, const VehicleParams &v, const DrivingTimeParams &p)
{
    VelocityProfile prof;
    if (!(v.maxSpeed > 0) || !(v.acceleration > 0) || !(v.deceleration > 0))
        throw std::invalid_argument("drivingTime needs max_speed, acceleration and deceleration > 0");
    std::vector<Pose2> pts;
    for (const Pose2 &q : path)
        if (pts.empty() || std::hypot(q.x - pts.back().x, q.y - pts.back().y) > 1e-9) pts.push_back(q);
    if (pts.size() < 2) return prof;
    // resample by arc length
    std::vector<double> xs, ys;
    double total = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) total += std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    const int n = std::max(1, int(std::ceil(total / p.sampleStep)));
    const double ds = total / n;
    std::size_t seg = 1;
    double segStart = 0;
    for (int k = 0; k <= n; ++k)
    {
        const double s = std::min(total, k * ds);
        while (seg + 1 < pts.size() &&
               segStart + std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y) < s)
        {
            segStart += std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y);
            ++seg;
        }
        const double len = std::hypot(pts[seg].x - pts[seg - 1].x, pts[seg].y - pts[seg - 1].y);
        const double t = len > 0 ? std::clamp((s - segStart) / len, 0.0, 1.0) : 0.0;
        xs.push_back(pts[seg - 1].x + t * (pts[seg].x - pts[seg - 1].x));
        ys.push_back(pts[seg - 1].y + t * (pts[seg].y - pts[seg - 1].y));
    }
    const int N = int(xs.size());
    const int w = std::max(1, int(std::lround(p.window / ds)));
    std::vector<double> vel(N);
    for (int k = 0; k < N; ++k)
    {
        const int a = std::max(0, k - w), b = std::min(N - 1, k + w);
        double theta = 0;
        if (a < k && k < b)
        {
            const double h1 = std::atan2(ys[k] - ys[a], xs[k] - xs[a]);
            const double h2 = std::atan2(ys[b] - ys[k], xs[b] - xs[k]);
            theta = std::abs(std::remainder(h2 - h1, 2 * M_PI));
        }
        vel[k] = speedLimit(v, theta, p.window);
    }
    if (p.stopAtEnds)
    {
        vel.front() = 0.0;
        vel.back() = 0.0;
    }
    for (int k = 1; k < N; ++k) vel[k] = std::min(vel[k], std::sqrt(vel[k - 1] * vel[k - 1] + 2 * v.acceleration * ds));
    for (int k = N - 2; k >= 0; --k)
        vel[k] = std::min(vel[k], std::sqrt(vel[k + 1] * vel[k + 1] + 2 * v.deceleration * ds));
    double time = 0;
    for (int k = 1; k < N; ++k) time += 2 * ds / std::max(vel[k - 1] + vel[k], 1e-9);
    prof.time = time;
    prof.x = xs;
    prof.y = ys;
    prof.v = vel;
    for (int k = 0; k < N; ++k) prof.s.push_back(k * ds);
    return prof;
}

DrivingTimeObjective::DrivingTimeObjective(const ob::SpaceInformationPtr &si, const VehicleParams &vehicle)
  : ob::OptimizationObjective(si), vehicle_(vehicle)
{
    if (!(vehicle.maxSpeed > 0) || !(vehicle.acceleration > 0) || !(vehicle.deceleration > 0))
        throw std::invalid_argument("DrivingTimeObjective needs max_speed, acceleration and deceleration > 0");
    description_ = "driving time (s)";
}

ob::Cost DrivingTimeObjective::stateCost(const ob::State *) const { return identityCost(); }

double DrivingTimeObjective::turnPenalty(double theta) const
{
    theta = std::abs(theta);
    if (theta < 1e-9) return 0.0;
    // the corner's radius: R_min opened up for a gentler turn (as corner-astar's physics weights)
    const double r = std::max(vehicle_.minTurningRadius(), 1e-3) / std::tan(std::min(theta, M_PI - 1e-6) / 2);
    const double vc = speedLimit(vehicle_, theta, r * theta / 2);
    const double V = vehicle_.maxSpeed;
    return 0.5 * (V - vc) * (V - vc) * (1.0 / vehicle_.acceleration + 1.0 / vehicle_.deceleration) / V;
}

ob::Cost DrivingTimeObjective::motionCost(const ob::State *s1, const ob::State *s2) const
{
    const auto *a = s1->as<ob::SE2StateSpace::StateType>();
    const auto *b = s2->as<ob::SE2StateSpace::StateType>();
    const double dx = b->getX() - a->getX(), dy = b->getY() - a->getY();
    const double len = std::hypot(dx, dy);
    double t = len / vehicle_.maxSpeed;
    if (len > 1e-9) t += turnPenalty(std::remainder(std::atan2(dy, dx) - a->getYaw(), 2 * M_PI));
    return ob::Cost(t);
}

ob::Cost DrivingTimeObjective::motionCostHeuristic(const ob::State *s1, const ob::State *s2) const
{
    const auto *a = s1->as<ob::SE2StateSpace::StateType>();
    const auto *b = s2->as<ob::SE2StateSpace::StateType>();
    return ob::Cost(std::hypot(b->getX() - a->getX(), b->getY() - a->getY()) / vehicle_.maxSpeed);
}

std::vector<std::string> objectiveNames() { return {"length", "obstacle", "length+obstacle", "driving-time"}; }

ob::OptimizationObjectivePtr makeObjective(const std::string &name, const ob::SpaceInformationPtr &si,
                                           const FootprintChecker &checker, double delta)
{
    if (name == "length") return std::make_shared<ob::PathLengthOptimizationObjective>(si);
    if (name == "obstacle") return std::make_shared<ObstacleDistanceObjective>(si, checker.fieldPtr(), delta);
    if (name == "length+obstacle")
    {
        auto m = std::make_shared<ob::MultiOptimizationObjective>(si);
        m->addObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si), 1.0);
        m->addObjective(std::make_shared<ObstacleDistanceObjective>(si, checker.fieldPtr(), delta), 1.0);
        return m;
    }
    if (name == "driving-time") return std::make_shared<DrivingTimeObjective>(si, checker.vehicle());
    std::string list;
    for (const auto &n : objectiveNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown objective '" + name + "' (known: " + list + ")");
}

}  // namespace gridcar
