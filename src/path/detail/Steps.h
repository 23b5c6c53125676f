#pragma once
/// @file Steps.h
/// @brief How many equal steps of at most a given length cover a length, with lengths that are
/// a whole number of steps but for the last bits counted as whole (private to src/path).

#include <cmath>

namespace gridcar::detail
{
/// ceil(length / step), less a billionth of a step: a lattice path's legs are whole multiples
/// of the sampling step up to rounding, and the last bits (which differ with the map's origin)
/// must not add a sample.
inline int stepsFor(double length, double step) { return int(std::ceil(length / step - 1e-9)); }

}  // namespace gridcar::detail
