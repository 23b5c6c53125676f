// Curve benchmark of the issue "trustworthy under real use": gridcar's Dubins / Reeds-Shepp curve
// code (include/gridcar/curves/CarCurves.h) against OMPL 1.5.2's, (1) time per shortest-curve
// length over seeded random pose pairs, with the largest length difference, and (2) the stress
// scenario that aborted: RRT, RRT* and BIT* round a wall on a Dubins space, N runs each, every
// run in a child process so that an abort inside OMPL's assertions is counted, not fatal;
// once on OMPL's own DubinsStateSpace, once on gridcar::DubinsSpace. Output: Markdown on
// stdout, progress on stderr. See docs/reliability.md and docs/performance.md.
#include "gridcar/curves/CarCurves.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/spaces/CarSpaces.h"
#include "gridcar/spaces/CurveSpaces.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <CLI/CLI.hpp>
#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace gridcar;
using Clock = std::chrono::steady_clock;

namespace
{
struct Timing
{
    double oursNs{0}, omplNs{0}, worstDiff{0};
};

template <class OmplSpace>
Timing timeLengths(CarCurve (*ours)(const Pose2 &, const Pose2 &, double), int pairs, unsigned seed)
{
    auto space = std::make_shared<OmplSpace>(1.0);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-8.0, 8.0), yaw(-M_PI, M_PI);
    std::vector<Pose2> a(static_cast<std::size_t>(pairs)), b(static_cast<std::size_t>(pairs));
    for (int i = 0; i < pairs; ++i)
    {
        a[std::size_t(i)] = {pos(rng), pos(rng), yaw(rng)};
        b[std::size_t(i)] = {pos(rng), pos(rng), yaw(rng)};
    }
    std::vector<double> mine(static_cast<std::size_t>(pairs)), theirs(static_cast<std::size_t>(pairs));
    auto t0 = Clock::now();
    for (int i = 0; i < pairs; ++i) mine[std::size_t(i)] = ours(a[std::size_t(i)], b[std::size_t(i)], 1.0).length;
    const double tOurs = std::chrono::duration<double>(Clock::now() - t0).count();
    ompl::base::ScopedState<ompl::base::SE2StateSpace> sa(space), sb(space);
    t0 = Clock::now();
    for (int i = 0; i < pairs; ++i)
    {
        sa->setXY(a[std::size_t(i)].x, a[std::size_t(i)].y);
        sa->setYaw(a[std::size_t(i)].yaw);
        sb->setXY(b[std::size_t(i)].x, b[std::size_t(i)].y);
        sb->setYaw(b[std::size_t(i)].yaw);
        theirs[std::size_t(i)] = space->distance(sa.get(), sb.get());
    }
    const double tOmpl = std::chrono::duration<double>(Clock::now() - t0).count();
    Timing t;
    t.oursNs = 1e9 * tOurs / pairs;
    t.omplNs = 1e9 * tOmpl / pairs;
    for (int i = 0; i < pairs; ++i) t.worstDiff = std::max(t.worstDiff, std::abs(mine[std::size_t(i)] - theirs[std::size_t(i)]));
    return t;
}

/// 60 m x 40 m at 0.2 m, free but for a wall at x = 30 m from y = 0 to y = 28 m.
std::shared_ptr<OccupancyGrid> wallMap()
{
    auto g = std::make_shared<OccupancyGrid>(300, 200, 0.2, CellState::Free);
    for (int r = 60; r < 200; ++r)
        for (int c = 150; c < 153; ++c) g->set(c, r, CellState::Occupied);
    return g;
}

/// One run round the wall, in this process: 0 exact, 1 not exact.
int oneRun(const std::string &planner, bool omplSpace, double limit)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    SetupOptions o;
    o.space = SpaceKind::Dubins;
    GridSetup s = makeGridSetup(wallMap(), VehicleParams::preset("paper-i"), o);
    if (omplSpace)
    {
        // the same set-up on OMPL's own DubinsStateSpace (its distance / interpolate code)
        const double r = s.checker->vehicle().minTurningRadius();
        auto space = std::make_shared<ompl::base::DubinsStateSpace>(r);
        space->setBounds(s.space->getBounds());
        s.ss = std::make_shared<ompl::geometric::SimpleSetup>(space);
        const auto &si = s.ss->getSpaceInformation();
        si->setStateValidityChecker(std::make_shared<FootprintValidityChecker>(si, s.checker));
        si->setMotionValidator(std::make_shared<CurveMotionValidator>(si, s.checker, r, 0.5 * s.grid->resolution()));
        si->setStateValidityCheckingResolution(0.5 * s.grid->resolution() / space->getMaximumExtent());
    }
    auto p = configurePlanner(s.ss->getSpaceInformation(), {planner, {}, false, false});
    const QueryResult q = runQuery(s, p, {10, 10, 0}, {50, 10, 0}, limit);
    return q.status == ompl::base::PlannerStatus::EXACT_SOLUTION ? 0 : 1;
}

struct Stress
{
    int runs{0}, exact{0}, aborted{0};
};

Stress stress(const std::string &planner, bool omplSpace, int runs, double limit, unsigned seed)
{
    Stress st;
    for (int i = 0; i < runs; ++i)
    {
        std::fflush(nullptr);
        const pid_t pid = fork();
        if (pid == 0)
        {
            ompl::RNG::setSeed(seed + unsigned(i));
            _exit(oneRun(planner, omplSpace, limit));
        }
        int status = 0;
        waitpid(pid, &status, 0);
        ++st.runs;
        if (WIFSIGNALED(status)) ++st.aborted;
        else if (WIFEXITED(status) && WEXITSTATUS(status) == 0) ++st.exact;
    }
    return st;
}
}  // namespace

int main(int argc, char **argv)
{
    CLI::App app{"bench_curves: gridcar's Dubins / Reeds-Shepp curves against OMPL's: speed, and the abort stress"};
    int pairs = 1000000, runs = 100;
    double limit = 0.1;
    unsigned seed = 1;
    app.add_option("--pairs", pairs, "random pose pairs for the timing")->check(CLI::Range(1, 100000000));
    app.add_option("--runs", runs, "runs per planner and space in the stress scenario")->check(CLI::Range(0, 100000));
    app.add_option("--time-limit", limit, "seconds per stress run")->check(CLI::Range(0.001, 60.0));
    app.add_option("--seed", seed, "first seed (OMPL's, one per run)");
    CLI11_PARSE(app, argc, argv);

    std::fprintf(stderr, "timing %d pose pairs\n", pairs);
    const Timing d = timeLengths<ompl::base::DubinsStateSpace>(dubinsCurve, pairs, seed);
    const Timing r = timeLengths<ompl::base::ReedsSheppStateSpace>(reedsSheppCurve, pairs, seed);
    std::printf("## Shortest-curve length, %d seeded random pose pairs (unit radius, positions in [-8, 8]^2)\n\n", pairs);
    std::printf("| curve | gridcar ns / pair | OMPL ns / pair | ratio | largest length difference |\n|---|---:|---:|---:|---:|\n");
    std::printf("| Dubins | %.0f | %.0f | %.2f | %.1e |\n", d.oursNs, d.omplNs, d.oursNs / d.omplNs, d.worstDiff);
    std::printf("| Reeds-Shepp | %.0f | %.0f | %.2f | %.1e |\n\n", r.oursNs, r.omplNs, r.oursNs / r.omplNs, r.worstDiff);

    std::printf("## RRT, RRT* and BIT* round a wall on a Dubins space, %d runs each, %.2f s, one process per run\n\n", runs, limit);
    std::printf("| planner | space | runs | aborted | exact |\n|---|---|---:|---:|---:|\n");
    for (const char *planner : {"rrt", "rrtstar", "bitstar"})
        for (bool omplSpace : {true, false})
        {
            const Stress st = stress(planner, omplSpace, runs, limit, seed);
            const char *space = omplSpace ? "OMPL's DubinsStateSpace" : "gridcar::DubinsSpace";
            std::fprintf(stderr, "%-8s %-24s %d runs, %d aborted, %d exact\n", planner, space, st.runs, st.aborted, st.exact);
            std::printf("| %s | %s | %d | %d | %d |\n", planner, space, st.runs, st.aborted, st.exact);
            std::fflush(stdout);
        }
    return 0;
}
