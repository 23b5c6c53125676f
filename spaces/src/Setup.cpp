#include "gridcar/spaces/Setup.h"

#include "gridcar/core/Angles.h"

#include "gridcar/spaces/CurveSpaces.h"
#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/ScopedState.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
    s.kind = options.space;
    ompl::base::StateSpacePtr planSpace = s.space;
    const double radius = vehicle.minTurningRadius();
    if (s.kind != SpaceKind::SE2)
    {
        if (!(radius > 0) || !std::isfinite(radius))
            throw std::invalid_argument("a " + spaceKindName(s.kind) + " space needs a vehicle with a turning radius (" +
                                        vehicle.name + " has none)");
        std::shared_ptr<ompl::base::SE2StateSpace> car;
        // OMPL's car spaces with gridcar's curve code (OMPL 1.5.2's Dubins code can abort)
        if (s.kind == SpaceKind::Dubins) car = std::make_shared<DubinsSpace>(radius);
        else car = std::make_shared<ReedsSheppSpace>(radius);
        car->setBounds(s.space->getBounds());
        planSpace = car;
    }
    s.ss = std::make_shared<ompl::geometric::SimpleSetup>(planSpace);
    const auto &si = s.ss->getSpaceInformation();
    si->setStateValidityChecker(std::make_shared<FootprintValidityChecker>(si, s.checker));
    const double step = options.sweepFraction * grid->resolution();
    if (s.kind == SpaceKind::SE2)
        si->setMotionValidator(std::make_shared<FootprintMotionValidator>(si, s.checker));
    else
        si->setMotionValidator(std::make_shared<CurveMotionValidator>(si, s.checker, radius, step));
    si->setStateValidityCheckingResolution(0.5 * grid->resolution() / planSpace->getMaximumExtent());
    return s;
}

void GridSetup::setStartAndGoal(const Pose2 &start, const Pose2 &goal, bool freeGoalHeading, const GoalTolerance &tolerance) const
{
    if (!std::isfinite(tolerance.position) || tolerance.position < 0 || !std::isfinite(tolerance.yaw) || tolerance.yaw < 0)
        throw std::invalid_argument("goal tolerance (" + std::to_string(tolerance.position) + " m, " + std::to_string(tolerance.yaw) +
                                    " rad) must be finite and >= 0");
    ompl::base::ScopedState<ompl::base::SE2StateSpace> a(ss->getStateSpace()), b(ss->getStateSpace());
    a->setXY(start.x, start.y);
    a->setYaw(wrapYaw(start.yaw));  // OMPL's SO(2) bounds are [-pi, pi): a yaw of +pi is out of them
    if (freeGoalHeading || !tolerance.exact())
    {
        ss->clearStartStates();
        ss->addStartState(a);
        const double yawTol = freeGoalHeading ? -1.0 : std::min(tolerance.yaw, M_PI);
        ss->setGoal(std::make_shared<PositionGoal>(ss->getSpaceInformation(), goal.x, goal.y, std::max(1e-6, tolerance.position),
                                                   wrapYaw(goal.yaw), yawTol));
        return;
    }
    b->setXY(goal.x, goal.y);
    b->setYaw(wrapYaw(goal.yaw));
    ss->setStartAndGoalStates(a, b);
}

}  // namespace gridcar
