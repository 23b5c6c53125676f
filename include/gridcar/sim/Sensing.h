#pragma once
/// @file Sensing.h
/// @brief A simulated 2D range sensor over the true world (a map and a scenario's obstacles)
/// and the working map a vehicle keeps of what it has seen, apart from the map it was given.

#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/OccupancyGrid.h"
#include "gridcar/sim/Simulation.h"

#include <array>
#include <cstddef>
#include <memory>
#include <unordered_map>
#include <vector>

namespace gridcar
{
/// A planar range sensor (a 360-degree lidar at the vehicle's reference point).
struct RangeSensorParams
{
    double range{10.0};  ///< m
    int beams{360};      ///< over the full circle
    double period{0.2};  ///< s between scans
    /// An obstacle of the scenario seen moving slower than this (its displacement over
    /// stationaryWindow, m/s) is put into the working map; a faster one (a pedestrian crossing)
    /// is left to the follower's potential field.
    double stationarySpeed{0.1};
    double stationaryWindow{1.0};  ///< s
};

/**
 * @brief The map a vehicle plans on: the map it was given, plus the cells where a scan hit an
 * obstacle the map did not show (a cell of the true world's map, or a standing obstacle of the
 * scenario), minus such cells a later scan saw through whole (the obstacle has gone). Cells the
 * given map holds as occupied are never cleared.
 *
 * Each beam is marched from the sensor in steps of half a cell up to the range: the first
 * point in an occupied cell of the true map or inside a scenario obstacle ends it; cells it
 * passed that a scan had marked, with no obstacle within three quarters of a cell of their
 * centre, are given back their state in the map. Line of sight, so nothing behind an obstacle
 * is seen. Unknown cells of the true map do not stop a beam.
 */
class WorkingMap
{
public:
    /// @p grid is the map the vehicle was given, changed in place by scan().
    explicit WorkingMap(std::shared_ptr<OccupancyGrid> grid);

    /// One scan from (x, y) at time @p t of @p truth (the same size and origin as the working
    /// map; std::invalid_argument otherwise) and @p world. Returns the cells that changed (their
    /// bounding window; empty when none), to pass to DistanceField::update() and
    /// FootprintChecker::cellsChanged().
    ///
    /// Footprint clearing (Nav2's obstacle layer, `footprint_clearing_enabled`): with @p body
    /// (the vehicle's outline in world coordinates, as it stands: a simple polygon in either
    /// orientation, std::invalid_argument where it cannot be triangulated), a cell the body overlaps is
    /// not marked, and a marked one is given back its state in the map: nothing can stand where
    /// the vehicle is, and a cell a scan marked for an obstacle beside the body, were it kept,
    /// would leave the vehicle's own pose in collision in the working map (no plan from it).
    CellWindow scan(const OccupancyGrid &truth, const Scenario &world, double t, double x, double y,
                    const RangeSensorParams &sensor, const std::vector<std::array<double, 2>> *body = nullptr);

    const OccupancyGrid &grid() const { return *grid_; }
    std::shared_ptr<OccupancyGrid> gridPtr() const { return grid_; }
    /// Cells marked by scans and not cleared since.
    std::size_t sensedCells() const { return sensed_.size(); }
    /// True when a cell marked by scans lies within @p radius m of (x, y).
    bool sensedWithin(double x, double y, double radius) const;

private:
    /// Gives the marked cells that @p body overlaps back their state in the map (into @p changed).
    void clearUnder(const std::vector<std::array<double, 2>> &body, CellWindow &changed);

    std::shared_ptr<OccupancyGrid> grid_;
    std::unordered_map<std::size_t, CellState> sensed_;  ///< marked cell -> its state in the given map
};

}  // namespace gridcar
