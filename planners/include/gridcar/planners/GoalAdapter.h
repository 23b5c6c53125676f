#pragma once
/// @file GoalAdapter.h
/// @brief One reading of OMPL goals (GoalState, gridcar's PositionGoal, sampleable and other
/// regions) for every search family.

#include "gridcar/core/Pose2.h"
#include "gridcar/planners/search/CarCollision.h"

#include <ompl/base/Goal.h>
#include <ompl/base/PlannerStatus.h>
#include <ompl/base/SpaceInformation.h>

#include <functional>
#include <string>

namespace gridcar
{
/// An OMPL goal as a search reads it (GoalAdapter::read()).
struct GoalTarget
{
    enum class Kind
    {
        State,          ///< ompl::base::GoalState: one pose (its heading when asked to match)
        Position,       ///< gridcar::PositionGoal: a position, a heading and its tolerance
        SampledRegion,  ///< a GoalSampleableRegion: a sample to aim at, the region decides
        Region          ///< any other GoalRegion: nothing to aim at, the region decides
    };
    Kind kind{Kind::Region};
    Pose2 pose;                 ///< the pose to aim at (every kind but Region)
    double yawTolerance{-1.0};  ///< rad: < 0 any heading, 0 exactly pose.yaw, > 0 within it
    /// The GoalState's state (Kind::State), appended to a path that reaches its cell.
    const ompl::base::State *state{nullptr};
    double positionTolerance{0.0};  ///< m: a PositionGoal's (Kind::Position)
    /// The goal's own test at a pose (isSatisfied()), for every kind.
    std::function<bool(const Pose2 &)> satisfied;
    /// The goal's own distance from a pose (isSatisfied()'s distance), for every kind.
    std::function<double(const Pose2 &)> distance;
};

/**
 * @brief Reads the problem's goal into a GoalTarget and checks that it can be reached at all:
 * a GoalState on the map with the vehicle free there (at its heading when the heading must
 * match, else at some heading when @p anyHeading allows), a PositionGoal where the vehicle
 * fits at an allowed heading; regions are searched as they are.
 */
class GoalAdapter
{
public:
    explicit GoalAdapter(ompl::base::SpaceInformationPtr si);
    ~GoalAdapter();
    GoalAdapter(const GoalAdapter &) = delete;
    GoalAdapter &operator=(const GoalAdapter &) = delete;

    /// @p matchHeading: a GoalState's heading must be matched. @p anyHeading: without
    /// matchHeading, a GoalState counts as free when the vehicle fits at any of 72 headings
    /// there (a search that arrives at its own heading); otherwise at the state's heading.
    /// Returns UNKNOWN when the goal can be searched, else INVALID_GOAL or
    /// UNRECOGNIZED_GOAL_TYPE (the reason logged under @p name).
    ompl::base::PlannerStatus read(const ompl::base::Goal *goal, bool matchHeading, bool anyHeading,
                                   const CarCollision &collision, const std::string &name, GoalTarget &out);

private:
    ompl::base::SpaceInformationPtr si_;
    ompl::base::State *scratch_;
};

}  // namespace gridcar
