#pragma once
/// @file CarHeuristics.h
/// @brief The car lattice's lower bounds on the cost to go, as separate parts: the position
/// bounds combined by max, the turn bound added (it bounds another term of the cost).

#include "gridcar/core/Angles.h"
#include "gridcar/core/Pose2.h"
#include "gridcar/curves/CarCurves.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridcar
{
/// Straight-line distance to the goal position x the cost model's least cost per metre.
/// Admissible for every cost model whose step cost is at least minCostPerMetre() x the step's
/// length (LatticeCostModel's contract): no path to the goal is shorter than the chord.
struct EuclideanBound
{
    Pose2 goal;
    double perMetre{1.0};
    double distance(const Pose2 &p) const { return std::hypot(goal.x - p.x, goal.y - p.y); }
    double operator()(const Pose2 &p) const { return perMetre * distance(p); }
};

/// The 2D obstacle-aware distance (ObstacleHeuristic: Dijkstra over the lattice's vectors
/// from the nodes round the goal, edges weighted by the cost model's nodeWeight()), divided by
/// the largest ratio of that graph's open-space distance to a primitive's length and less the
/// seed radius x the least cost per metre. Admissible when the collision model's tests are
/// relaxations (CarCollision::relaxed(): a node the 2D graph drops is one no pose of the car
/// can occupy): every path of primitives then maps to a 2D walk no longer than ratio x its
/// length. With an application's checker (not a relaxation) it is an estimate: the path is
/// near-optimal rather than bounded. Infinity where the 2D graph cannot reach the goal.
struct ObstacleBound
{
    double ratio{1.0};
    double seedCost{0.0};  ///< seed radius x least cost per metre
    /// Cost per metre of the 2D distance: the cost model's least (minCostPerMetre()) when the
    /// 2D search counts metres, 1 when it weighs its edges in the model's units already
    /// (LatticeCostModel::weighted()).
    double perMetre{1.0};
    /// @p graphDistance: the 2D distance at the node (< 0: not computed, infinity: unreachable).
    double operator()(double graphDistance) const
    {
        if (graphDistance == std::numeric_limits<double>::infinity()) return graphDistance;
        return graphDistance < 0 ? 0.0 : graphDistance * perMetre / ratio - seedCost;
    }
};

/// The turning a path from a pose to the goal position needs at least x the cost model's least
/// cost per radian of turning (minTurnCostPerRad(): corner A*'s weights; 0 for the others).
/// Admissible for cost models that charge turning on top of length: somewhere the path's
/// tangent is parallel to the chord (Rolle), so the body turns by at least the smaller of the
/// angles between its heading and the chord's two directions, driving forwards or backwards.
struct TurnBound
{
    Pose2 goal;
    double perRad{0.0};
    /// The least turn (rad) from @p p.
    double angle(const Pose2 &p) const
    {
        const double dx = goal.x - p.x, dy = goal.y - p.y;
        if (dx * dx + dy * dy < 1e-12) return 0.0;
        const double a = std::abs(wrapAngle(std::atan2(dy, dx) - p.yaw));
        return std::min(a, M_PI - a);
    }
    double operator()(const Pose2 &p) const { return perRad <= 0 ? 0.0 : perRad * angle(p); }
};

/// The obstacle-free non-holonomic bound of Hybrid A* planners: the length of the shortest
/// Reeds-Shepp curve (a primitive set that reverses) or Dubins curve (forward only) from the pose
/// to the goal pose at the primitives' turning radius, x the least cost per metre. Admissible for
/// a goal heading that must be matched: every path of primitives is a curve of curvature at most
/// 1 / radius from the pose to the goal pose, so it is no shorter than the shortest one, and
/// reversed length and gear changes cost at least their length. Inactive (0) without a goal
/// heading, or beyond @p within metres of the goal (where it is close to the straight line).
struct CurveBound
{
    Pose2 goal;
    double radius{0.0};  ///< 0: inactive
    bool reverse{false};
    double perMetre{1.0};
    double within{0.0};
    double operator()(const Pose2 &p) const
    {
        if (radius <= 0 || std::hypot(goal.x - p.x, goal.y - p.y) > within) return 0.0;
        const CarCurve c = reverse ? reedsSheppCurve(p, goal, radius) : dubinsCurve(p, goal, radius);
        return c.empty() ? 0.0 : perMetre * c.length;
    }
};

/// h = weight x max(Euclidean, obstacle, curve) + weight x turn: the position bounds bound the
/// same term (length-like cost) and combine by max; the turn bound bounds the turning term and
/// adds. @p weight >= 1 inflates it (a bounded-suboptimal search).
struct CarHeuristic
{
    EuclideanBound euclidean;
    ObstacleBound obstacle;
    CurveBound curve;
    TurnBound turn;
    bool useObstacle{true};
    double weight{1.0};
    /// The position part at node pose @p p with 2D distance @p graphDistance; @p other: a
    /// further lower bound of the same term (a CurveTableBound's, in the cost model's units).
    double position(const Pose2 &p, double graphDistance, double other = 0.0) const
    {
        if (!useObstacle) return weight * std::max({euclidean.perMetre * euclidean.distance(p), curve(p), other});
        const double e = euclidean(p);
        const double g = obstacle(graphDistance);
        if (g == std::numeric_limits<double>::infinity()) return g;
        return weight * std::max({e, g, curve(p), other});
    }
    double turning(const Pose2 &p) const { return turn.perRad <= 0 ? 0.0 : weight * turn.perRad * turn.angle(p); }
};

}  // namespace gridcar
