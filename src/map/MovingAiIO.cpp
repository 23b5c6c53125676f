// Moving AI benchmark maps (.map) and scenario files (.scen).
#include "gridcar/map/MapIO.h"

#include "gridcar/core/Files.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gridcar
{
namespace
{
/// The file as text, after requireReadableFile() (a directory or a missing file is said so).
std::ifstream openText(const std::string &path, const std::string &what)
{
    requireReadableFile(path, what);
    return std::ifstream(path);
}

bool getLineNoCR(std::istream &in, std::string &line)
{
    if (!std::getline(in, line)) return false;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
}
}  // namespace

OccupancyGrid loadMovingAiMap(const std::string &path)
{
    std::ifstream in = openText(path, "Moving AI map");
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
    std::ifstream in = openText(path, "Moving AI scenario file");
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

}  // namespace gridcar
