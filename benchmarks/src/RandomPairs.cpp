/// @file RandomPairs.cpp
/// @brief randomPairs(): seeded start / goal pairs for the benchmark programs; loadAreaMap();
/// crossingPedestrian().
#include "gridcar/bench/RandomPairs.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/vehicle/Dynamics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <random>

namespace gridcar
{
std::shared_ptr<const OccupancyGrid> loadAreaMap(const std::string &shared, const BenchArea &area)
{
    if (area.map == "embedded") return std::make_shared<const OccupancyGrid>(generateCampus(CampusParams()));
    const std::string file = shared + "/" + area.map;
    if (!std::filesystem::exists(file))
    {
        std::printf("\n%s: %s is absent, skipped\n", area.name.c_str(), file.c_str());
        return nullptr;
    }
    return std::make_shared<const OccupancyGrid>(loadMap(file));
}

std::vector<std::pair<Pose2, Pose2>> randomPairs(const FootprintChecker &fc, int n, unsigned seed, double lo, double hi)
{
    const OccupancyGrid &g = fc.grid();
    const DistanceField &f = fc.field();
    const int W = g.width(), H = g.height();
    const double h = g.resolution() * std::sqrt(2.0);
    std::vector<int> label(std::size_t(W) * H, -1);
    int labels = 0;
    for (int start = 0; start < W * H; ++start)
    {
        if (label[std::size_t(start)] >= 0 || f.cellDistance(start % W, start / W) <= fc.vehicle().width / 2) continue;
        std::deque<int> q{start};
        label[std::size_t(start)] = labels;
        while (!q.empty())
        {
            const int k = q.front();
            q.pop_front();
            const int c = k % W, r = k / W;
            const int nb[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
            for (const auto &p : nb)
            {
                if (p[0] < 0 || p[1] < 0 || p[0] >= W || p[1] >= H) continue;
                const int m = p[1] * W + p[0];
                if (label[std::size_t(m)] < 0 && f.cellDistance(p[0], p[1]) > fc.vehicle().width / 2)
                {
                    label[std::size_t(m)] = labels;
                    q.push_back(m);
                }
            }
        }
        ++labels;
    }
    std::vector<int> ok;
    const double rOut = fc.vehicle().circumscribedRadius();
    for (int k = 0; k < W * H; ++k)
        if (label[std::size_t(k)] >= 0 && f.cellDistance(k % W, k / W) - h > rOut) ok.push_back(k);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::size_t> pick(0, ok.empty() ? 0 : ok.size() - 1);
    std::vector<std::pair<Pose2, Pose2>> out;
    for (int tries = 0; int(out.size()) < n && tries < 1000000 && !ok.empty(); ++tries)
    {
        const int a = ok[pick(rng)], b = ok[pick(rng)];
        if (label[std::size_t(a)] != label[std::size_t(b)]) continue;
        const Pose2 s{g.cellCenterX(a % W), g.cellCenterY(a / W), 0.0}, t{g.cellCenterX(b % W), g.cellCenterY(b / W), 0.0};
        const double d = std::hypot(t.x - s.x, t.y - s.y);
        if (d < lo || d > hi) continue;
        out.push_back({s, t});
    }
    return out;
}

Pose2 withFittingYaw(const FootprintChecker &fc, Pose2 p)
{
    double yaw = p.yaw;
    if (fc.fitsAtSomeHeading(p.x, p.y, 72, &yaw)) p.yaw = yaw;
    return p;
}

MovingObstacle crossingPedestrian(const std::vector<Pose2> &path, const VehicleParams &v, double fraction)
{
    MovingObstacle o;
    o.name = "pedestrian";
    std::vector<double> cum{0.0};
    for (std::size_t i = 1; i < path.size(); ++i)
        cum.push_back(cum.back() + std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y));
    if (path.size() < 2 || cum.back() < 1e-6) return o;
    const std::size_t mid = std::size_t(std::lower_bound(cum.begin(), cum.end(), fraction * cum.back()) - cum.begin());
    const std::size_t a = std::min(mid, path.size() - 2);
    const double hx = path[a + 1].x - path[a].x, hy = path[a + 1].y - path[a].y, hn = std::hypot(hx, hy);
    const double nx = -hy / hn, ny = hx / hn;
    const double scale = std::clamp(v.length / 4.5, 0.1, 1.0);
    o.radius = 0.3 * scale;
    o.speed = 1.2 * scale;
    const double side = 3.0 * scale + v.width, far = side + 8.0 * o.speed;
    o.waypoints = {{path[mid].x - far * nx, path[mid].y - far * ny}, {path[mid].x + side * nx, path[mid].y + side * ny}};
    std::vector<Pose2> firstHalf(path.begin(), path.begin() + std::ptrdiff_t(mid + 1));
    const double arrive = firstHalf.size() > 1 ? drivingTime(firstHalf, v) : 0.0;
    o.startTime = arrive - far / o.speed;  // negative: already walking at the start
    return o;
}

}  // namespace gridcar
