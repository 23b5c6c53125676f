/// @file RandomPairs.cpp
/// @brief randomPairs(): seeded start / goal pairs for the benchmark programs; loadAreaMap().
#include "gridcar/bench/RandomPairs.h"

#include "gridcar/map/CampusGenerator.h"
#include "gridcar/map/MapIO.h"

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

}  // namespace gridcar
