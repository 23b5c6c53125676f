#pragma once
/// @file Pose2.h
/// @brief The two coordinate types every layer shares: a world pose and a grid cell.

namespace gridcar
{
/// A pose of the vehicle's reference point (rear-axle centre): world x, y (m), yaw (rad).
struct Pose2
{
    double x{0}, y{0}, yaw{0};
};

/// Integer cell coordinate: column (x to the right) and row (row 0 is the TOP image row).
struct Cell
{
    int col{0};
    int row{0};
    bool operator==(const Cell &o) const { return col == o.col && row == o.row; }
    bool operator!=(const Cell &o) const { return !(*this == o); }
};

}  // namespace gridcar
