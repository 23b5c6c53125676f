#pragma once
/// @file MapIO.h
/// @brief Readers and writers for occupancy-grid map files.

#include "gridcar/image/Image.h"
#include "gridcar/map/OccupancyGrid.h"

#include <string>
#include <vector>

namespace gridcar
{
/// How a ROS map_server image is interpreted (the yaml `mode` key).
enum class RosMapMode
{
    Trinary,
    Scale,
    Raw
};

/// Parameters of a ROS map_server YAML file.
struct RosMapMeta
{
    std::string image;          ///< image path as written in the YAML
    std::string imagePath;      ///< resolved path (relative to the YAML file's folder)
    double resolution{0.0};     ///< metres per cell
    double origin[3]{0, 0, 0};  ///< x, y, yaw of the lower-left pixel
    bool negate{false};
    double occupiedThresh{0.65};
    double freeThresh{0.196};
    RosMapMode mode{RosMapMode::Trinary};
    /// `values: costmap` (gridcar's key, raw mode only): the pixels are Nav2 costmap_2d values
    /// (0..252 costs, 253-254 lethal, 255 unknown) instead of occupancy percentages.
    bool costmapValues{false};
};

/**
 * @brief Loads a ROS map_server map (YAML + PGM/PNG image).
 *
 * Keys `image`, `resolution`, `origin` are required; `negate` (0), `occupied_thresh` (0.65),
 * `free_thresh` (0.196) and `mode` (trinary) are optional. The image path is relative to
 * the YAML file. Per pixel, the colour channels are averaged (alpha excluded),
 * p = (255 - v) / 255 (v / 255 with negate); occupied if p > occupied_thresh, free if
 * p < free_thresh, else unknown. A fully transparent pixel (alpha 0) is unknown. In `raw`
 * mode the value is the occupancy in percent (0..100), anything above 100 is unknown.
 *
 * Cost layer (OccupancyGrid::cost()): in `scale` and `raw` modes a p between free_thresh and
 * occupied_thresh is, as map_server's scale mode means it, a free cell with a traversal cost
 * 252 (p - free_thresh) / (occupied_thresh - free_thresh) instead of unknown. With
 * `values: costmap` (raw mode) the pixels are Nav2 costmap values: 0..252 a free cell of that
 * cost, 253-254 occupied (inscribed / lethal), 255 unknown. `trinary` (the default) has no cost
 * layer and reads as before.
 * Throws MapLoadError("<file>: <reason>") for any malformed input.
 */
OccupancyGrid loadRosMap(const std::string &yamlPath, RosMapMeta *metaOut = nullptr);

/// Converts a decoded image to a grid with map_server semantics (see loadRosMap()).
OccupancyGrid imageToGrid(const Image &img, const RosMapMeta &meta, const std::string &fileForErrors);

/**
 * @brief Loads a Moving AI `.map` file (type octile). `.`, `G`, `S` are passable; `@`, `O`,
 * `T`, `W` are blocked. Resolution 1 m, origin (0, 0), cell (x = column, y = row) with row 0
 * at the top. CRLF line endings are accepted.
 */
OccupancyGrid loadMovingAiMap(const std::string &path);

/// One line of a Moving AI scenario file.
struct ScenarioEntry
{
    int bucket{0};
    std::string map;
    int mapWidth{0}, mapHeight{0};
    int startX{0}, startY{0}, goalX{0}, goalY{0};  ///< x = column, y = row (row 0 top)
    double optimalLength{0.0};
};

/// Loads a Moving AI `.scen` file (version 1; 9 columns per line, optimal length last).
std::vector<ScenarioEntry> loadScenario(const std::string &path);

/**
 * @brief Loads a plain image (PPM/PGM/PNG) as a map, as OMPL's PPM demos do: a pixel is occupied
 * when every colour channel is dark (< 128), else free (so OMPL's pure red / green start and
 * goal marker pixels are free, and black walls are occupied). Resolution @p resolution m/cell, origin 0.
 */
OccupancyGrid loadImageMap(const std::string &path, double resolution = 1.0);

/// Loads any supported map, chosen by extension: .yaml/.yml (ROS), .map (Moving AI),
/// .ppm/.pgm/.pnm/.png (plain image, dark = occupied).
OccupancyGrid loadMap(const std::string &path);

/// Gray image of a grid in map_server colours: free 254, occupied 0, unknown 205.
Image gridToImage(const OccupancyGrid &grid);

/**
 * @brief Writes a ROS map_server pair: @p yamlPath and the image next to it (PGM if the
 * name ends in .pgm, else PNG). Throws std::runtime_error on failure.
 */
void saveRosMap(const OccupancyGrid &grid, const std::string &yamlPath, const std::string &imageFileName);

}  // namespace gridcar
