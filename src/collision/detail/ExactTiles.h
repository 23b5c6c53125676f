#pragma once
/// @file ExactTiles.h
/// @brief The exact (FCL) check's obstacles of a FootprintChecker: boxes over the obstacle
/// boundary cells per tile of the map, each tile made on first use, and walls round the map.

#include "gridcar/collision/FootprintChecker.h"

#include <memory>
#include <mutex>
#include <vector>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>

namespace gridcar
{
/// The exact check's obstacle boxes, per kTile x kTile cells, each made on first use.
struct FootprintChecker::ExactTiles
{
    /// Tiles over @p g (none made yet) and the walls round it, @p wall metres thick.
    ExactTiles(const OccupancyGrid &g, double wall);

    static constexpr int kTile = 64;
    struct Tile
    {
        std::once_flag once;
        std::unique_ptr<fcl::DynamicAABBTreeCollisionManagerd> manager;  ///< null: no boxes in the tile
        std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
    };
    int tilesX{0}, tilesY{0};
    std::unique_ptr<Tile[]> tiles;
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> walls;
    std::unique_ptr<fcl::DynamicAABBTreeCollisionManagerd> wallManager;

    /// Tile (tx, ty) of @p g, its boxes made on the first call (thread-safe).
    const Tile &tile(const OccupancyGrid &g, int tx, int ty);
    /// The tiles over @p cells made again on their next use (not while others read them).
    void reset(const CellWindow &cells);
};

}  // namespace gridcar
