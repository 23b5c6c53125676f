#include "gridcar/render/Render.h"

#include <algorithm>
#include <cmath>

namespace gridcar
{
OccupancyGrid cropAround(const OccupancyGrid &grid, const WorldBox &box, double margin)
{
    const Cell tl = grid.worldToCell(box.x0 - margin, box.y1 + margin), br = grid.worldToCell(box.x1 + margin, box.y0 - margin);
    const int c0 = std::clamp(tl.col, 0, grid.width() - 1), r0 = std::clamp(tl.row, 0, grid.height() - 1);
    const int c1 = std::clamp(br.col, 0, grid.width() - 1), r1 = std::clamp(br.row, 0, grid.height() - 1);
    return grid.cropped(c0, r0, c1 - c0 + 1, r1 - r0 + 1);
}

void MapCanvas::polyline(const std::vector<Pose2> &path, const Rgb &colour, int thickness)
{
    std::vector<std::pair<double, double>> pts;
    pts.reserve(path.size());
    for (const Pose2 &p : path) pts.push_back({p.x, p.y});
    polyline(pts, colour, thickness);
}

MapCanvas::MapCanvas(const OccupancyGrid &grid, int maxSide) : grid_(grid)
{
    const int longSide = std::max(grid.width(), grid.height());
    scale_ = std::min(8.0, double(std::max(64, maxSide)) / longSide);
    if (scale_ >= 1.0) scale_ = std::floor(scale_);
    img_.width = std::max(1, int(std::ceil(grid.width() * scale_)));
    img_.height = std::max(1, int(std::ceil(grid.height() * scale_)));
    img_.channels = 3;
    img_.data.assign(std::size_t(img_.width) * img_.height * 3, 255);
    // rank: free 0 < unknown 1 < occupied 2; keep the darkest per pixel
    std::vector<std::uint8_t> rank(std::size_t(img_.width) * img_.height, 0);
    // the cost layer (Nav2's 0..252 on free cells), the highest per pixel
    std::vector<std::uint8_t> cost(grid.hasCosts() ? rank.size() : 0, 0);
    for (int r = 0; r < grid.height(); ++r)
    {
        const int py0 = int(r * scale_), py1 = std::max(py0, int((r + 1) * scale_) - 1);
        for (int c = 0; c < grid.width(); ++c)
        {
            const CellState s = grid.at(c, r);
            const std::uint8_t k = s == CellState::Occupied ? 2 : s == CellState::Unknown ? 1 : 0;
            const std::uint8_t cc = k == 0 ? grid.cost(c, r) : 0;
            if (k == 0 && cc == 0) continue;
            const int px0 = int(c * scale_), px1 = std::max(px0, int((c + 1) * scale_) - 1);
            for (int py = py0; py <= std::min(py1, img_.height - 1); ++py)
                for (int px = px0; px <= std::min(px1, img_.width - 1); ++px)
                {
                    const std::size_t i = std::size_t(py) * img_.width + px;
                    rank[i] = std::max(rank[i], k);
                    if (cc) cost[i] = std::max(cost[i], cc);
                }
        }
    }
    for (std::size_t i = 0; i < rank.size(); ++i)
    {
        const std::uint8_t v = rank[i] == 2 ? 0 : rank[i] == 1 ? 190 : 255;
        img_.data[3 * i] = img_.data[3 * i + 1] = img_.data[3 * i + 2] = v;
        if (rank[i] == 0 && !cost.empty() && cost[i])
        {
            // white towards kCostColour as the cost rises to 252
            const double a = 0.85 * cost[i] / 252.0;
            for (int ch = 0; ch < 3; ++ch)
                img_.data[3 * i + ch] = std::uint8_t(std::lround(255.0 * (1.0 - a) + kCostColour[ch] * a));
        }
    }
}

double MapCanvas::toPx(double x) const { return grid_.worldToMapU(x) * scale_; }
double MapCanvas::toPy(double y) const { return (grid_.height() - grid_.worldToMapV(y)) * scale_; }

void MapCanvas::pixel(int px, int py, const Rgb &c)
{
    if (px < 0 || py < 0 || px >= img_.width || py >= img_.height) return;
    std::uint8_t *p = img_.px(px, py);
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
}

void MapCanvas::line(double x0, double y0, double x1, double y1, const Rgb &c, int thickness)
{
    const double len = std::hypot(x1 - x0, y1 - y0);
    const int n = std::max(1, int(std::ceil(len * 2)));
    const int h = std::max(0, thickness / 2);
    for (int i = 0; i <= n; ++i)
    {
        const double t = double(i) / n;
        const int px = int(std::floor(x0 + t * (x1 - x0))), py = int(std::floor(y0 + t * (y1 - y0)));
        for (int dy = -h; dy <= h; ++dy)
            for (int dx = -h; dx <= h; ++dx) pixel(px + dx, py + dy, c);
    }
}

void MapCanvas::polyline(const std::vector<std::pair<double, double>> &pts, const Rgb &colour, int thickness)
{
    for (std::size_t i = 1; i < pts.size(); ++i)
        line(toPx(pts[i - 1].first), toPy(pts[i - 1].second), toPx(pts[i].first), toPy(pts[i].second), colour,
             thickness);
    if (pts.size() == 1) disc(pts[0].first, pts[0].second, thickness, colour);
}

void MapCanvas::polygon(const std::vector<std::pair<double, double>> &pts, const Rgb &colour)
{
    if (pts.empty()) return;
    auto closed = pts;
    closed.push_back(pts.front());
    polyline(closed, colour, 1);
}

void MapCanvas::disc(double x, double y, int radiusPx, const Rgb &colour)
{
    const double cx = toPx(x), cy = toPy(y);
    for (int dy = -radiusPx; dy <= radiusPx; ++dy)
        for (int dx = -radiusPx; dx <= radiusPx; ++dx)
            if (dx * dx + dy * dy <= radiusPx * radiusPx) pixel(int(std::floor(cx)) + dx, int(std::floor(cy)) + dy, colour);
}

void MapCanvas::tintCells(const std::vector<Cell> &cells, const Rgb &colour)
{
    for (const Cell &c : cells)
    {
        const int px0 = int(c.col * scale_), py0 = int(c.row * scale_);
        const int px1 = std::max(px0, int((c.col + 1) * scale_) - 1), py1 = std::max(py0, int((c.row + 1) * scale_) - 1);
        for (int py = py0; py <= py1; ++py)
            for (int px = px0; px <= px1; ++px)
            {
                if (px < 0 || py < 0 || px >= img_.width || py >= img_.height) continue;
                std::uint8_t *p = img_.px(px, py);
                if (p[0] == 255 && p[1] == 255 && p[2] == 255) pixel(px, py, colour);  // only on free space
            }
    }
}

}  // namespace gridcar
