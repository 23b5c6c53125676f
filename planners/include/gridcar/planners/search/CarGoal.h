#pragma once
/// @file CarGoal.h
/// @brief The goal manager of the car lattice: what a query's goal asks of the search (which
/// states are in it, which is nearest it, whether the analytic expansion aims at it and at
/// which end headings, whether its heading is to be met), decided in one place.

#include "gridcar/core/Pose2.h"

#include <functional>
#include <vector>

namespace gridcar
{
class CarLattice;

/// A car-lattice query's goal: the fields of CarLatticeQuery that describe it (its base).
struct CarGoalTerms
{
    /// The goal position the heuristic aims at and the analytic expansion reaches exactly
    /// (when shoot), with the heading to meet (see goalYawTolerance).
    Pose2 goal;
    bool shoot{true};
    double goalYawTolerance{-1.0};  ///< rad: < 0 any heading, 0 exactly goal.yaw, > 0 within it
    /// m: how far from `goal` inGoal accepts a position (a PositionGoal's tolerance; 0 for a
    /// GoalState, < 0 for a region that is no disc round `goal`)
    double goalPositionTolerance{-1.0};
    /// Goal test of a lattice state (empty: only the analytic expansion reaches the goal).
    std::function<bool(const Pose2 &)> inGoal;
    /// False when `goal` is no target at all (a goal region that cannot be sampled): no
    /// heuristic then (Dijkstra order), and no shot.
    bool aim{true};
    /// Without aim: the goal's own distance from a pose, so that an approximate answer ends at
    /// the explored state nearest the goal (empty: at the start).
    std::function<double(const Pose2 &)> goalDistance;
};

/**
 * @brief The goal as the car lattice's search sees it (after Nav2's Smac GoalManager): a
 * view of a query's goal terms, with the search's every question about the goal.
 */
class CarGoal
{
public:
    explicit CarGoal(const CarGoalTerms &terms) : t_(terms) {}

    /// The pose aimed at.
    const Pose2 &pose() const { return t_.goal; }
    /// A state at world pose @p p is in the goal (the goal test; without one only the analytic
    /// expansion reaches the goal).
    bool reached(const Pose2 &p) const { return t_.inGoal && t_.inGoal(p); }
    /// How far a state at @p p is from the goal, for the approximate answer (smaller is nearer):
    /// the squared distance to the position aimed at, or without aim the goal's own distance
    /// (0 without one: the start is kept).
    double closeness(const Pose2 &p) const
    {
        if (!t_.aim) return t_.goalDistance ? t_.goalDistance(p) : 0.0;
        return (p.x - t_.goal.x) * (p.x - t_.goal.x) + (p.y - t_.goal.y) * (p.y - t_.goal.y);
    }
    /// The heuristic aims at the goal (else the search runs in Dijkstra order).
    bool aimed() const { return t_.aim; }
    /// The analytic expansion tries curves to the goal pose.
    bool shootable() const { return t_.shoot && t_.aim; }
    /// The goal's heading is to be met exactly by the shot (the curve bound then applies).
    bool exactHeading() const { return t_.goalYawTolerance == 0; }
    /// The end headings the analytic expansion tries from world pose @p from: the goal's (and
    /// both ends of its tolerance), or with a free goal heading the bearing to the goal and
    /// every heading of @p lattice turned by @p frameYaw (the lattice frame's yaw).
    std::vector<double> endYaws(const Pose2 &from, const CarLattice &lattice, double frameYaw) const;

private:
    const CarGoalTerms &t_;
};

}  // namespace gridcar
