// A simulated range sensor and the working map of what it saw.
#include "gridcar/sim/Sensing.h"

#include "collision/detail/Polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace gridcar
{
WorkingMap::WorkingMap(std::shared_ptr<OccupancyGrid> grid) : grid_(std::move(grid))
{
    if (!grid_) throw std::invalid_argument("WorkingMap needs a map");
}

bool WorkingMap::sensedWithin(double x, double y, double radius) const
{
    const OccupancyGrid &g = *grid_;
    for (const auto &[i, before] : sensed_)
    {
        const int col = int(i % std::size_t(g.width())), row = int(i / std::size_t(g.width()));
        if (std::hypot(g.cellCenterX(col) - x, g.cellCenterY(row) - y) <= radius) return true;
    }
    return false;
}

namespace
{
/// The bounding window of changed cells.
void grow(CellWindow &w, int col, int row)
{
    if (w.empty())
    {
        w = {col, row, col, row};
        return;
    }
    w.col0 = std::min(w.col0, col), w.col1 = std::max(w.col1, col);
    w.row0 = std::min(w.row0, row), w.row1 = std::max(w.row1, row);
}

using detail::Pt;
}  // namespace

void WorkingMap::clearUnder(const std::vector<Pt> &body, CellWindow &changed)
{
    if (body.size() < 3 || sensed_.empty()) return;
    // the outline counter-clockwise in triangles: a cell overlaps the body where it meets one
    std::vector<Pt> ccw = body;
    double area = 0.0;
    for (std::size_t i = 0, j = ccw.size() - 1; i < ccw.size(); j = i++) area += ccw[j][0] * ccw[i][1] - ccw[i][0] * ccw[j][1];
    if (area < 0) std::reverse(ccw.begin(), ccw.end());
    const std::vector<detail::Tri> tris = detail::triangulate(std::move(ccw));
    OccupancyGrid &g = *grid_;
    double x0 = body[0][0], x1 = x0, y0 = body[0][1], y1 = y0;
    for (const Pt &p : body) x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    const Cell a = g.worldToCell(x0, y1), b = g.worldToCell(x1, y0);
    const double h = 0.5 * g.resolution();
    for (int row = std::max(0, a.row); row <= std::min(g.height() - 1, b.row); ++row)
        for (int col = std::max(0, a.col); col <= std::min(g.width() - 1, b.col); ++col)
        {
            const auto m = sensed_.find(g.index(col, row));
            if (m == sensed_.end()) continue;
            const double cx = g.cellCenterX(col), cy = g.cellCenterY(row);
            if (std::none_of(tris.begin(), tris.end(), [&](const detail::Tri &t) { return detail::triangleMeetsSquare(t, cx, cy, h); }))
                continue;
            g.set(col, row, m->second);
            sensed_.erase(m);
            grow(changed, col, row);
        }
}

CellWindow WorkingMap::scan(const OccupancyGrid &truth, const Scenario &world, double t, double x, double y,
                            const RangeSensorParams &sensor, const std::vector<Pt> *body)
{
    OccupancyGrid &g = *grid_;
    if (!truth.sameFrame(g))
        throw std::invalid_argument("WorkingMap::scan: the true map must have the working map's size, resolution and origin");
    if (!(sensor.range > 0) || sensor.beams < 1 || !std::isfinite(sensor.range))
        throw std::invalid_argument("range sensor: range must be > 0 and beams >= 1");
    // the obstacles within reach, and which of them stand still
    std::vector<const MovingObstacle *> near;
    std::vector<bool> standing;
    for (const MovingObstacle &o : world.obstacles)
        if (o.distanceFrom(x, y, t) <= sensor.range)
        {
            near.push_back(&o);
            const double w = sensor.stationaryWindow;
            standing.push_back(std::hypot(o.velocityEstimate(t, w, 0), o.velocityEstimate(t, w, 1)) < sensor.stationarySpeed);
        }
    const double res = g.resolution(), h = 0.5 * res;
    CellWindow changed{0, 0, -1, -1};
    for (int b = 0; b < sensor.beams; ++b)
    {
        const double a = 2.0 * M_PI * b / sensor.beams, c = std::cos(a), s = std::sin(a);
        for (double r = h; r <= sensor.range; r += h)
        {
            const double px = x + r * c, py = y + r * s;
            const Cell cell = truth.worldToCell(px, py);
            if (!truth.inBounds(cell.col, cell.row)) break;
            const std::size_t i = g.index(cell.col, cell.row);
            int hit = -1;  // -2: the true map; k >= 0: near[k]
            if (truth.at(cell.col, cell.row) == CellState::Occupied)
                hit = -2;
            else
                for (std::size_t k = 0; k < near.size() && hit == -1; ++k)
                    if (near[k]->distanceFrom(px, py, t) <= 0.0) hit = int(k);
            if (hit != -1)
            {
                if ((hit == -2 || standing[std::size_t(hit)]) && g.at(cell.col, cell.row) != CellState::Occupied)
                {
                    sensed_.emplace(i, g.at(cell.col, cell.row));
                    g.set(cell.col, cell.row, CellState::Occupied);
                    grow(changed, cell.col, cell.row);
                }
                break;
            }
            if (sensed_.empty()) continue;
            const auto m = sensed_.find(i);
            if (m == sensed_.end()) continue;
            // seen through: free again when no obstacle is near the cell's centre
            const double cx = g.cellCenterX(cell.col), cy = g.cellCenterY(cell.row);
            bool clear = true;
            for (const MovingObstacle *o : near) clear = clear && o->distanceFrom(cx, cy, t) > 0.75 * res;
            if (!clear) continue;
            g.set(cell.col, cell.row, m->second);
            sensed_.erase(m);
            grow(changed, cell.col, cell.row);
        }
    }
    if (body) clearUnder(*body, changed);
    return changed;
}

}  // namespace gridcar
