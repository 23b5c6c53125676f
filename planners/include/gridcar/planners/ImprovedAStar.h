#pragma once
/// @file ImprovedAStar.h
/// @brief Paper I's improved A* on the shared search core.

#include "gridcar/path/PostProcess.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include <string>

namespace gridcar
{
/**
 * @brief Improved A* for a car-like vehicle (paper I): curvature-limited lattice, arc
 * heuristic, body-contour cost, obstacle-distance cost, turning-point adjustment and quadratic
 * Bezier smoothing.
 *
 * **Lattice** (`lattice`): `car` (default) searches the car lattice (search/CarLattice.h): its
 * own cell size (`lattice_cell`, automatic by default), 8 or 16 headings (`headings`, default
 * 16; paper I's 8 directions with 8), primitives of curvature
 * 0 or 1 / (1.01 R_min), footprint certified along every primitive, the obstacle-aware
 * heuristic, and a Dubins curve into the exact goal: its paths are drivable as searched, so
 * `smooth` does not apply. `grid` is the lattice described next, on the map's own cells, kept
 * to reproduce paper I's tables.
 *
 * **Grid lattice.** State = (cell, heading of 8, straight run k). A successor keeps the heading or
 * turns it by 45 degrees (never more: a 90-degree corner takes two vertices), and a turn is
 * allowed only after the vehicle has run straight for need(heading) steps since the previous
 * turn, need = ceil(L_turn / step length), L_turn = 2 sin(22.5 deg) / (K_max cos^2(22.5 deg))
 * (= 0.897 R_min) with K_max = tan(phi_max) / wheelbase (eq. 2). That is exactly the leg length
 * for which the symmetric quadratic Bezier round a 45-degree vertex (bezierCorner(), end points
 * at half the leg) has curvature <= K_max, so the searched path is drivable after smoothing, not
 * only the smoothed one (states are interned on discovery, so the lattice size is not bounded
 * by 32-bit indices). The first leg from the start and the last leg into the goal need half
 * of that (the start state counts floor(need / 2) steps already run; a goal is accepted with
 * k >= ceil(need / 2)). A point vehicle (K_max = inf) has need = 0.
 *
 * **Evaluation** (`mode`):
 * - `paper`: f = g' + h (1 + o) + s, g' = g if g < o else 0 (eq. 4-5); g the path length.
 *   Since g exceeds o after a step or two, this is in effect a greedy best-first search on
 *   h (1 + o): few expansions, no optimality. Closed states are not reopened.
 * - `integral`: g = integral of (1 + o) along the path (trapezoid per step: length x
 *   (1 + (o(a) + o(b)) / 2), the cost of ObstacleDistanceObjective + path length), f = g + h.
 *   Optimal for that cost on the lattice when h is admissible.
 *
 * **Heuristic** (`heuristic`): `arc` = d phi_max / sin(phi_max) (eq. 6-7, 1.086 d at 40 deg),
 * `euclidean` = d, `octile` (8-connected lattice distance), `auto` (default) = arc in paper
 * mode, octile in integral mode. The arc heuristic is NOT admissible in general: wherever a
 * nearly straight path to the goal exists the true remaining length is below 1.086 d. It is a
 * lower bound only where the remaining path must bend by at least phi_max on each side of the
 * chord. In integral mode, since arc <= 1.086 x euclidean <= 1.086 x the true cost, it gives a
 * solution within phi_max / sin(phi_max) of the optimum.
 *
 * **Body contour s(n)** (`contour`): `fcl` (default) = the swept FCL footprint check of every
 * move (GridPlanner::moveValid); `points` = paper I's detection points at D/2 round the cell
 * centre (FootprintChecker::isValidDetectionPoints), cheaper, blind to the car's length.
 *
 * **Obstacle cost o(n)** (`obstacle_cost`): `inverse` = delta / d_min (eq. 8) with d_min the
 * distance field's d_O at the cell (m); `voronoi` = delta x Dolgov's Voronoi field rho_V in
 * [0, 1] (then delta is a plain gain). `delta` (default 1 m): the paper gives no value.
 *
 * **Post-processing** (`smooth`, default true): smoothPath() (turning points, adjustment under
 * K_max, Bezier) replaces the lattice path in the solution; lastSmoothing() reports it,
 * its time separately from the search.
 *
 * @par External documentation
 * Paper I: Yang Yao et al., "Research on intelligent vehicle path planning based on improved A*
 * algorithm", 2020, sections 3.1-3.5.
 */
/// improved A*'s parameters (see ImprovedAStar).
struct ImprovedAStarParams
{
    bool paperMode{true};          ///< `mode` = paper (else integral)
    bool carLattice{true};         ///< `lattice` = car (else grid)
    std::string heuristic{"auto"}; ///< `heuristic` (grid lattice): auto, arc, euclidean, octile
    double delta{1.0};             ///< `delta`, the obstacle-cost gain
    bool voronoi{false};           ///< `obstacle_cost` = voronoi (else inverse)
    bool points{false};            ///< `contour` = points (else fcl; grid lattice)
    bool smooth{true};             ///< `smooth` (grid lattice)
};

class ImprovedAStar : public GridPlanner
{
public:
    explicit ImprovedAStar(const ompl::base::SpaceInformationPtr &si);
    ~ImprovedAStar() override;

    void setup() override;
    void clear() override;
    /// improved A*'s own parameters.
    const ImprovedAStarParams &improvedParams() const { return ip_; }

    std::string mode() const { return ip_.paperMode ? "paper" : "integral"; }
    void setMode(const std::string &m);
    std::string heuristic() const { return ip_.heuristic; }
    void setHeuristic(const std::string &h);
    double delta() const { return ip_.delta; }
    void setDelta(double d);
    std::string obstacleCost() const { return ip_.voronoi ? "voronoi" : "inverse"; }
    void setObstacleCost(const std::string &c);
    std::string contour() const { return ip_.points ? "points" : "fcl"; }
    void setContour(const std::string &c);
    bool smooth() const { return ip_.smooth; }
    void setSmooth(bool s)
    {
        ip_.smooth = s;
        parameterSet("smooth");
    }
    std::string lattice() const { return ip_.carLattice ? "car" : "grid"; }
    void setLattice(const std::string &l);
    bool usesCarLattice() const override { return ip_.carLattice; }
    /// heuristic, smooth and contour are the grid search's (paper I's section 3), refused on
    /// the car lattice, with allow_corner_cutting.
    std::vector<std::string> gridLatticeOnlyParams() const override
    {
        return {"allow_corner_cutting", "heuristic", "smooth", "contour"};
    }

    /// Paper I's evaluation, eq. 4-5: f = g' + h (1 + o) + s with g' = g if g < o, else 0;
    /// s = 0 (successors with s = infinity are never generated).
    static double paperPriority(double g, double h, double o) { return (g >= o ? 0.0 : g) + h * (1.0 + o); }
    /// Straight steps needed before a turn, for straight (0) and diagonal (1) headings.
    int stepsBeforeTurn(int diagonal) const { return need_[diagonal ? 1 : 0]; }
    /// o(n) at a cell (after setup()).
    double obstacleCostAt(int col, int row) const;
    /// o(n) at a world pose: delta / d_O (or delta rho_V) from the map's distance field; with
    /// another validity checker delta / its clearance() if it computes one, else 0.
    double obstacleCostAtPose(const Pose2 &p) const;
    /// Heuristic value from a cell to the goal cell, metres (after setup(), in the current mode).
    double heuristicAt(int col, int row, int goalCol, int goalRow) const;
    /// The last solve()'s report with paper I's smoothing (on the grid lattice).
    PlannerReport lastReport() const override;
    /// Post-processing report of the last solve() (empty when smooth = false).
    const SmoothingResult &lastSmoothing() const
    {
        static const SmoothingResult none;
        return ip_.carLattice ? none : lastSmoothing_;
    }
    /// The lattice path of the last solve() before post-processing (world poses).
    const std::vector<Pose2> &lastLatticePath() const { return latticePath_; }
    /// The path before smoothing (world poses; empty when nothing was smoothed).
    const std::vector<Pose2> &lastRawPath() const
    {
        static const std::vector<Pose2> none;
        return !ip_.carLattice && ip_.smooth && !lastSmoothing_.path.empty() ? latticePath_ : none;
    }

protected:
    std::unique_ptr<GridNodes> makeGridNodes() override;
    bool postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc) override;
    std::unique_ptr<LatticeCostModel> carCost() const override;

private:
    friend struct ImprovedExpander;
    friend class ImprovedNodes;
    mutable ompl::base::State *obstacleScratch_{nullptr};
    ImprovedAStarParams ip_;
    int need_[2]{0, 0};
    int runStates_{1};      ///< K: values of the straight-run counter (0 .. K-1)
    double arcFactor_{1.0}; ///< phi_max / sin(phi_max)
    int hKind_{0};          ///< 0 arc, 1 euclidean, 2 octile (resolved from ip_.heuristic and mode)
    /// Lattice key of a state, ((cell * 8 + heading) * K + run), and back.
    struct Key
    {
        std::uint64_t width, runs;
        std::uint64_t of(int c, int r, int d, int k) const
        {
            return ((std::uint64_t(r) * width + std::uint64_t(c)) * 8 + std::uint64_t(d)) * runs + std::uint64_t(k);
        }
        void split(std::uint64_t key, int &c, int &r, int &d, int &k) const
        {
            k = int(key % runs);
            const std::uint64_t cd = key / runs;
            d = int(cd % 8);
            c = int((cd / 8) % width);
            r = int((cd / 8) / width);
        }
    };
    Key keyCodec() const;
    /// Lattice key ((cell * 8 + heading) * K + run) of a state; search states are compact ids
    /// handed out in order of discovery (the lattice of a 0.05 m map exceeds 2^32 keys).
    SmoothingResult lastSmoothing_;
    std::vector<Pose2> latticePath_;
};

}  // namespace gridcar
