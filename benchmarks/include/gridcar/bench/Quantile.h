#pragma once
/// @file Quantile.h
/// @brief The quantile the benchmark programs report (bench_native, bench_parking, bench_replan):
/// the sample at the rounded rank q (n - 1) of the sorted values, NaN for none.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gridcar
{
inline double quantile(std::vector<double> v, double q)
{
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5))];
}
}  // namespace gridcar
