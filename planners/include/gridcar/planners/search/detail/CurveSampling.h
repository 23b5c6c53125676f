#pragma once
/// @file CurveSampling.h
/// @brief Where a curve of the analytic expansion is sampled for its collision test. Internal
/// to the car-lattice search (detail/), shared by the expansion and the path shortcut.

#include "gridcar/curves/CarCurves.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gridcar::detail
{
/// Arc lengths along a piece of @p length metres starting at @p at, appended to @p arc, its end
/// included, no body point moving more than @p spacing between two of them (@p travel: how far
/// the farthest body point moves along the piece); @p at advances past the piece.
inline void appendArcs(double length, double travel, double spacing, double &at, std::vector<double> &arc)
{
    const int m = std::max(1, int(std::ceil(travel / spacing)));
    for (int i = 1; i <= m; ++i) arc.push_back(at + length * i / m);
    at += length;
}

/// Arc lengths at which @p path is sampled: each segment on its own, its end included (a cusp
/// is a pose of the path: a sample straddling it would make a kink), no body point (at most
/// @p reach from the reference point) moving more than @p spacing between two samples.
inline void sampleArcs(const CarCurve &path, double reach, double spacing, std::vector<double> &arc)
{
    arc.clear();
    double at = 0;
    for (int seg = 0; seg < path.count; ++seg)
    {
        const CurveSegment &sg = path.segments[std::size_t(seg)];
        const double l = std::abs(sg.length);
        if (l <= 0) continue;
        appendArcs(l, sg.steer == Steer::Straight ? l : l * (1.0 + reach / path.radius), spacing, at, arc);
    }
    if (arc.empty()) arc.push_back(path.length);
}
}  // namespace gridcar::detail
