#pragma once
/// @file Goals.h
/// @brief A goal over a position with a free or bounded heading, for any OMPL planner.

#include <ompl/base/goals/GoalSampleableRegion.h>

namespace gridcar
{
/**
 * @brief Goal region: within @p positionTolerance metres of (x, y), at any heading (yaw
 * tolerance < 0) or within yawTolerance radians of @p yaw.
 *
 * distanceGoal() = position distance, plus the heading's excess over the tolerance (radians,
 * counted as metres), for ranking states; the threshold is the position tolerance, and
 * isSatisfied() tests the position and the heading each within its own tolerance.
 * sampleGoal() gives the exact position at the goal yaw, or with a free
 * heading the first of 72 yaws (5 degrees apart, from 0) at which the state is valid, so
 * OMPL's sampling planners can aim at it. The car-lattice planners reach the exact position
 * with a Dubins curve (search/CarLatticeSearch.h).
 */
class PositionGoal : public ompl::base::GoalSampleableRegion
{
public:
    PositionGoal(const ompl::base::SpaceInformationPtr &si, double x, double y, double positionTolerance,
                 double yaw = 0.0, double yawTolerance = -1.0);

    double distanceGoal(const ompl::base::State *st) const override;
    /// Within the position tolerance and within the yaw tolerance, each on its own;
    /// @p distance (when given) is distanceGoal().
    bool isSatisfied(const ompl::base::State *st, double *distance) const override;
    bool isSatisfied(const ompl::base::State *st) const override { return isSatisfied(st, nullptr); }
    void sampleGoal(ompl::base::State *st) const override;
    unsigned int maxSampleCount() const override { return 1; }

    double x() const { return x_; }
    double y() const { return y_; }
    double yaw() const { return yaw_; }
    double yawTolerance() const { return yawTol_; }
    bool freeHeading() const { return yawTol_ < 0; }
    double positionTolerance() const { return getThreshold(); }

private:
    double x_, y_, yaw_, yawTol_;
};

}  // namespace gridcar
