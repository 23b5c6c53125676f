#pragma once
/// @file ImprovedAStar.h
/// @brief Paper I's improved A* on the shared search core.

#include "gridcar/path/PostProcess.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/GridLatticePlanner.h"
#include "gridcar/planners/Settings.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include <string>
#include <vector>

namespace gridcar
{
/**
 * @brief Improved A* for a car-like vehicle (paper I): curvature-limited lattice, arc
 * heuristic, body-contour cost, obstacle-distance cost, turning-point adjustment and quadratic
 * Bezier smoothing.
 *
 * Two planners: ImprovedAStar (`improved-astar`) searches the car lattice
 * (search/CarLattice.h, CarLatticePlanner): its own cell size (`lattice_cell`, automatic by
 * default), 8 or 16 headings (`headings`, default 16; paper I's 8 directions with 8),
 * primitives of curvature 0 or 1 / (1.01 R_min), footprint certified along every primitive,
 * the obstacle-aware heuristic, and a Dubins curve into the exact goal: its paths are drivable
 * as searched. ImprovedAStarGrid (`improved-astar-grid`; the older command line
 * `improved-astar lattice=grid`) is paper I's lattice described next, on the map's own cells,
 * kept to reproduce paper I's tables. Both take `mode`, `delta` and `obstacle_cost`
 * (ImprovedSettings); `heuristic`, `contour` and `smooth` are the grid search's.
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
 * **Evaluation** (`mode`; default `integral` on improved-astar, `paper` on improved-astar-grid):
 * - `paper`: f = g' + h (1 + o) + s, g' = g if g < o else 0 (eq. 4-5); g the path length.
 *   Since g exceeds o after a step or two, this is in effect a greedy best-first search on
 *   h (1 + o): few expansions, no optimality. Closed states are not reopened. On the car
 *   lattice it wanders (loops and detours twice the length where a straight route exists).
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
/// The settings both of paper I's planners take (`mode`, `delta`, `obstacle_cost`; see
/// ImprovedAStar), declared from one table (improvedSettingFields()).
struct ImprovedSettings
{
    /// `mode` = paper (else integral); improved-astar-grid's default, improved-astar's is integral
    bool paperMode{true};
    double delta{1.0};     ///< `delta`, the obstacle-cost gain
    bool voronoi{false};   ///< `obstacle_cost` = voronoi (else inverse)
};

/// The table of ImprovedSettings (Settings.h).
const std::vector<SettingField<ImprovedSettings>> &improvedSettingFields();

/// Paper I's evaluation, eq. 4-5: f = g' + h (1 + o) + s with g' = g if g < o, else 0; s = 0
/// (successors with s = infinity are never generated).
inline double paperPriority(double g, double h, double o) { return (g >= o ? 0.0 : g) + h * (1.0 + o); }

/**
 * @brief Paper I's obstacle cost o(n) (eq. 8) on the world a planner set up: delta / d_O
 * (`inverse`) or delta x Dolgov's Voronoi field (`voronoi`) from the map's distance field; on
 * another validity checker delta / its clearance() if it computes one, else 0.
 */
class ObstacleCost
{
public:
    ObstacleCost() = default;
    ObstacleCost(const ObstacleCost &) = delete;
    ObstacleCost &operator=(const ObstacleCost &) = delete;
    ~ObstacleCost();
    /// The world of @p si (gridcar's @p checker, or null); ompl::Exception naming @p planner
    /// when `voronoi` needs gridcar's checker and has none.
    void setup(const ompl::base::SpaceInformationPtr &si, const FootprintChecker *checker, const std::string &planner);
    /// o(n) at a world pose.
    double atPose(const Pose2 &p) const;
    /// o(n) at a cell of @p space.
    double atCell(const GridSE2StateSpace &space, int col, int row) const;

    ImprovedSettings settings;  ///< as set (the planner's parameters)

private:
    ompl::base::SpaceInformationPtr si_;
    const FootprintChecker *checker_{nullptr};
    mutable ompl::base::State *scratch_{nullptr};
};

/// Paper I's improved A* on the car lattice (see the file's comment above).
class ImprovedAStar : public CarLatticePlanner
{
public:
    explicit ImprovedAStar(const ompl::base::SpaceInformationPtr &si);
    void setup() override;
    const ImprovedSettings &improvedSettings() const { return obstacles_.settings; }
    /// o(n) at a world pose (after setup()).
    double obstacleCostAtPose(const Pose2 &p) const { return obstacles_.atPose(p); }
    /// Its car-lattice paths are final (drivable as searched): it needs no smoothing wrapper.
    PlannerReport lastReport() const override;

protected:
    std::unique_ptr<LatticeCostModel> carCost() const override;

private:
    ObstacleCost obstacles_;
};

/// Paper I's improved A* as published, on the map's cells (see the file's comment above).
class ImprovedAStarGrid : public GridLatticePlanner
{
public:
    explicit ImprovedAStarGrid(const ompl::base::SpaceInformationPtr &si);

    void setup() override;
    void clear() override;
    const ImprovedSettings &improvedSettings() const { return obstacles_.settings; }

    std::string heuristic() const { return heuristic_; }
    /// `heuristic`: auto, arc, euclidean, octile; std::invalid_argument otherwise.
    void setHeuristic(const std::string &h);
    std::string contour() const { return points_ ? "points" : "fcl"; }
    /// `contour`: fcl or points; std::invalid_argument otherwise.
    void setContour(const std::string &c);
    bool smooth() const { return smooth_; }
    void setSmooth(bool s)
    {
        smooth_ = s;
        parameterSet("smooth");
    }

    /// Straight steps needed before a turn, for straight (0) and diagonal (1) headings.
    int stepsBeforeTurn(int diagonal) const { return need_[diagonal ? 1 : 0]; }
    /// o(n) at a cell (after setup()).
    double obstacleCostAt(int col, int row) const { return obstacles_.atCell(*space_, col, row); }
    /// Heuristic value from a cell to the goal cell, metres (after setup(), in the current mode).
    double heuristicAt(int col, int row, int goalCol, int goalRow) const;
    /// The last solve()'s report with paper I's smoothing.
    PlannerReport lastReport() const override;
    /// Post-processing report of the last solve() (empty when smooth = false).
    const SmoothingResult &lastSmoothing() const { return lastSmoothing_; }
    /// The lattice path of the last solve() before post-processing (world poses).
    const std::vector<Pose2> &lastLatticePath() const { return latticePath_; }
    /// The path before smoothing (world poses; empty when nothing was smoothed).
    const std::vector<Pose2> &lastRawPath() const
    {
        static const std::vector<Pose2> none;
        return smooth_ && !lastSmoothing_.path.empty() ? latticePath_ : none;
    }

protected:
    std::unique_ptr<GridNodes> makeGridNodes() override;
    bool postProcess(ompl::geometric::PathGeometric &path, const ompl::base::PlannerTerminationCondition &ptc) override;

private:
    friend struct ImprovedExpander;
    friend class ImprovedNodes;
    ObstacleCost obstacles_;
    std::string heuristic_{"auto"};  ///< `heuristic`: auto, arc, euclidean, octile
    bool points_{false};             ///< `contour` = points (else fcl)
    bool smooth_{true};              ///< `smooth`
    int need_[2]{0, 0};
    int runStates_{1};      ///< K: values of the straight-run counter (0 .. K-1)
    double arcFactor_{1.0}; ///< phi_max / sin(phi_max)
    int hKind_{0};          ///< 0 arc, 1 euclidean, 2 octile (resolved from heuristic_ and mode)
    /// Lattice key of a state, ((cell * 8 + heading) * K + run), and back; search states are
    /// compact ids handed out in order of discovery (the lattice of a 0.05 m map exceeds 2^32 keys).
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
    SmoothingResult lastSmoothing_;
    std::vector<Pose2> latticePath_;
};

}  // namespace gridcar
