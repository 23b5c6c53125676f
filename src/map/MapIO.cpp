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

std::ifstream openText(const std::string &path)
{
    std::ifstream in(path);
    if (!in) throw MapLoadError(path, "cannot open file (" + std::string(std::strerror(errno)) + ")");
    return in;
}

bool getLineNoCR(std::istream &in, std::string &line)
{
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
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
                if (meta.mode == RosMapMode::Raw)
                {
                    if (v > 100.0) s = CellState::Unknown;
                    else
                    {
                        const double occ = v / 100.0;
                        s = occ > meta.occupiedThresh ? CellState::Occupied :
                            occ < meta.freeThresh     ? CellState::Free :
                                                        CellState::Unknown;
                    }
                }
                else
                {
                    if (meta.negate) v = 255.0 - v;
                    const double occ = (255.0 - v) / 255.0;
                    s = occ > meta.occupiedThresh ? CellState::Occupied :
                        occ < meta.freeThresh     ? CellState::Free :
                                                    CellState::Unknown;
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

OccupancyGrid loadMovingAiMap(const std::string &path)
{
    std::ifstream in = openText(path);
    std::string line;
    long long width = -1, height = -1;
    bool sawType = false, sawMap = false;
    int lineNo = 0;
    while (!sawMap && getLineNoCR(in, line))
    {
        ++lineNo;
        std::istringstream ls(line);
        std::string key;
        if (!(ls >> key)) continue;
        if (key == "type")
        {
            std::string t;
            ls >> t;
            if (t != "octile") throw MapLoadError(path, "line " + std::to_string(lineNo) + ": unsupported map type '" + t + "' (expected octile)");
            sawType = true;
        }
        else if (key == "height" || key == "width")
        {
            long long v;
            if (!(ls >> v)) throw MapLoadError(path, "line " + std::to_string(lineNo) + ": '" + key + "' needs an integer");
            (key == "height" ? height : width) = v;
        }
        else if (key == "map")
            sawMap = true;
        else
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": unexpected header line '" + printable(line) + "'");
    }
    if (!sawType) throw MapLoadError(path, "missing header line 'type octile'");
    if (width < 0 || height < 0) throw MapLoadError(path, "missing 'height' or 'width' in the header");
    if (!sawMap) throw MapLoadError(path, "missing 'map' line after the header");
    if (width <= 0 || height <= 0 || width > (1 << 20) || height > (1 << 20) ||
        (unsigned long long)(width) * (unsigned long long)(height) > kMaxMapCells)
        throw MapLoadError(path, "absurd map size " + std::to_string(width) + " x " + std::to_string(height));
    {
        // the rows must fit in what is left of the file before the grid is allocated for them
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        const std::streamoff at = in.tellg();
        const unsigned long long need = (unsigned long long)(width) * (unsigned long long)(height) + (unsigned long long)(height) - 1;
        if (!ec && at >= 0 && (unsigned long long)(size) - (unsigned long long)(at) < need)
            throw MapLoadError(path, "truncated: the header declares " + std::to_string(width) + " x " + std::to_string(height) +
                                         " cells, which need " + std::to_string(need) + " bytes of rows, the file has " +
                                         std::to_string((unsigned long long)(size) - (unsigned long long)(at)));
    }
    OccupancyGrid grid(int(width), int(height), 1.0, CellState::Free);
    for (int r = 0; r < height; ++r)
    {
        if (!getLineNoCR(in, line))
            throw MapLoadError(path, "truncated: expected " + std::to_string(height) + " map rows, found " + std::to_string(r));
        ++lineNo;
        if ((long long)line.size() != width)
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": row " + std::to_string(r) + " has " +
                                         std::to_string(line.size()) + " characters, expected " + std::to_string(width));
        for (int c = 0; c < width; ++c)
        {
            const char ch = line[c];
            CellState s;
            switch (ch)
            {
                case '.': case 'G': case 'S': s = CellState::Free; break;
                case '@': case 'O': case 'T': case 'W': s = CellState::Occupied; break;
                default:
                    throw MapLoadError(path, "line " + std::to_string(lineNo) + ", column " + std::to_string(c) +
                                                 ": invalid map character '" + printable(std::string(1, ch)) + "'");
            }
            grid.set(c, r, s);
        }
    }
    while (getLineNoCR(in, line))
    {
        ++lineNo;
        if (line.find_first_not_of(" \t") != std::string::npos)
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": more rows than the header's height " + std::to_string(height));
    }
    return grid;
}

std::vector<ScenarioEntry> loadScenario(const std::string &path)
{
    std::ifstream in = openText(path);
    std::string line;
    int lineNo = 0;
    bool sawVersion = false;
    std::vector<ScenarioEntry> out;
    while (getLineNoCR(in, line))
    {
        ++lineNo;
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        if (!sawVersion)
        {
            std::istringstream ls(line);
            std::string key;
            double ver = 0;
            if (!(ls >> key >> ver) || key != "version")
                throw MapLoadError(path, "line 1: expected 'version 1'");
            if (ver != 1.0) throw MapLoadError(path, "unsupported scenario version " + std::to_string(ver));
            sawVersion = true;
            continue;
        }
        // columns are tab-separated; the map name has no spaces in practice, but split on tabs
        // first so that a path with spaces still parses
        std::vector<std::string> cols;
        {
            std::string cur;
            std::istringstream ls(line);
            if (line.find('\t') != std::string::npos)
                while (std::getline(ls, cur, '\t')) cols.push_back(cur);
            else
                while (ls >> cur) cols.push_back(cur);
        }
        if (cols.size() != 9)
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": expected 9 columns, found " + std::to_string(cols.size()));
        ScenarioEntry e;
        try
        {
            std::size_t used = 0;
            auto toInt = [&](const std::string &s) {
                const long v = std::stol(s, &used);
                if (used != s.size() || v < 0 || v > (1 << 24)) throw std::invalid_argument(s);
                return int(v);
            };
            e.bucket = toInt(cols[0]);
            e.map = cols[1];
            e.mapWidth = toInt(cols[2]);
            e.mapHeight = toInt(cols[3]);
            e.startX = toInt(cols[4]);
            e.startY = toInt(cols[5]);
            e.goalX = toInt(cols[6]);
            e.goalY = toInt(cols[7]);
            e.optimalLength = std::stod(cols[8], &used);
            if (used != cols[8].size() || !std::isfinite(e.optimalLength) || e.optimalLength < 0)
                throw std::invalid_argument(cols[8]);
        }
        catch (const std::exception &)
        {
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": malformed number");
        }
        if (e.startX >= e.mapWidth || e.goalX >= e.mapWidth || e.startY >= e.mapHeight || e.goalY >= e.mapHeight)
            throw MapLoadError(path, "line " + std::to_string(lineNo) + ": start or goal outside the stated map size");
        out.push_back(std::move(e));
    }
    if (!sawVersion) throw MapLoadError(path, "empty scenario file (expected 'version 1')");
    return out;
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
