#include "gridcar/core/Cusps.h"

#include <cmath>

namespace gridcar
{
std::vector<PathPiece> splitAtCusps(const std::vector<Pose2> &path)
{
    std::vector<Pose2> pts;
    for (const Pose2 &p : path)
        if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
    std::vector<PathPiece> out;
    if (pts.empty()) return out;
    out.push_back({{pts[0]}, false});
    int dir = 0;  // 0 unknown, +1 forward, -1 backward
    double c0 = std::cos(pts[0].yaw), s0 = std::sin(pts[0].yaw);  // the previous pose's (each pose's once)
    for (std::size_t i = 1; i < pts.size(); ++i)
    {
        const double c1 = std::cos(pts[i].yaw), s1 = std::sin(pts[i].yaw);
        const double dx = pts[i].x - pts[i - 1].x, dy = pts[i].y - pts[i - 1].y;
        const double a = dx * c0 + dy * s0;
        const double b = dx * c1 + dy * s1;
        c0 = c1;
        s0 = s1;
        const int step = a > 0 && b > 0 ? 1 : a < 0 && b < 0 ? -1 : dir;
        if (dir != 0 && step != 0 && step != dir)
            out.push_back({{pts[i - 1]}, step < 0});  // a cusp at pts[i - 1]
        else if (dir == 0 && step != 0)
            out.back().backward = step < 0;
        if (step != 0) dir = step;
        out.back().poses.push_back(pts[i]);
    }
    return out;
}

bool drivesBackwards(const std::vector<Pose2> &path)
{
    for (const PathPiece &p : splitAtCusps(path))
        if (p.backward) return true;
    return false;
}

}  // namespace gridcar
