/// @file StretchCost.cpp
/// @brief The gear of a step and the cost of a stretch of a path (detail/StretchCost.h).
#include "gridcar/planners/search/detail/StretchCost.h"

#include "gridcar/core/Angles.h"

#include <cmath>

namespace gridcar::detail
{
/// The gear of the step from @p a to @p b: 1 forwards, -1 backwards (the displacement against
/// the mean heading of both poses), 0 for a repeated pose (samePosition()).
int stepGear(const Pose2 &a, const Pose2 &b)
{
    if (samePosition(a, b)) return 0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double along = dx * (std::cos(a.yaw) + std::cos(b.yaw)) + dy * (std::sin(a.yaw) + std::sin(b.yaw));
    return along < 0 ? -1 : 1;
}

/// The cost of driving poses[0..n] the way the search costs its motions: the path cut into
/// runs of one gear and one turning side, each a stepCost() with its length and turning (and
/// the cost layer), times the reverse penalty when driven backwards; plus the cusp penalty per
/// gear change, counting one against @p before (the gear the car arrives in, 0: none) and
/// @p after (the gear it leaves in). The number of gear changes goes to @p cusps.
double stretchCost(const std::vector<Pose2> &poses, int before, int after, const CarLatticeQuery &q,
                   const LatticeCostModel &cost, int &cusps)
{
    double total = 0;
    cusps = 0;
    int gear = before;
    std::size_t a = 0;  // start of the current run
    double len = 0, turn = 0;
    int runGear = 0, side = 0;
    std::vector<Pose2> samples;
    const auto close = [&](std::size_t b) {
        if (b <= a) return;
        samples.assign(poses.begin() + std::ptrdiff_t(a) + 1, poses.begin() + std::ptrdiff_t(b) + 1);
        double step = cost.stepCost(poses[a], samples, len, std::abs(turn)) +
                      q.mapCost(samples, len) * cost.costPerMetreOfPenalty();
        if (runGear < 0) step *= q.settings.reversePenalty;
        total += step;
    };
    for (std::size_t k = 0; k + 1 < poses.size(); ++k)
    {
        const Pose2 &p = poses[k], &r = poses[k + 1];
        int g = stepGear(p, r);
        if (g == 0) g = gear != 0 ? gear : 1;
        const double ds = std::hypot(r.x - p.x, r.y - p.y);
        const double dyaw = wrapAngle(r.yaw - p.yaw);
        const int s = std::abs(dyaw) <= 1e-6 * std::max(ds, 1e-9) + 1e-12 ? 0 : (dyaw > 0 ? 1 : -1);
        if (gear != 0 && g != gear) ++cusps;
        if (k > 0 && (g != runGear || (s != 0 && side != 0 && s != side)))
        {
            close(k);
            a = k;
            len = turn = 0;
            side = 0;
        }
        runGear = g;
        if (s != 0) side = s;
        len += ds;
        turn += dyaw;
        gear = g;
    }
    close(poses.size() - 1);
    if (after != 0 && gear != 0 && after != gear) ++cusps;
    return total + cusps * q.cuspPenalty;
}

}  // namespace gridcar::detail
