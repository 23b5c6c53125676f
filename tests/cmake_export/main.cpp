#include <gridcar/map/CampusGenerator.h>
#include <gridcar/spaces/Setup.h>

#include <cstdio>
#include <memory>

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
    for (int r = 0; r < grid->height(); r += 10)
        for (int c = 0; c < grid->width(); c += 10, ++total)
        {
            setup.space->fromLattice({c, r, 0}, s);
            valid += si->isValid(s) ? 1 : 0;
        }
    si->freeState(s);
    std::printf("consumer ok: %d x %d map, %d of %d lattice poses valid\n", grid->width(), grid->height(), valid, total);
    return (valid > 0 && valid < total) ? 0 : 1;
}
