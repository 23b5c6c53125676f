/// @file CarGoal.cpp
/// @brief The car lattice's goal manager: the analytic expansion's end headings.
#include "gridcar/planners/search/CarGoal.h"

#include "gridcar/core/Angles.h"
#include "gridcar/planners/search/CarLattice.h"

#include <cmath>

namespace gridcar
{
std::vector<double> CarGoal::endYaws(const Pose2 &from, const CarLattice &lattice, double frameYaw) const
{
    const Pose2 &g = t_.goal;
    std::vector<double> yaws;
    if (t_.goalYawTolerance < 0)
    {
        yaws.push_back(std::atan2(g.y - from.y, g.x - from.x));
        for (int h = 0; h < lattice.neighbourCount(); ++h) yaws.push_back(wrapYaw(frameYaw + lattice.stepYaw(h)));
    }
    else
    {
        yaws.push_back(g.yaw);
        if (t_.goalYawTolerance > 0)
            for (double d : {-t_.goalYawTolerance, t_.goalYawTolerance}) yaws.push_back(wrapYaw(g.yaw + d));
    }
    return yaws;
}

}  // namespace gridcar
