#pragma once
/// @file Memory.h
/// @brief The process's resident memory, for the planners' memory bound (max_memory_mb).

namespace gridcar
{
/// Resident set size of this process in MB (Linux: /proc/self/statm), or -1 where it cannot be
/// read (the memory bound then does not apply).
double residentMegabytes();

}  // namespace gridcar
