#pragma once
/// @file ParamsFile.h
/// @brief `--params-file FILE` of `gridcar plan`, `drive` and `bench`: a planner, its
/// parameters, the vehicle, the space and the time limit in one YAML file, so that a set-up can
/// be kept, shared and reused (as ROS users keep a node's parameters in a file).
///
/// @code{.yaml}
/// planner: corner-astar          # any gridcar or OMPL planner name
/// params:                        # its declared parameters (gridcar planner --param NAME=VALUE)
///   cost: time
///   reverse: 1
/// vehicle: paper-c-car           # a preset, or a vehicle file (relative to this file)
/// space: reeds-shepp             # se2 | dubins | reeds-shepp
/// time_limit: 5                  # s
/// @endcode
/// Every key is optional; an unknown key is an error (a misspelt key must not be ignored).

#include "gridcar/bench/Problem.h"

#include <string>
#include <utility>
#include <vector>

namespace gridcar::bench
{
/// The contents of a parameters file; empty fields were not given.
struct ParamsFile
{
    std::string file;
    std::string planner;
    std::vector<std::pair<std::string, std::string>> params;  ///< in the file's order
    std::string vehicle;  ///< a preset name, or a vehicle file's path (absolute when found beside the file)
    std::string space;
    double timeLimit{0.0};  ///< 0: not given
};

/// Reads and checks @p file; InputError "<file>: <why>" for anything malformed or unknown.
ParamsFile readParamsFile(const std::string &file);

/// `bench --params-file` on a problem: its vehicle, space and time limit replace the problem's;
/// its params go to the problem's planners named like its planner (case-insensitive; every
/// planner when it names none). InputError when it names a planner the problem does not have.
void applyParamsFile(Problem &p, const ParamsFile &pf);

}  // namespace gridcar::bench
