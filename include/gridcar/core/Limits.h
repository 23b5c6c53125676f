#pragma once
/// @file Limits.h
/// @brief Sizes every reader of maps and images refuses to go beyond, before allocating.

#include <cstddef>

namespace gridcar
{
/// Largest number of cells a map may have (about 1.1 GB of cell data would be absurd for a
/// planner on this project's machines), and of pixels an image read as a map may have;
/// readers refuse bigger headers before allocating.
constexpr std::size_t kMaxMapCells = std::size_t(1) << 28;  // 268 M cells, e.g. 16384 x 16384

}  // namespace gridcar
