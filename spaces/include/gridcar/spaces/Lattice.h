#pragma once
/// @file Lattice.h
/// @brief The search lattice's headings: the one place that rounds a yaw to a heading, and
/// the 8 move directions of the grid planners.

#include <cmath>

namespace gridcar
{
/// The nearest of @p bins equally spaced headings to @p yaw: bin k at yaw k * 2 pi / bins
/// (0 = +x, counter-clockwise); a yaw exactly half-way rounds up to the higher bin; a yaw that
/// is not finite gives bin 0.
int headingBin(double yaw, int bins);

/// The 8 lattice move directions, 45 degrees apart: 0 = +x (east), counter-clockwise, in the
/// world frame (y up). Row offsets are negative for moves towards +y (row 0 is the top).
struct Moves
{
    static constexpr int dcol[8] = {1, 1, 0, -1, -1, -1, 0, 1};
    static constexpr int drow[8] = {0, -1, -1, -1, 0, 1, 1, 1};
    static double yaw(int d) { return d * M_PI / 4.0; }
    /// Nearest of the 8 directions to a yaw (headingBin(yaw, 8)).
    static int fromYaw(double yaw) { return headingBin(yaw, 8); }
    /// Heading change between two directions in 45-degree steps (0..4).
    static int turn(int from, int to)
    {
        const int t = ((to - from) % 8 + 8) % 8;
        return t > 4 ? 8 - t : t;
    }
};

}  // namespace gridcar
