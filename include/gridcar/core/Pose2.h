#pragma once
/// @file Pose2.h
/// @brief The two coordinate types every layer shares: a world pose and a grid cell.

#include <cmath>

namespace gridcar
{
/// A pose of the vehicle's reference point (rear-axle centre): world x, y (m), yaw (rad).
struct Pose2
{
    double x{0}, y{0}, yaw{0};
};

/// Metres within which two poses of a path are one: a curve's end sampled twice, rounding
/// apart (the heading of a step this short is noise, not a turn).
constexpr double kSamePosition = 1e-6;

/// True if @p a and @p b lie within kSamePosition of each other.
inline bool samePosition(const Pose2 &a, const Pose2 &b) { return std::hypot(a.x - b.x, a.y - b.y) <= kSamePosition; }

/// Integer cell coordinate: column (x to the right) and row (row 0 is the TOP image row).
struct Cell
{
    int col{0};
    int row{0};
    bool operator==(const Cell &o) const { return col == o.col && row == o.row; }
    bool operator!=(const Cell &o) const { return !(*this == o); }
};

}  // namespace gridcar
