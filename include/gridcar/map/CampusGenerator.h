#pragma once
/// @file CampusGenerator.h
/// @brief Deterministic generator of a campus-like occupancy grid (the embedded default map).

#include "gridcar/map/OccupancyGrid.h"

#include <cstdint>

namespace gridcar
{
/// Parameters of the campus generator. Defaults give paper I's map size (4846 x 2816 cells at
/// 0.298 m/cell, about 1444 m x 839 m).
struct CampusParams
{
    int width{4846};
    int height{2816};
    double resolution{0.298};      ///< metres per cell
    std::uint64_t seed{1};
    double roadMinWidth{5.0};      ///< metres
    double roadMaxWidth{10.0};     ///< metres
    double blockSize{170.0};       ///< typical distance between junctions, metres
    double margin{12.0};           ///< unknown band around the map, metres
    double narrowWidth{3.2};       ///< free width of the narrow passages (gates), metres
    int narrowPassages{3};         ///< number of gates placed on roads
    double curbWidth{0.5};         ///< thickness of the occupied curb drawn along road edges
};

/**
 * @brief Makes a campus-like map deterministically from CampusParams::seed.
 *
 * Layout: a jittered grid of junctions joined by roads 5-10 m wide (a random spanning tree so
 * that every road is reachable, plus most of the remaining links), some of them bent
 * (quadratic Bezier centre lines), rounded junction corners, one roundabout, a parking lot with
 * rows of islands, a plaza with buildings and narrow walkways between them, and gates that
 * narrow a few roads to CampusParams::narrowWidth. Roads, lot and plaza are free; building
 * blocks are unknown with an occupied curb along every edge to free space; buildings are
 * occupied; an unknown band of CampusParams::margin surrounds the map.
 *
 * The same parameters always give the same grid (no std:: distributions are used, so the
 * result does not depend on the standard library). Throws std::invalid_argument for sizes
 * that cannot hold a road network (less than about 60 m x 60 m) or absurd ones.
 */
OccupancyGrid generateCampus(const CampusParams &params = CampusParams());

}  // namespace gridcar
