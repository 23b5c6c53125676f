/// @file GridFamily.cpp
/// @brief The grid lattice: the move cache over the collision model, one query from start
/// state to path, and the explored graph.
#include "gridcar/planners/GridFamily.h"

#include "gridcar/core/Angles.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gridcar
{
std::uint32_t GridNodes::parent(const GridFamily &f, std::uint32_t s) const { return f.dense().parent(s); }

double GridNodes::g(const GridFamily &f, std::uint32_t s) const { return f.dense().g(s); }

void GridNodes::forEachClosed(const GridFamily &f, const std::function<void(std::uint32_t)> &fn) const
{
    const std::size_t n = denseStates(f);
    if (n == 0) return;
    for (std::size_t s = 0; s < n; ++s)
        if (f.dense().closed(std::uint32_t(s))) fn(std::uint32_t(s));
}

std::string GridFamily::setup(std::shared_ptr<const GridSE2StateSpace> space, std::shared_ptr<CarCollision> collision,
                              std::unique_ptr<GridNodes> nodes, double maxMemoryMb)
{
    if (collision != collision_) forgetMoves();  // a new map or motion validator
    space_ = std::move(space);
    collision_ = std::move(collision);
    nodes_ = std::move(nodes);
    width_ = space_->width();
    height_ = space_->height();
    straightStep_ = space_->cellSize();
    diagStep_ = space_->cellSize() * std::sqrt(2.0);
    const std::size_t cells = std::size_t(width_) * std::size_t(height_);
    const std::size_t dense = nodes_->denseStates(*this);
    // the per-map arrays, refused when they alone would exceed max_memory_mb
    const double mb = (double(cells) * 8 + 16.0 * double(dense)) / (1024.0 * 1024.0);
    if (maxMemoryMb > 0 && mb > maxMemoryMb)
    {
        moveCache_.release();
        dense_.reset();
        return "the grid lattice of " + std::to_string(cells) + " cells needs " + std::to_string(long(mb)) +
               " MB of move cache and search records, more than max_memory_mb " + std::to_string(long(maxMemoryMb));
    }
    if (moveCache_.size() != cells * 8) moveCache_.assignZeros(cells * 8);
    if (dense == 0)
        dense_.reset();
    else if (!dense_ || dense_->size() != dense)
        dense_ = std::make_unique<SearchSpace>(dense);
    return "";
}

bool GridFamily::checkMoveUncached(int col, int row, int d) const
{
    const int nc = col + Moves::dcol[d], nr = row + Moves::drow[d];
    if (nc < 0 || nr < 0 || nc >= width_ || nr >= height_) return false;
    const OccupancyGrid *grid = collision_->cells();
    const double yaw = wrapYaw(Moves::yaw(d));
    if ((d & 1) && !allowCornerCutting_)
    {
        // both side cells of a diagonal must be free (Moving AI rule)
        if (grid)
        {
            if (grid->isBlocked(nc, row) || grid->isBlocked(col, nr)) return false;
        }
        else if (!collision_->poseFree({space_->cellCenterX(nc), space_->cellCenterY(row), yaw}) ||
                 !collision_->poseFree({space_->cellCenterX(col), space_->cellCenterY(nr), yaw}))
            return false;
    }
    if (grid && collision_->pointVehicle()) return !grid->isBlocked(nc, nr);  // plain grid: the target cell
    return collision_->segmentFree({space_->cellCenterX(col), space_->cellCenterY(row), yaw},
                                   {space_->cellCenterX(nc), space_->cellCenterY(nr), yaw});
}

bool GridFamily::fillMoveCache(int col, int row, int d) const
{
    std::uint8_t &c = moveCache_[(std::size_t(row) * width_ + col) * 8 + d];
    c = checkMoveUncached(col, row, d) ? 1 : 2;
    return c == 1;
}

double GridFamily::octile(int c0, int r0, int c1, int r1) const
{
    const int dx = std::abs(c1 - c0), dy = std::abs(r1 - r0);
    return straightStep_ * std::max(dx, dy) + (diagStep_ - straightStep_) * std::min(dx, dy);
}

bool GridFamily::isGoal(int col, int row, int dir) const
{
    if (query_.goalKnown && col == query_.goalCol && row == query_.goalRow &&
        (dir < 0 || ((query_.goalDirs >> dir) & 1u)))
        return true;
    return query_.regionTest &&
           goal_->satisfied({space_->cellCenterX(col), space_->cellCenterY(row), dir >= 0 ? Moves::yaw(dir) : 0.0});
}

double GridFamily::closeness(int col, int row, int dir) const
{
    if (!query_.goalKnown)
        return goal_->distance({space_->cellCenterX(col), space_->cellCenterY(row), dir >= 0 ? Moves::yaw(dir) : 0.0});
    const double dx = space_->cellCenterX(col) - goal_->pose.x, dy = space_->cellCenterY(row) - goal_->pose.y;
    return dx * dx + dy * dy;
}

void GridFamily::readGoal(const GoalTarget &goal)
{
    goal_ = &goal;
    if (goal.kind == GoalTarget::Kind::Region)
    {
        query_.regionTest = true;  // nothing to aim at: the region's own test
        return;
    }
    const LatticeState gl = space_->toLattice(goal.pose.x, goal.pose.y, goal.pose.yaw);
    query_.goalKnown = space_->inBounds(gl);
    query_.goalCol = gl.col;
    query_.goalRow = gl.row;
    switch (goal.kind)
    {
        case GoalTarget::Kind::State:
            if (goal.yawTolerance == 0.0) query_.goalDirs = std::uint8_t(1u << Moves::fromYaw(goal.pose.yaw));
            break;
        case GoalTarget::Kind::Position:
        {
            if (goal.yawTolerance >= 0)
            {
                // within the tolerance, or the direction nearest the goal's yaw
                query_.goalDirs = std::uint8_t(1u << Moves::fromYaw(goal.pose.yaw));
                for (int d = 0; d < 8; ++d)
                    if (std::abs(wrapAngle(Moves::yaw(d) - goal.pose.yaw)) <= goal.yawTolerance)
                        query_.goalDirs |= std::uint8_t(1u << d);
            }
            // another cell's centre is at least half a cell from the position
            query_.regionTest = goal.positionTolerance >= 0.5 * straightStep_;
            // a satisfying centre lies within the tolerance plus half a cell's diagonal of the
            // target cell's: the octile and Euclidean bounds shrink by at most sqrt 2 times that
            if (query_.regionTest) query_.goalSlack = std::sqrt(2.0) * goal.positionTolerance + straightStep_;
            break;
        }
        default:  // a sampleable region: its sample's cell, and the region's own test
            query_.regionTest = true;
    }
    if (!query_.goalKnown) query_.regionTest = true;
}

Pose2 GridFamily::goalPose(const GoalTarget &goal, double arrivalYaw) const
{
    if (goal.kind != GoalTarget::Kind::Position) return goal.pose;
    Pose2 p{goal.pose.x, goal.pose.y, arrivalYaw};
    if (goal.yawTolerance >= 0)
    {
        if (std::abs(wrapAngle(arrivalYaw - goal.pose.yaw)) > goal.yawTolerance) p.yaw = goal.pose.yaw;
        return p;  // the goal's yaw was checked free (GoalAdapter::read())
    }
    // a free heading: the arrival's, else the free one of 72 nearest it (the vehicle fits at one)
    for (int k = 0; k <= 36 && !collision_->poseFree(p); ++k)
        for (int side : {1, -1})
        {
            p.yaw = wrapYaw(arrivalYaw + side * k * M_PI / 36);
            if (collision_->poseFree(p)) break;
        }
    return p;
}

bool GridFamily::lastLegFree(const Pose2 &from, const Pose2 &to) const
{
    // along the leg at its own heading (both ends included), as the lattice's moves are
    // checked; the goal pose itself at its yaw (GoalAdapter::read() and goalPose() chose it free)
    const double dx = to.x - from.x, dy = to.y - from.y;
    if (std::hypot(dx, dy) <= 1e-9) return collision_->poseFree(to);
    const double h = std::atan2(dy, dx);
    return collision_->segmentFree({from.x, from.y, h}, {to.x, to.y, h}) && collision_->poseFree(to);
}

FamilyRun GridFamily::solve(const ompl::base::SpaceInformationPtr &si, const ompl::base::State *start,
                            bool freeStartHeading, const GoalTarget &goal, const std::function<bool()> &cancelled,
                            std::atomic<std::uint64_t> *progress)
{
    FamilyRun run;
    const LatticeState sl = space_->toLattice(start);
    if (!space_->inBounds(sl))
    {
        run.end.noPath = ompl::base::PlannerStatus::INVALID_START;
        return run;
    }
    query_ = GridQuery();
    query_.startCol = sl.col;
    query_.startRow = sl.row;
    query_.startDir = freeStartHeading ? -1 : Moves::fromYaw(start->as<ompl::base::SE2StateSpace::StateType>()->getYaw());
    readGoal(goal);

    const std::vector<std::uint32_t> starts = nodes_->starts(*this);
    const auto t0 = std::chrono::steady_clock::now();
    const SearchResult res = nodes_->search(*this, starts, cancelled, progress);
    run.searchSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.expanded = res.expanded;
    run.end.cancelled = res.outcome == SearchOutcome::Cancelled;
    const std::uint32_t end = res.outcome == SearchOutcome::Found ? res.goal : res.closest;
    if (end == SearchSpace::kNoParent) return run;  // nothing expanded: no path
    std::vector<std::uint32_t> states;
    for (std::uint32_t s = end; s != SearchSpace::kNoParent; s = nodes_->parent(*this, s)) states.push_back(s);
    std::reverse(states.begin(), states.end());
    run.cost = nodes_->g(*this, end);

    auto path = std::make_shared<ompl::geometric::PathGeometric>(si);
    path->append(start);
    Pose2 last = toPose(start);
    ompl::base::State *tmp = si->allocState();
    for (std::size_t i = 1; i < states.size(); ++i)
    {
        int c, r, d, pc, pr, pd;
        nodes_->decode(*this, states[i], c, r, d);
        nodes_->decode(*this, states[i - 1], pc, pr, pd);
        // the heading of the move into the cell (rows grow downwards)
        last = {space_->cellCenterX(c), space_->cellCenterY(r), std::atan2(double(pr - r), double(c - pc))};
        setPose(tmp, last);
        path->append(tmp);
    }
    run.end.reached = res.outcome == SearchOutcome::Found;
    if (run.end.reached)
    {
        int c, r, d;
        nodes_->decode(*this, end, c, r, d);
        const bool inTarget = query_.goalKnown && c == query_.goalCol && r == query_.goalRow;
        if (goal.state)
        {
            if (states.size() > 1 || !si->equalStates(start, goal.state))
            {
                // the last leg, from the cell's centre to the goal pose, checked as a move is
                run.end.reached = lastLegFree(last, goal.pose);
                if (run.end.reached) path->append(goal.state);
            }
        }
        else if (inTarget && !goal.satisfied(last))
        {
            const Pose2 end = goalPose(goal, last.yaw);
            if (lastLegFree(last, end))
            {
                last = end;
                setPose(tmp, last);
                path->append(tmp);
            }
        }
        // a region's sample may lie outside it: then the path only comes near
        if (!goal.state) run.end.reached = goal.satisfied(last);
    }
    si->freeState(tmp);
    run.end.path = path;
    return run;
}

void GridFamily::plannerData(ompl::base::PlannerData &data, PlannerDataStates &states) const
{
    if (!nodes_) return;
    auto stateOf = [&](std::uint32_t s) {
        int c, r, d;
        nodes_->decode(*this, s, c, r, d);
        return states.at(s, {space_->cellCenterX(c), space_->cellCenterY(r), d >= 0 ? Moves::yaw(d) : 0.0});
    };
    nodes_->forEachClosed(*this, [&](std::uint32_t s) {
        const std::uint32_t p = nodes_->parent(*this, s);
        if (p == SearchSpace::kNoParent)
            data.addStartVertex(ompl::base::PlannerDataVertex(stateOf(s)));
        else
            data.addEdge(ompl::base::PlannerDataVertex(stateOf(p)), ompl::base::PlannerDataVertex(stateOf(s)));
    });
}

}  // namespace gridcar
