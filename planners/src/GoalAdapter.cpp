/// @file GoalAdapter.cpp
/// @brief OMPL goals read once for both search families.
#include "gridcar/planners/GoalAdapter.h"

#include "gridcar/spaces/Goals.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <cmath>

namespace gridcar
{
GoalAdapter::GoalAdapter(ompl::base::SpaceInformationPtr si) : si_(std::move(si)), scratch_(si_->allocState()) {}

GoalAdapter::~GoalAdapter() { si_->freeState(scratch_); }

ompl::base::PlannerStatus GoalAdapter::read(const ompl::base::Goal *goal, bool matchHeading, bool anyHeading,
                                            const CarCollision &collision, const std::string &name, GoalTarget &out)
{
    using ompl::base::PlannerStatus;
    out = GoalTarget();
    auto invalid = [&](const char *why) {
        OMPL_ERROR("%s: %s", name.c_str(), why);
        return PlannerStatus(PlannerStatus::INVALID_GOAL);
    };
    const auto *region = dynamic_cast<const ompl::base::GoalRegion *>(goal);
    if (!region)
    {
        OMPL_ERROR("%s: the goal must be a GoalRegion (e.g. GoalState, PositionGoal)", name.c_str());
        return PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    }
    out.satisfied = [this, region](const Pose2 &p) {
        setPose(scratch_, p);
        return region->isSatisfied(scratch_);
    };
    out.distance = [this, region](const Pose2 &p) {
        setPose(scratch_, p);
        double d = 0.0;
        region->isSatisfied(scratch_, &d);
        return d;
    };
    if (const auto *pg = dynamic_cast<const PositionGoal *>(goal))
    {
        out.kind = GoalTarget::Kind::Position;
        out.pose = {pg->x(), pg->y(), pg->yaw()};
        out.yawTolerance = pg->yawTolerance();
        out.positionTolerance = pg->positionTolerance();
        const auto fits = [&](const Pose2 &p) {
            if (pg->freeHeading()) return collision.fitsAtSomeHeading(p.x, p.y, 72);
            if (collision.poseFree(p)) return true;
            for (double d : {-pg->yawTolerance(), pg->yawTolerance()})  // either end of a heading tolerance
                if (d != 0.0 && collision.poseFree({p.x, p.y, p.yaw + d})) return true;
            return false;
        };
        if (fits(out.pose)) return PlannerStatus::UNKNOWN;
        // the goal position blocked but a tolerance round it: aim at the nearest position within
        // it where the vehicle fits (at most 60 rings, 5 cm apart or more, 5 degrees round), the
        // region deciding
        const double tol = out.positionTolerance, step = std::max(0.05, tol / 60);
        for (double r = step; r <= tol + 1e-9; r += step)
            for (int k = 0; k < 72; ++k)
            {
                const Pose2 p{out.pose.x + r * std::cos(k * M_PI / 36), out.pose.y + r * std::sin(k * M_PI / 36), out.pose.yaw};
                if (fits(p)) return out.pose = p, PlannerStatus(PlannerStatus::UNKNOWN);
            }
        return invalid(tol > 0 ? "the vehicle fits at no allowed heading within the goal's position tolerance"
                               : "the vehicle fits at no allowed heading at the goal position");
    }
    if (const auto *gs = dynamic_cast<const ompl::base::GoalState *>(goal))
    {
        out.kind = GoalTarget::Kind::State;
        out.state = gs->getState();
        out.pose = toPose(out.state);
        out.yawTolerance = matchHeading ? 0.0 : -1.0;
        if (!si_->satisfiesBounds(out.state)) return invalid("goal state is outside the space's bounds (off the map, or a yaw outside [-pi, pi): OMPL's SO(2) excludes +pi)");
        const bool atItsHeading = matchHeading || !anyHeading;
        const bool ok = atItsHeading ? collision.poseFree(out.pose) : collision.fitsAtSomeHeading(out.pose.x, out.pose.y, 72);
        return ok ? PlannerStatus(PlannerStatus::UNKNOWN)
                  : invalid(atItsHeading ? "goal state is in collision" : "the vehicle fits at no heading at the goal");
    }
    const auto *gsr = dynamic_cast<const ompl::base::GoalSampleableRegion *>(goal);
    if (gsr && gsr->canSample())
    {
        gsr->sampleGoal(scratch_);  // a target for the heuristic; the region itself decides
        out.kind = GoalTarget::Kind::SampledRegion;
        out.pose = toPose(scratch_);
        return PlannerStatus::UNKNOWN;
    }
    out.kind = GoalTarget::Kind::Region;  // nothing to aim at: a node satisfying it ends the search
    return PlannerStatus::UNKNOWN;
}

}  // namespace gridcar
