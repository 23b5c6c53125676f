#pragma once
/// @file PaperI.h
/// @brief `gridcar paper-i`: paper I's section 4 (three query areas; Dijkstra, A* Manhattan /
/// Euclidean, improved A* in both modes and corner A*) on the embedded campus and on the
/// Tsudanuma map (native 0.05 m and resampled to paper I's 0.298 m/cell).

#include <string>
#include <vector>

namespace gridcar::bench
{
struct PaperIOptions
{
    std::string outDir{"paper-i-out"};
    std::string sharedDir{"../shared"};
    double timeLimit{60.0};
    bool skipNative{false};
    std::vector<std::string> maps;  ///< empty: all
};

/// Writes paper_i_tables.md, paper_i.json and one picture per area into outDir; the Tsudanuma
/// maps only when found under sharedDir. Returns the exit status (0).
int runPaperI(const PaperIOptions &o);

}  // namespace gridcar::bench
