#include "gridcar/spaces/Setup.h"

#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/ScopedState.h>

namespace gridcar
{
GridSetup makeGridSetup(std::shared_ptr<const OccupancyGrid> grid, const VehicleParams &vehicle,
                        const SetupOptions &options, std::shared_ptr<const DistanceField> field)
{
    if (!grid) throw std::invalid_argument("makeGridSetup needs a grid");
    GridSetup s;
    s.grid = grid;
    s.field = field ? std::move(field) : std::make_shared<const DistanceField>(*grid);
    s.checker = std::make_shared<FootprintChecker>(s.grid, s.field, vehicle);
    s.checker->setSweepFraction(options.sweepFraction);
    s.space = std::make_shared<GridSE2StateSpace>(*grid, options.headingBins);
    s.ss = std::make_shared<ompl::geometric::SimpleSetup>(s.space);
    const auto &si = s.ss->getSpaceInformation();
    si->setStateValidityChecker(std::make_shared<FootprintValidityChecker>(si, s.checker));
    si->setMotionValidator(std::make_shared<FootprintMotionValidator>(si, s.checker));
    si->setStateValidityCheckingResolution(0.5 * grid->resolution() / s.space->getMaximumExtent());
    return s;
}

void GridSetup::setStartAndGoal(const Pose2 &start, const Pose2 &goal) const
{
    ompl::base::ScopedState<ompl::base::SE2StateSpace> a(space), b(space);
    a->setXY(start.x, start.y);
    a->setYaw(start.yaw);
    b->setXY(goal.x, goal.y);
    b->setYaw(goal.yaw);
    ss->setStartAndGoalStates(a, b);
}

}  // namespace gridcar
