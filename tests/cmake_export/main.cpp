#include <gridcar/map/CampusGenerator.h>
#include <gridcar/query/PlanQuery.h>
#include <gridcar/spaces/Setup.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

int main()
{
    gridcar::CampusParams p;
    p.width = 400;
    p.height = 300;
    p.resolution = 0.5;
    auto grid = std::make_shared<const gridcar::OccupancyGrid>(gridcar::generateCampus(p));
    gridcar::GridSetup setup = gridcar::makeGridSetup(grid, gridcar::VehicleParams::preset("paper-i"));
    // count valid poses on a coarse lattice through OMPL's SpaceInformation
    const auto si = setup.ss->getSpaceInformation();
    ompl::base::State *s = si->allocState();
    int valid = 0, total = 0;
    std::vector<gridcar::Pose2> free;
    for (int r = 0; r < grid->height(); r += 10)
        for (int c = 0; c < grid->width(); c += 10, ++total)
        {
            setup.space->fromLattice({c, r, 0}, s);
            if (!si->isValid(s)) continue;
            ++valid;
            free.push_back({grid->cellCenterX(c), grid->cellCenterY(r), 0.0});
        }
    si->freeState(s);
    std::printf("consumer ok: %d x %d map, %d of %d lattice poses valid\n", grid->width(), grid->height(), valid, total);
    if (valid == 0 || valid == total) return 1;
    // the installed query pipeline: a planner configured by name and settings, one query
    // between two free poses 10-20 m apart, the typed result (status, path, metrics, verdict)
    for (const auto &a : free)
        for (const auto &b : free)
        {
            const double d = std::hypot(b.x - a.x, b.y - a.y);
            if (d < 10 || d > 20) continue;
            gridcar::PlannerConfig config;
            config.name = "corner-astar";
            config.params = {{"heuristic_weight", "1"}};
            const auto planner = gridcar::configurePlanner(si, config);
            const gridcar::QueryResult q = gridcar::runQuery(setup, planner, a, b, 10.0);
            std::printf("query: %s, %zu poses, %.2f m, %s\n", q.status.asString().c_str(), q.path.size(), q.metrics.length,
                        q.drivability.drivable ? "drivable" : q.drivability.reason.c_str());
            return q.status == ompl::base::PlannerStatus::EXACT_SOLUTION && q.metrics.length >= d && q.drivability.drivable ? 0 : 1;
        }
    return 1;
}
