#include "collision/detail/ExactTiles.h"

#include "collision/detail/FclShapes.h"

#include <algorithm>
#include <cmath>
#include <new>

#include <fcl/broadphase/default_broadphase_callbacks.h>

namespace gridcar
{
using detail::makeBox;

FootprintChecker::ExactTiles::ExactTiles(const OccupancyGrid &g, double wall)
{
    tilesX = (g.width() + kTile - 1) / kTile;
    tilesY = (g.height() + kTile - 1) / kTile;
    tiles = std::make_unique<Tile[]>(std::size_t(tilesX) * std::size_t(tilesY));
    const double mx0 = g.originX(), my0 = g.originY(), mx1 = mx0 + g.sizeX(), my1 = my0 + g.sizeY();
    walls.push_back(makeBox(mx0 - wall / 2, (my0 + my1) / 2, wall, g.sizeY() + 2 * wall));
    walls.push_back(makeBox(mx1 + wall / 2, (my0 + my1) / 2, wall, g.sizeY() + 2 * wall));
    walls.push_back(makeBox((mx0 + mx1) / 2, my0 - wall / 2, g.sizeX() + 2 * wall, wall));
    walls.push_back(makeBox((mx0 + mx1) / 2, my1 + wall / 2, g.sizeX() + 2 * wall, wall));
    wallManager = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
    std::vector<fcl::CollisionObjectd *> raw;
    for (auto &o : walls) raw.push_back(o.get());
    wallManager->registerObjects(raw);
    wallManager->setup();
}

namespace
{
struct Run
{
    int c0, c1, r0, r1;
};

/// Obstacle boundary cells (blocked cells with a non-blocked 4-neighbour inside the map) of
/// the window [c0, c1) x [r0, r1), merged into rectangles: runs along a row, stacked where
/// the next row has a run of the same extent.
std::vector<Run> boundaryRuns(const OccupancyGrid &g, int cBegin, int cEnd, int rBegin, int rEnd)
{
    const int W = g.width(), H = g.height();
    auto boundary = [&](int c, int r) {
        if (!g.isBlocked(c, r)) return false;
        return (c > 0 && !g.isBlocked(c - 1, r)) || (c + 1 < W && !g.isBlocked(c + 1, r)) ||
               (r > 0 && !g.isBlocked(c, r - 1)) || (r + 1 < H && !g.isBlocked(c, r + 1));
    };
    std::vector<Run> done, open, rowRuns, next;  // open: runs that may still grow downwards
    for (int r = rBegin; r < rEnd; ++r)
    {
        rowRuns.clear();
        for (int c = cBegin; c < cEnd;)
        {
            if (!boundary(c, r))
            {
                ++c;
                continue;
            }
            int e = c;
            while (e + 1 < cEnd && boundary(e + 1, r)) ++e;
            rowRuns.push_back({c, e, r, r});
            c = e + 1;
        }
        // merge with open runs of the same extent ending on the previous row (both sorted by c0)
        next.clear();
        std::size_t k = 0;
        for (Run &rr : rowRuns)
        {
            while (k < open.size() && open[k].c0 < rr.c0) done.push_back(open[k++]);
            if (k < open.size() && open[k].c0 == rr.c0 && open[k].c1 == rr.c1)
            {
                Run m = open[k++];
                m.r1 = r;
                next.push_back(m);
            }
            else
                next.push_back(rr);
        }
        while (k < open.size()) done.push_back(open[k++]);
        open.swap(next);
    }
    done.insert(done.end(), open.begin(), open.end());
    return done;
}
}  // namespace

const FootprintChecker::ExactTiles::Tile &FootprintChecker::ExactTiles::tile(const OccupancyGrid &g, int tx, int ty)
{
    Tile &tile = tiles[std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx)];
    std::call_once(tile.once, [&] {
        const int c0 = tx * kTile, r0 = ty * kTile;
        const std::vector<Run> runs =
            boundaryRuns(g, c0, std::min(g.width(), c0 + kTile), r0, std::min(g.height(), r0 + kTile));
        if (runs.empty()) return;
        const double res = g.resolution();
        std::vector<fcl::CollisionObjectd *> raw;
        for (const Run &run : runs)
        {
            const double x0 = g.originX() + run.c0 * res, x1 = g.originX() + (run.c1 + 1) * res;
            const double yTop = g.cellCenterY(run.r0) + res / 2, yBot = g.cellCenterY(run.r1) - res / 2;
            tile.objects.push_back(makeBox((x0 + x1) / 2, (yTop + yBot) / 2, x1 - x0, yTop - yBot));
            raw.push_back(tile.objects.back().get());
        }
        tile.manager = std::make_unique<fcl::DynamicAABBTreeCollisionManagerd>();
        tile.manager->registerObjects(raw);
        tile.manager->setup();
    });
    return tile;
}

void FootprintChecker::ExactTiles::reset(const CellWindow &cells)
{
    if (cells.empty()) return;
    for (int ty = cells.row0 / kTile; ty <= cells.row1 / kTile; ++ty)
        for (int tx = cells.col0 / kTile; tx <= cells.col1 / kTile; ++tx)
        {
            Tile &t = tiles[std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx)];
            t.~Tile();  // (a once_flag is made anew, not reset)
            new (&t) Tile();
        }
}

bool FootprintChecker::collidesExact(fcl::CollisionObjectd *o) const
{
    {
        fcl::DefaultCollisionData<double> data;
        exact_->wallManager->collide(o, &data, fcl::DefaultCollisionFunction<double>);
        if (data.result.isCollision()) return true;
    }
    const fcl::AABBd &bb = o->getAABB();
    const OccupancyGrid &g = *grid_;
    const double res = g.resolution();
    // the cells under the object's box, a cell more each way, clamped to the map
    auto colOf = [&](double x) {
        const double c = std::floor((x - g.originX()) / res);
        return int(std::clamp(c, -1.0, double(g.width())));
    };
    auto rowOf = [&](double y) {  // rows count down from the top
        const double r = double(g.height() - 1) - std::floor((y - g.originY()) / res);
        return int(std::clamp(r, -1.0, double(g.height())));
    };
    const int cA = std::max(0, colOf(bb.min_[0]) - 1), cB = std::min(g.width() - 1, colOf(bb.max_[0]) + 1);
    const int rA = std::max(0, rowOf(bb.max_[1]) - 1), rB = std::min(g.height() - 1, rowOf(bb.min_[1]) + 1);
    if (cA > cB || rA > rB) return false;
    for (int ty = rA / ExactTiles::kTile; ty <= rB / ExactTiles::kTile; ++ty)
        for (int tx = cA / ExactTiles::kTile; tx <= cB / ExactTiles::kTile; ++tx)
        {
            const ExactTiles::Tile &tile = exact_->tile(g, tx, ty);
            if (!tile.manager) continue;
            fcl::DefaultCollisionData<double> data;
            tile.manager->collide(o, &data, fcl::DefaultCollisionFunction<double>);
            if (data.result.isCollision()) return true;
        }
    return false;
}

std::size_t FootprintChecker::obstacleBoxCount() const
{
    std::size_t n = 0;
    if (!exact_) return n;  // a point vehicle: its exact check reads the grid
    const OccupancyGrid &g = *grid_;
    for (int ty = 0; ty < exact_->tilesY; ++ty)
        for (int tx = 0; tx < exact_->tilesX; ++tx)
        {
            const int c0 = tx * ExactTiles::kTile, r0 = ty * ExactTiles::kTile;
            n += boundaryRuns(g, c0, std::min(g.width(), c0 + ExactTiles::kTile), r0,
                              std::min(g.height(), r0 + ExactTiles::kTile))
                     .size();
        }
    return n;
}

}  // namespace gridcar
