#pragma once
/// @file PaperC.h
/// @brief `gridcar paper-c`: paper C's driving-time comparison. A* Euclidean against corner A*
/// (paper and physics weights) on random road pairs, each path driven in the simulation by paper
/// C's robot and car, on the embedded campus and the Tsudanuma map; plus a corner-weight sweep.

#include <string>

namespace gridcar::bench
{
struct PaperCOptions
{
    std::string outDir{"paper-c-out"};
    std::string sharedDir{"../shared"};
    int pairs{20};
    unsigned long long seed{1};
    double timeLimit{20.0};
    /// corner A*'s `mode`: `paper` (paper C's 8-connected grid, the reproduction) or
    /// `drivable` (the car lattice)
    std::string cornerMode{"paper"};
};

/// Writes paper_c_tables.md and paper_c.json into outDir. Returns the exit status (0).
int runPaperC(const PaperCOptions &o);

}  // namespace gridcar::bench
