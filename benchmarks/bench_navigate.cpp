// The navigation suite of the issue "Driving in a changing world": seeded start / goal pairs on
// the real maps in ../shared (indoor maps with paper C's robot, the Tsudanuma campus with both
// cars). Each pair is planned on the map; then an obstacle the map does not show (an
// axis-aligned box, 1 m to --box-max a side: a pallet in an aisle, a parked car across a lane,
// a closed gate where it spans the way, a dead end where it leaves no way on but back) stands
// across the path at 30-70 % of its length, clear of both ends. gridcar's Navigator drives
// with a range sensor (--range, 360 beams, 5 scans a second) and replans when the path ahead is
// blocked in its working map. Against it: the same pair planned with the box in the map and
// driven (the obstacle known in advance). Each pair is run again with a pedestrian crossing the
// path at a fifth of its length when the vehicle would get there (bench_drive's pedestrian). Every drive's samples are checked against the true
// map and the obstacles independently (the body's corners and its distance-field clearance).
// Output: a Markdown table on stdout, one line per run on stderr. See docs/simulation.md.
#include "gridcar/bench/Quantile.h"
#include "gridcar/bench/RandomPairs.h"
#include "gridcar/query/Navigate.h"

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace gridcar;

namespace
{
struct Area
{
    BenchArea area;
    double boxMax, range;
};

const std::vector<Area> kAreas = {
    {{"willow-garage", "maps/ros/willow_garage/willow-2010-02-18-0.10.yaml", "paper-c-robot", 5, 40}, 3.0, 8.0},
    {{"mit-stata", "maps/ros/mit_stata_basement/stata_basement.yaml", "paper-c-robot", 5, 40}, 3.0, 8.0},
    {{"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-i", 30, 150}, 10.0, 20.0},
    {{"tsudanuma", "maps/ros/tsudanuma_campus/tsudanuma_all.yaml", "paper-c-car", 30, 150}, 10.0, 20.0},
};

struct Options
{
    std::string shared{"../shared"};
    int pairs{10};
    unsigned seed{1};
    double limit{5.0};
    std::vector<std::string> only;
    bool stopToReplan{false};
    std::vector<std::string> params;  ///< NAME=VALUE on corner-astar, in every plan
};

struct Tally
{
    int runs{0}, reached{0}, collided{0}, blockedReported{0}, stuck{0}, other{0}, touched{0};
    std::vector<double> replanSeconds, timeRatio;
    int replans{0}, rolling{0};
};

/// The worst clearance of the drive's samples: the body against the true map (its checker's
/// clearance) and against each obstacle of the scenario (its corners and the obstacle's centre).
double worstClearance(const NavigationResult &r, const FootprintChecker &world, const Scenario &sc)
{
    double worst = 1e9;
    for (const TrajectorySample &s : r.trajectory)
    {
        double d = world.isValid(s.x, s.y, s.yaw) ? world.clearance(s.x, s.y, s.yaw) : -1.0;
        double cx[4], cy[4];
        world.corners(s.x, s.y, s.yaw, cx, cy);
        for (const MovingObstacle &o : sc.obstacles)
        {
            for (int k = 0; k < 4; ++k) d = std::min(d, o.distanceFrom(cx[k], cy[k], s.t));
            double ox, oy;  // the obstacle's centre inside the body (corners all outside it)
            o.positionAt(s.t, ox, oy);
            const double c = std::cos(s.yaw), sn = std::sin(s.yaw), lx = (ox - s.x) * c + (oy - s.y) * sn,
                         ly = -(ox - s.x) * sn + (oy - s.y) * c;
            const VehicleParams &v = world.vehicle();
            if (lx >= -v.rearOverhang && lx <= v.length - v.rearOverhang && std::abs(ly) <= v.width / 2) d = -1.0;
        }
        worst = std::min(worst, d);
    }
    return worst;
}

MovingObstacle boxAt(const Pose2 &c, double a, double b)
{
    MovingObstacle o;
    o.name = "unmapped box";
    o.shape = MovingObstacle::Shape::Box;
    o.sizeX = a, o.sizeY = b;
    o.waypoints = {{c.x, c.y}};
    o.speed = 0.0;
    return o;
}

bool near(const MovingObstacle &o, const Pose2 &p, double reach) { return o.distanceFrom(p.x, p.y, 0.0) < reach; }

void run(const Options &o, const Area &a)
{
    const auto grid = loadAreaMap(o.shared, a.area);
    if (!grid) return;
    const VehicleParams vehicle = VehicleParams::preset(a.area.vehicle);
    GridSetup setup = makeGridSetup(grid, vehicle);
    const PlannerParams params = parsePlannerParams(o.params);
    auto planner = configurePlanner(setup.ss->getSpaceInformation(), {"corner-astar", params, false, false});
    const auto pairs = randomPairs(*setup.checker, o.pairs, o.seed, a.area.lo, a.area.hi);
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> side(1.0, a.boxMax), at(0.3, 0.7);
    Tally tally[2];
    int noDetour = 0, planned = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k)
    {
        const Pose2 s = withFittingYaw(*setup.checker, pairs[k].first), g = pairs[k].second;
        // the box's place and size drawn for every pair, planned or not, so that a pair the
        // first plan misses (a time-limited plan on a loaded machine) leaves the others' boxes
        const double f = at(rng);
        double bx = side(rng), by = side(rng);
        const QueryResult first = runQuery(setup, planner, s, g, o.limit, true);
        if (first.status != ompl::base::PlannerStatus::EXACT_SOLUTION) continue;
        ++planned;
        // the box at 30-70 % of the path, shrunk until it is clear of both ends
        std::vector<double> cum{0.0};
        for (std::size_t i = 1; i < first.path.size(); ++i)
            cum.push_back(cum.back() + std::hypot(first.path[i].x - first.path[i - 1].x, first.path[i].y - first.path[i - 1].y));
        const std::size_t mid = std::size_t(std::lower_bound(cum.begin(), cum.end(), f * cum.back()) - cum.begin());
        const Pose2 c = first.path[std::min(mid, first.path.size() - 1)];
        const double reach = setup.checker->reach() + 1.0;
        MovingObstacle box = boxAt(c, bx, by);
        for (int shrink = 0; shrink < 20 && (near(box, s, reach) || near(box, g, reach)); ++shrink) box = boxAt(c, bx *= 0.8, by *= 0.8);
        if (near(box, s, reach) || near(box, g, reach)) continue;
        // the box known in advance: in the map, planned and driven
        auto known = std::make_shared<OccupancyGrid>(*grid);
        const Cell lo = known->worldToCell(c.x - bx / 2, c.y + by / 2), hi = known->worldToCell(c.x + bx / 2, c.y - by / 2);
        for (int r = std::max(0, lo.row); r <= std::min(known->height() - 1, hi.row); ++r)
            for (int col = std::max(0, lo.col); col <= std::min(known->width() - 1, hi.col); ++col) known->set(col, r, CellState::Occupied);
        GridSetup ks = makeGridSetup(known, vehicle);
        const QueryResult kq = runQuery(ks, configurePlanner(ks.ss->getSpaceInformation(), {"corner-astar", params, false, false}), s, g,
                                        o.limit, true);
        const bool detour = kq.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        double knownTime = NAN;
        if (detour)
        {
            const DriveResult kd = drivePath(kq.path, *ks.checker, Scenario());
            if (kd.outcome == DriveResult::Outcome::Reached) knownTime = kd.drivingTime;
        }
        else
            ++noDetour;
        for (int ped = 0; ped < 2; ++ped)
        {
            Scenario sc;
            sc.obstacles.push_back(box);
            if (ped)  // crossing the path before the box when the vehicle gets there
                sc.obstacles.push_back(crossingPedestrian(first.path, vehicle, std::max(0.2, (reach + 2.0) / cum.back())));
            NavigationOptions no;
            no.planTimeLimit = o.limit;
            no.sensor.range = a.range;
            no.replanRolling = !o.stopToReplan;
            no.planner.params = params;
            const auto t0 = std::chrono::steady_clock::now();
            Navigator nav(grid, vehicle, no);
            const NavigationResult r = nav.run(s, g, true, sc);
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            Tally &t = tally[ped];
            ++t.runs;
            const double worst = worstClearance(r, nav.worldChecker(), sc);
            if (worst <= 0.0 && r.outcome != NavigationResult::Outcome::Collided) ++t.touched;  // counted once
            switch (r.outcome)
            {
                case NavigationResult::Outcome::Reached: ++t.reached; break;
                case NavigationResult::Outcome::Collided: ++t.collided; break;
                case NavigationResult::Outcome::GoalBlocked:
                case NavigationResult::Outcome::NoPath: t.blockedReported += detour ? 0 : 1; t.other += detour ? 1 : 0; break;
                case NavigationResult::Outcome::Stuck: ++t.stuck; break;
                default: ++t.other; break;
            }
            t.replans += r.replans;
            t.rolling += r.rollingReplans;
            t.replanSeconds.insert(t.replanSeconds.end(), r.replanSeconds.begin(), r.replanSeconds.end());
            if (r.outcome == NavigationResult::Outcome::Reached && std::isfinite(knownTime)) t.timeRatio.push_back(r.drivingTime / knownTime);
            std::fprintf(stderr, "%s %s pair %zu%s: --start %.2f,%.2f,%.1f --goal %.2f,%.2f, box %.2f x %.2f m at %.2f,%.2f, %s (%s), "
                                 "%d replans (%d rolling), %d retreats, %.1f s driven (known in advance %.1f s), worst clearance %.2f m, %.1f s wall\n",
                         a.area.name.c_str(), a.area.vehicle.c_str(), k, ped ? " + pedestrian" : "", s.x, s.y, s.yaw * 180 / M_PI, g.x,
                         g.y, bx, by, c.x, c.y,
                         NavigationResult::outcomeName(r.outcome).c_str(), r.reason.c_str(), r.replans, r.rollingReplans, r.retreats, r.drivingTime, knownTime,
                         worst, wall);
        }
    }
    std::printf("| %s | %s | %d | %d |", a.area.name.c_str(), a.area.vehicle.c_str(), planned, noDetour);
    for (const Tally &t : tally)
    {
        const auto q = [&](const std::vector<double> &v, double p, double scale) { return v.empty() ? NAN : scale * quantile(v, p); };
        std::printf(" %d / %d | %d | %d | %d | %d (%d) | %.2f / %.2f |", t.reached + t.blockedReported, t.runs, t.collided + t.touched,
                    t.stuck, t.other, t.replans, t.rolling, q(t.timeRatio, 0.5, 1.0), q(t.timeRatio, 0.9, 1.0));
        if (&t == &tally[0])
            std::printf(" %.0f / %.0f / %.0f |", q(t.replanSeconds, 0.5, 1e3), q(t.replanSeconds, 0.95, 1e3), q(t.replanSeconds, 1.0, 1e3));
    }
    std::printf("\n");
    std::fflush(stdout);
}
}  // namespace

int main(int argc, char **argv)
{
    CLI::App app{"The navigation suite: an obstacle the map does not show across each planned path; gridcar's Navigator "
                 "(range sensor, working map, replanning) against the obstacle known in advance"};
    Options o;
    app.add_option("--shared", o.shared, "The shared folder (maps)")->capture_default_str();
    app.add_option("--pairs", o.pairs, "Start / goal pairs per map and vehicle")->capture_default_str();
    app.add_option("--seed", o.seed, "Seed of the pairs, the boxes and OMPL's random numbers")->capture_default_str();
    app.add_option("--time-limit", o.limit, "Seconds per plan")->capture_default_str();
    app.add_option("--only", o.only, "Only these areas (willow-garage, mit-stata, tsudanuma) or vehicles");
    app.add_option("--param", o.params, "NAME=VALUE set on corner-astar in every plan (repeatable), e.g. safety_margin=0");
    app.add_flag("--stop-to-replan", o.stopToReplan,
                 "Brake to a standstill before every replan (NavigationOptions::replanRolling off: the behaviour before "
                 "replanning while rolling)");
    CLI11_PARSE(app, argc, argv);
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    ompl::RNG::setSeed(o.seed);
    std::printf("| map | vehicle | pairs planned | no detour (box closes the way) | reached or reported blocked | collisions | stuck | "
                "other | replans (while rolling) | driving time / known in advance: median / p90 | replan (update + search) median / p95 / max "
                "(ms) | with a pedestrian: reached or reported | collisions | stuck | other | replans (while rolling) | time ratio median / p90 |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Area &a : kAreas)
    {
        bool wanted = o.only.empty();
        for (const std::string &w : o.only) wanted = wanted || w == a.area.name || w == a.area.vehicle;
        if (wanted) run(o, a);
    }
    return 0;
}
