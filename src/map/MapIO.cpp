#include "gridcar/map/MapIO.h"

#include "gridcar/core/Files.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/yaml.h>

namespace gridcar
{
namespace
{
std::string dirOf(const std::string &path)
{
    const auto pos = path.find_last_of('/');
    return pos == std::string::npos ? std::string() : path.substr(0, pos + 1);
}

std::string lowerExt(const std::string &path)
{
    const auto slash = path.find_last_of('/');
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot + 1);
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

/// A number for an error message ("1e+155", not 156 digits).
std::string shortNumber(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

double yamlNumber(const YAML::Node &node, const std::string &key, const std::string &file)
{
    try
    {
        const double v = node.as<double>();
        if (!std::isfinite(v)) throw MapLoadError(file, "key '" + key + "' must be finite");
        return v;
    }
    catch (const YAML::Exception &)
    {
        throw MapLoadError(file, "key '" + key + "' must be a number");
    }
}

}  // namespace

OccupancyGrid imageToGrid(const Image &img, const RosMapMeta &meta, const std::string &file)
{
    OccupancyGrid grid;
    try
    {
        grid = OccupancyGrid(img.width, img.height, meta.resolution, CellState::Unknown);
        grid.setOrigin(meta.origin[0], meta.origin[1], meta.origin[2]);
    }
    catch (const std::invalid_argument &e)
    {
        throw MapLoadError(file, e.what());
    }
    const bool hasAlpha = img.channels == 2 || img.channels == 4;
    const int colourChannels = hasAlpha ? img.channels - 1 : img.channels;
    if (colourChannels < 1) throw MapLoadError(file, "image has no colour channel");
    std::vector<CellState> &cells = grid.cells();
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
        {
            const std::uint8_t *p = img.px(x, y);
            CellState s;
            if (hasAlpha && p[img.channels - 1] == 0)
                s = CellState::Unknown;
            else
            {
                int sum = 0;
                for (int k = 0; k < colourChannels; ++k) sum += p[k];
                double v = double(sum) / colourChannels;
                // an occupancy between the thresholds: unknown in trinary mode, a free cell with a
                // cost in scale and raw modes (map_server's intermediate values)
                const auto classify = [&](double occ) {
                    if (occ > meta.occupiedThresh) return CellState::Occupied;
                    if (occ < meta.freeThresh) return CellState::Free;
                    if (meta.mode == RosMapMode::Trinary) return CellState::Unknown;
                    const double span = meta.occupiedThresh - meta.freeThresh;
                    const double c = span > 0 ? 252.0 * (occ - meta.freeThresh) / span : 252.0;
                    grid.setCost(x, y, std::uint8_t(std::lround(std::clamp(c, 0.0, 252.0))));
                    return CellState::Free;
                };
                if (meta.mode == RosMapMode::Raw && meta.costmapValues)
                {
                    const int iv = int(std::lround(v));
                    s = iv >= 255 ? CellState::Unknown : iv >= 253 ? CellState::Occupied : CellState::Free;
                    if (iv > 0 && iv <= 252) grid.setCost(x, y, std::uint8_t(iv));
                }
                else if (meta.mode == RosMapMode::Raw)
                    s = v > 100.0 ? CellState::Unknown : classify(v / 100.0);
                else
                {
                    if (meta.negate) v = 255.0 - v;
                    s = classify((255.0 - v) / 255.0);
                }
            }
            cells[grid.index(x, y)] = s;
        }
    return grid;
}

OccupancyGrid loadRosMap(const std::string &yamlPath, RosMapMeta *metaOut)
{
    YAML::Node root;
    requireReadableFile(yamlPath, "map file");
    try
    {
        root = YAML::LoadFile(yamlPath);
    }
    catch (const YAML::Exception &e)
    {
        throw MapLoadError(yamlPath, std::string("YAML syntax error: ") + e.what());
    }
    if (!root.IsMap()) throw MapLoadError(yamlPath, "expected a YAML mapping with keys image, resolution, origin");
    RosMapMeta meta;
    for (const char *key : {"image", "resolution", "origin"})
        if (!root[key]) throw MapLoadError(yamlPath, std::string("missing required key '") + key + "'");
    try
    {
        meta.image = root["image"].as<std::string>();
    }
    catch (const YAML::Exception &)
    {
        throw MapLoadError(yamlPath, "key 'image' must be a string");
    }
    if (meta.image.empty()) throw MapLoadError(yamlPath, "key 'image' is empty");
    meta.imagePath = meta.image[0] == '/' ? meta.image : dirOf(yamlPath) + meta.image;
    meta.resolution = yamlNumber(root["resolution"], "resolution", yamlPath);
    if (!(meta.resolution >= kMinResolution && meta.resolution <= kMaxResolution))
        throw MapLoadError(yamlPath, "resolution must be positive and between 0.0001 and 1000 m per cell, got " + shortNumber(meta.resolution));
    const YAML::Node origin = root["origin"];
    if (!origin.IsSequence() || origin.size() != 3)
        throw MapLoadError(yamlPath, "key 'origin' must be a list [x, y, yaw]");
    for (int i = 0; i < 3; ++i) meta.origin[i] = yamlNumber(origin[i], "origin", yamlPath);
    if (std::abs(meta.origin[0]) > kMaxMapExtent || std::abs(meta.origin[1]) > kMaxMapExtent)
        throw MapLoadError(yamlPath, "origin is more than 10000 km from 0 (x " + shortNumber(meta.origin[0]) + ", y " +
                                         shortNumber(meta.origin[1]) + ")");
    if (root["negate"])
    {
        const double n = yamlNumber(root["negate"], "negate", yamlPath);
        if (n != 0.0 && n != 1.0) throw MapLoadError(yamlPath, "key 'negate' must be 0 or 1");
        meta.negate = n != 0.0;
    }
    if (root["occupied_thresh"]) meta.occupiedThresh = yamlNumber(root["occupied_thresh"], "occupied_thresh", yamlPath);
    if (root["free_thresh"]) meta.freeThresh = yamlNumber(root["free_thresh"], "free_thresh", yamlPath);
    if (meta.occupiedThresh < 0 || meta.occupiedThresh > 1 || meta.freeThresh < 0 || meta.freeThresh > 1)
        throw MapLoadError(yamlPath, "occupied_thresh and free_thresh must lie in [0, 1]");
    if (meta.freeThresh > meta.occupiedThresh)
        throw MapLoadError(yamlPath, "free_thresh must not exceed occupied_thresh");
    if (root["mode"])
    {
        std::string m;
        try
        {
            m = root["mode"].as<std::string>();
        }
        catch (const YAML::Exception &)
        {
            throw MapLoadError(yamlPath, "key 'mode' must be a string");
        }
        if (m == "trinary") meta.mode = RosMapMode::Trinary;
        else if (m == "scale") meta.mode = RosMapMode::Scale;
        else if (m == "raw") meta.mode = RosMapMode::Raw;
        else throw MapLoadError(yamlPath, "unknown mode '" + m + "' (expected trinary, scale or raw)");
    }
    if (root["values"])
    {
        const std::string v = root["values"].IsScalar() ? root["values"].Scalar() : "";
        if (v != "occupancy" && v != "costmap")
            throw MapLoadError(yamlPath, "key 'values' must be occupancy or costmap, got '" + printable(v) + "'");
        if (v == "costmap" && meta.mode != RosMapMode::Raw)
            throw MapLoadError(yamlPath, "'values: costmap' needs 'mode: raw' (the pixels are then Nav2 costmap values)");
        meta.costmapValues = v == "costmap";
    }
    Image img;
    try
    {
        img = readImage(meta.imagePath);
    }
    catch (const MapLoadError &e)
    {
        throw MapLoadError(yamlPath, "image '" + meta.image + "': " + e.what());
    }
    if (metaOut) *metaOut = meta;
    return imageToGrid(img, meta, yamlPath);
}


OccupancyGrid loadImageMap(const std::string &path, double resolution)
{
    const Image img = readImage(path);
    OccupancyGrid grid(img.width, img.height, resolution, CellState::Free);
    const bool hasAlpha = img.channels == 2 || img.channels == 4;
    const int cc = hasAlpha ? img.channels - 1 : img.channels;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
        {
            const std::uint8_t *p = img.px(x, y);
            bool dark = true;  // every colour channel below 128 (OMPL's red/green markers stay free)
            for (int k = 0; k < cc; ++k) dark = dark && p[k] < 128;
            grid.set(x, y, dark ? CellState::Occupied : CellState::Free);
        }
    return grid;
}

OccupancyGrid loadMap(const std::string &path)
{
    const std::string ext = lowerExt(path);
    if (ext == "yaml" || ext == "yml") return loadRosMap(path);
    if (ext == "map") return loadMovingAiMap(path);
    if (ext == "ppm" || ext == "pgm" || ext == "pnm" || ext == "png") return loadImageMap(path);
    throw MapLoadError(path, "unknown map format '." + ext + "' (expected .yaml, .map, .ppm, .pgm or .png)");
}

Image gridToImage(const OccupancyGrid &grid)
{
    Image img;
    img.width = grid.width();
    img.height = grid.height();
    img.channels = 1;
    img.data.resize(grid.size());
    const auto &cells = grid.cells();
    for (std::size_t i = 0; i < cells.size(); ++i)
        img.data[i] = cells[i] == CellState::Free ? 254 : cells[i] == CellState::Occupied ? 0 : 205;
    return img;
}

void saveRosMap(const OccupancyGrid &grid, const std::string &yamlPath, const std::string &imageFileName)
{
    const Image img = gridToImage(grid);
    const std::string imagePath = dirOf(yamlPath) + imageFileName;
    if (lowerExt(imageFileName) == "pgm") writePgm(imagePath, img);
    else writePng(imagePath, img);
    std::ofstream y(yamlPath);
    if (!y) throw std::runtime_error(yamlPath + ": cannot write file (" + std::string(std::strerror(errno)) + ")");
    y.precision(17);
    y << "image: " << imageFileName << "\n"
      << "mode: trinary\n"
      << "resolution: " << grid.resolution() << "\n"
      << "origin: [" << grid.originX() << ", " << grid.originY() << ", " << grid.originYaw() << "]\n"
      << "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
    if (!y) throw std::runtime_error(yamlPath + ": write error");
}

}  // namespace gridcar

