#pragma once
/// @file CurveWords.h
/// @brief Internal to src/curves: candidate words of the car curves and the shortest of them
/// that lands on the goal (not installed).

#include "gridcar/curves/CarCurves.h"

#include <initializer_list>
#include <vector>

namespace gridcar
{
namespace curves
{
/// An angle within this of 0 (or of a full turn) is 0: no extra loop from a rounding error.
constexpr double kSnap = 1e-10;
/// How close (unit radius, and rad) a candidate must land on the goal to count.
constexpr double kLandTolerance = 1e-6;

/// @p a in [0, 2 pi), a value within kSnap below 2 pi taken as 0.
double mod2pi(double a);
/// @p a in [-pi, pi], a value within kSnap of 0 taken as 0.
double modPi(double a);

/// The goal @p b seen from @p a, at unit turning radius: (x, y, heading change).
Pose2 normalisedGoal(const Pose2 &a, const Pose2 &b, double radius);
/// True if every number is finite and the radius > 0.
bool finitePoses(const Pose2 &a, const Pose2 &b, double radius);

/// Candidate words at unit radius (segment lengths in radians of arc, or radii of straight).
class Candidates
{
public:
    void add(std::initializer_list<CurveSegment> segs);
    /// The shortest candidate that, driven from the origin, ends within kLandTolerance of
    /// @p goal, scaled to @p radius; an empty curve when none does.
    CarCurve shortestLanding(const Pose2 &goal, double radius);
    /// The @p maxCount shortest candidates that land on @p goal (shortest first), scaled to
    /// @p radius; words of the same length and steering as a shorter one are left out.
    std::vector<CarCurve> landings(const Pose2 &goal, double radius, int maxCount);

private:
    struct Word
    {
        CurveSegment segments[5];
        int count{0};
        double length{0.0};
    };
    std::vector<Word> words_;
};

}  // namespace curves
}  // namespace gridcar
