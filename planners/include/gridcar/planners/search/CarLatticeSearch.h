#pragma once
/// @file CarLatticeSearch.h
/// @brief A* on the car lattice (search/CarLattice.h) through the shared search core: footprint
/// checks of every primitive, the obstacle-aware heuristic, an analytic Dubins shot to the exact
/// goal, and a pluggable cost model (improved A*'s and corner A*'s costs on the same successors).

#include "gridcar/core/Angles.h"
#include "gridcar/planners/search/AStar.h"
#include "gridcar/planners/search/AnalyticExpansion.h"
#include "gridcar/planners/search/CarCollision.h"
#include "gridcar/planners/search/CarGoal.h"
#include "gridcar/planners/search/CarLattice.h"
#include "gridcar/planners/search/CarLatticeSettings.h"
#include "gridcar/planners/search/CurveTable.h"
#include "gridcar/planners/search/ObstacleHeuristic.h"
#include "gridcar/planners/search/TurnHeuristic.h"
#include "gridcar/planners/search/detail/StateInterner.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gridcar
{
class CarLatticeSearch;

/// The cost of driving along the lattice; the search core orders states by g + h unless
/// customPriority().
class LatticeCostModel
{
public:
    virtual ~LatticeCostModel() = default;
    /// Cost of the motion through world poses @p samples (after @p from; the last one is the
    /// end), @p length metres long, turning by @p absTurn radians in total.
    virtual double stepCost(const Pose2 &from, const std::vector<Pose2> &samples, double length,
                            double absTurn) const = 0;
    /// A lower bound of stepCost() per metre driven (the heuristic's distances are scaled by it).
    virtual double minCostPerMetre() const { return 1.0; }
    /// Cost per metre near a pose, for the obstacle-aware heuristic's edges (an edge costs its
    /// length x the smaller weight of its two nodes). Default: minCostPerMetre().
    virtual double nodeWeight(const Pose2 &p) const { (void)p; return minCostPerMetre(); }
    /// True if nodeWeight() varies (the 2D search then weighs its edges).
    virtual bool weighted() const { return false; }
    /// A lower bound of the cost per radian of heading change (beyond the length): the
    /// heuristic adds it times the least turning any forward path to the goal needs.
    virtual double minTurnCostPerRad() const { return 0.0; }
    /// True if the search may bound the turning a route needs (TurnHeuristic) with
    /// minTurnCostPerRad(): corner-astar's `turn_heuristic`. Default: whenever turning costs.
    virtual bool turnBound() const { return minTurnCostPerRad() > 0; }
    /// The cost of a metre where a length (the cusp penalty, metres of the gear change) is
    /// turned into this model's units. Default 1 (costs in metres).
    virtual double costPerMetreOfPenalty() const { return 1.0; }
    /// True if stepCost() depends on the motion's shape alone (its lengths and heading changes
    /// from @p from on), not on where the motion is or which way it points: the search then
    /// computes it once per primitive.
    virtual bool shapeOnly() const { return false; }
    /// Paper I's evaluation: order the open list by priority() instead of g + h.
    virtual bool customPriority() const { return false; }
    virtual double priority(double g, double h, const Pose2 &at) const { (void)at; return g + h; }
};

/// Path length as the cost.
class LengthCost : public LatticeCostModel
{
public:
    double stepCost(const Pose2 &, const std::vector<Pose2> &, double length, double) const override { return length; }
    bool shapeOnly() const override { return true; }
};

/// One query on the car lattice, in world terms: its goal (the CarGoalTerms base, which the
/// search reads through its goal manager CarGoal), its start and its settings.
struct CarLatticeQuery : CarGoalTerms
{
    Pose2 start;
    bool freeStartHeading{false};  ///< start at any lattice heading where the car fits
    /// The settings the search reads as they are: `heuristicWeight` w >= 1 (weighted A*: the
    /// path found costs at most w x the lattice optimum when the heuristic is a lower bound;
    /// larger w, fewer expansions), `reversePenalty` (>= 1, on the cost of a primitive driven
    /// backwards: the primitive set's reverse ones, the reversed segments of the analytic
    /// expansion), `curveHeuristic` (Table: the curve bound read from the lattice's
    /// CurveTable), `costLayerWeight`. A query built by hand searches unweighted A* without a
    /// reversing penalty (CarLatticeSettings::plainSearch()); the planners copy in theirs. What
    /// the settings leave to the vehicle or the map is resolved into the fields below.
    CarLatticeSettings settings{CarLatticeSettings::plainSearch()};
    /// Searched from the goal back to the start (start and goal swapped by the caller, the path
    /// read backwards afterwards): every motion is driven in the other gear than it is searched,
    /// so reversePenalty weighs the primitives and curve segments searched forwards. A manoeuvre
    /// into a tight spot is a manoeuvre out of it read backwards, and getting out is what a
    /// search finds quickly (few ways lead in; from inside, the first free motion leads out).
    bool timeReversed{false};
    /// Where a reversing lattice may drive backwards: from states within this many metres of
    /// the start or the goal position (manoeuvres: turning round, parking, leaving a dead end),
    /// and by analytic curves that start there and reverse no farther than this; < 0:
    /// everywhere (reverse=auto resolves it; reverse=on and the fallback searches leave it < 0).
    double reverseWithin{-1.0};
    /// True if a state at world pose @p p may set off backwards (reverseWithin).
    bool mayReverseAt(const Pose2 &p) const
    {
        const auto near = [&](const Pose2 &e) { return (p.x - e.x) * (p.x - e.x) + (p.y - e.y) * (p.y - e.y) <= reverseWithin * reverseWithin; };
        return reverseWithin < 0 || near(start) || near(goal);
    }
    /// Cost (>= 0, the cost model's unit; settings.cuspPenalty resolved and converted) of a gear change: between a state reached forwards
    /// and a motion backwards, or the other way, and at every cusp of the analytic expansion.
    double cuspPenalty{0.0};
    /// Within this many metres of a goal whose heading must be matched, the heuristic also
    /// takes the Reeds-Shepp (reversing) or Dubins length to the goal pose (CurveBound); 0: not.
    double curveWithin{0.0};
    /// settings.curveHeuristic == Table: that length read from the lattice's CurveTable (nodes
    /// within curveWithin per axis of the reference nodes round the goal; the table kept across
    /// runs) instead of computed at every state; a hybrid lattice (whose states are not nodes)
    /// then has no curve bound.
    bool curveTable() const { return settings.curveHeuristic == CurveHeuristic::Table; }
    /// Motions checked when the search is about to use them (lazyAstar()) rather than when
    /// generated, where that changes nothing but the work (a node lattice, costs known
    /// before the check: the same states closed with the same costs, ties apart).
    bool lazyChecks{true};
    /// With a cost model whose turnBound() holds (corner-astar's corner weights): the search first runs
    /// without the turn bound (TurnHeuristic, a search of its own), and again with it only
    /// after this many expansions; 0: with it from the start.
    std::uint64_t turnBoundAfter{10000};
    /// Only paths that may cost at most this are searched: a motion into a state whose g + h /
    /// heuristicWeight exceeds it is not generated (the safety margin's second search, which
    /// keeps its path only if it is at most 5 % dearer than the first). Infinite: no bound.
    double costBound{std::numeric_limits<double>::infinity()};
    /// CarFamily::solve(): the fallback searches (FallbackSchedule) may run when this one ends
    /// without the goal (false: the safety margin's search, which only looks for a better path).
    bool fallbacks{true};
    /// The search that ran this query last (same start, goal and cost model) for a body inside
    /// this one's (the safety margin's first search): where it laid the same lattice graph over
    /// the same frame, its 2D distances and turn bound hold here too (every path of this body
    /// is one of that body's), and this run reads them, resuming their searches, instead of
    /// searching the 2D graph again; weaker bounds than this body's own (null: its own).
    CarLatticeSearch *boundsFrom{nullptr};
    /// Shared by the runs of one CarFamily query (0: none): a search run again within it from
    /// the same start to the same goal (a probe, a fallback round) resumes its 2D bounds.
    std::uint64_t boundsEpoch{0};
    /// The map the search runs on, for the costs read off it (null: none, as on an OMPL
    /// application's own validity checker): its cost layer and its distance field.
    const FootprintChecker *map{nullptr};
    /// True if the map's cost layer weighs on the motions: the map has one (OccupancyGrid::
    /// cost(), 0..252) and settings.costLayerWeight > 0.
    bool layered() const { return map && settings.costLayerWeight > 0 && map->grid().hasCosts(); }
    /// True if a motion's cost depends on where it is on the map (mapCost() is not 0).
    bool mapCosts() const { return layered() || (map && settings.clearance > 0); }
    /// The map's cost layer value at @p p (0..252).
    double layerAt(const Pose2 &p) const
    {
        const Cell cell = map->grid().worldToCell(p.x, p.y);
        return map->grid().cost(cell.col, cell.row);
    }
    /// The clearance's extra metres per metre at @p p: (1 - room / clearance)^2 where the body's
    /// room (FootprintChecker::freeSlack()) is below the clearance, else 0.
    double nearAt(const Pose2 &p) const
    {
        const double room = std::max(0.0, map->freeSlack(p));
        return room < settings.clearance ? (1 - room / settings.clearance) * (1 - room / settings.clearance) : 0.0;
    }
    /// The extra cost (m) of a motion over @p poses of @p length metres read off the map (the
    /// callers convert it by the cost model's costPerMetreOfPenalty()): with a cost layer,
    /// weight x (mean cost of its poses / 252) x its length; with a clearance, the mean of
    /// nearAt() over its poses x its length.
    double mapCost(const std::vector<Pose2> &poses, double length) const
    {
        if (!mapCosts() || poses.empty()) return 0.0;
        const bool layer = layered(), near = map && settings.clearance > 0;
        double layerSum = 0, nearSum = 0;
        for (const Pose2 &p : poses)
        {
            if (layer) layerSum += layerAt(p);
            if (near) nearSum += nearAt(p);
        }
        const double n = double(poses.size());
        return (settings.costLayerWeight * layerSum / (252.0 * n) + nearSum / n) * length;
    }
    /// The analytic expansion ends the search at once, so with map costs its curve must not
    /// cross costlier ground than the query's start and goal: the search then goes round a
    /// costly band, not through it (measured from the query's start, not the curve's, or a
    /// node just inside the band would shoot through the rest). True when @p poses' mean
    /// cost-layer value exceeds that of both ends + 8, or with a clearance when some pose of
    /// them is nearer an obstacle (nearAt()) than both ends are.
    bool crossesCostlierGround(const std::vector<Pose2> &poses) const
    {
        if (!mapCosts() || poses.empty()) return false;
        if (layered())
        {
            double mean = 0;
            for (const Pose2 &p : poses) mean += layerAt(p);
            if (mean / double(poses.size()) > std::max(layerAt(start), layerAt(goal)) + 8.0) return true;
        }
        if (!(map && settings.clearance > 0)) return false;
        const double ends = std::max(nearAt(start), nearAt(goal));
        return std::any_of(poses.begin(), poses.end(), [&](const Pose2 &p) { return nearAt(p) > ends + 1e-9; });
    }
};

/// What a search on the car lattice found.
struct CarLatticeResult
{
    SearchOutcome outcome{SearchOutcome::Exhausted};
    bool exact{false};          ///< the path ends in the goal
    std::vector<Pose2> path;    ///< dense world poses (spacing <= the lattice's), start first
    double cost{0.0};           ///< of the path, by the cost model
    std::uint64_t expanded{0};
    std::size_t states{0};      ///< lattice states generated
    std::size_t heuristicNodes{0};  ///< 2D nodes the obstacle-aware heuristic closed
    std::size_t turnBoundStates{0};  ///< (node, axis) states the turn bound closed (0: not used)
    int shotsTried{0};
    /// Not empty: the goal was proven unreachable before any search (why, for the user); the
    /// result then has no path (see CarLatticeSearch: fast failure).
    std::string unreachable;
    bool startShutIn{false};  ///< unreachable: the start's free space is the one shut off (else the goal's)
};

/**
 * @brief A* over (node, heading) states of a CarLattice laid over the map with its origin at
 * the start position and its x axis along the start yaw (the start is always a node, whatever
 * its pose); collision is checked against the map's own cells at every sampled pose with the
 * rectangle grown by CarLattice::margin() (so the swept motion is certified), mostly by the
 * distance field's disc cover (FootprintChecker); or, on a SpaceCollision, by the OMPL
 * application's own validity checker at every sampled pose. Where a motion's cost is known
 * before its check (CarLatticeQuery::lazyChecks), a motion is checked only when its entry comes
 * off the open list (lazyAstar(): the same search, most motions never checked).
 *
 * Heuristic: max(Euclidean distance x the cost model's least cost per metre, ObstacleHeuristic
 * distance (edges weighted by the cost model's nodeWeight()) / ratio - seed radius), where ratio >= 1 is the largest ratio of the 2D graph's
 * open-space distance to a primitive's length, measured on the lattice's own primitives. Where
 * the 2D graph does not join start and goal, the Euclidean part alone is used, so the search
 * still returns the explored state nearest the goal (an approximate solution) rather than
 * trusting a relaxation to prove the goal unreachable.
 * Fast failure: where the 2D graph does not join start and goal and the goal is one position
 * (a GoalState, or a PositionGoal within a micrometre, as a goal without a heading is) on gridcar's checker,
 * FootprintChecker::reachability() (the body's inscribed disc over 8-connected cells, a proof for any motion, forwards or backwards, at any
 * resolution) is asked, within 4 M cells; when it proves the ends apart the run returns at once
 * with CarLatticeResult::unreachable saying why, and the planner runs no fallback search (it
 * asks the same before its fallbacks when the 2D graph's relaxation joined the ends).
 * Goal: a node passing inGoal, or a free curve of the lattice's family from the node to the
 * goal (AnalyticExpansion: when it is tried, which curves, the free check). Closed states stay
 * closed (each node keeps the primitive it was first expanded with), as in Hybrid A*. A found
 * path is shortened afterwards by PathShortcut (a post-processor of its own).
 */
class CarLatticeSearch
{
public:
    /// On gridcar's footprint checker (its fast paths).
    CarLatticeSearch(const FootprintChecker &checker, std::shared_ptr<const CarLattice> lattice);
    /// On any collision source (e.g. SpaceCollision: an OMPL application's validity checker).
    CarLatticeSearch(std::shared_ptr<CarCollision> collision, std::shared_ptr<const CarLattice> lattice);
    ~CarLatticeSearch();

    const CarLattice &lattice() const { return *lattice_; }
    /// What the search asks about collisions (the start and goal checks use it too).
    const CarCollision &collision() const { return *col_; }
    /// Largest open-space 2D-graph distance over primitive length (>= 1).
    double heuristicRatio() const { return ratio_; }
    /// Sets its headings on the shared collision model again (a probe's search ran meanwhile).
    void reclaimCollision();
    /// The states the last run's bounds closed: 2D nodes and (node, axis) states of the turn
    /// bound (what reading them through CarLatticeQuery::boundsFrom saves another search).
    std::size_t boundStates() const
    {
        return (h2d_ ? h2d_->closedCount() : 0) + (useTurn_ && turn_ ? turn_->closedCount() : 0);
    }

    CarLatticeResult run(const CarLatticeQuery &q, const LatticeCostModel &cost, const std::function<bool()> &cancelled,
                         std::atomic<std::uint64_t> *progress = nullptr);

    /// The heuristic of the last run() at a node of its lattice at heading h (world pose out).
    double heuristicAt(int i, int j);
    /// The turn bound of the last run at node (i, j), heading h, in @p cost's units (what the
    /// heuristic takes it as, unweighted; for tests); NaN when the run did not use it.
    double turnBoundAt(int i, int j, int h, const LatticeCostModel &cost);
    /// The lattice's CurveTable for the running query's curveWithin, at most 4 Mi entries
    /// (built on first use and kept while the range stays; null on a hybrid lattice).
    const CurveTable *curveTable();
    /// A world pose in the last run()'s lattice frame.
    Pose2 latticePose(const Pose2 &world) const;
    /// World pose of lattice node (i, j) at heading h in the last run()'s frame.
    Pose2 nodePose(int i, int j, int h) const;
    /// World position of lattice node (i, j) in the last run()'s frame (nodePose() without the yaw).
    std::array<double, 2> nodeXY(int i, int j) const
    {
        const double x = i * lattice_->cell(), y = j * lattice_->cell();
        return {ox_ + cphi_ * x - sphi_ * y, oy_ + sphi_ * x + cphi_ * y};
    }
    /// World pose of a state of the last run() (yaw wrapped): its node's, or on a hybrid lattice
    /// the continuous pose it was reached at.
    Pose2 statePose(std::uint32_t s) const { return worldPose(pose_[s]); }
    /// Calls fn(node, parent) for every state the last run() expanded (the start: parent = node).
    void forEachExpanded(const std::function<void(const Pose2 &, const Pose2 &)> &fn) const;
    /// True if the motion from @p from through poses 1..n given by @p poseAt (computed only
    /// where needed) is free: the rectangle grown by the lattice's margin at every pose (see
    /// CarLattice).
    bool curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt) const;
    /// curveFree() with the body grown by @p extra metres more (room a follower needs where a
    /// path is changed after the search).
    bool curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double extra) const;
    /// The lattice's clothoid turns, with which its analytic expansion joins the goal (null:
    /// arcs, or a reversing lattice).
    const ClothoidTurn *clothoidTurns() const { return analytic_->clothoidTurns(); }
    /// The analytic expansion the search tries towards the goal.
    const AnalyticExpansion &analyticExpansion() const { return *analytic_; }

    /// Fast failure (see the class): why the goal of @p q is proven unreachable, or empty
    /// (@p startShutIn: the start's free space is the one shut off). Asked by run() where the
    /// 2D graph does not join the ends, and by the planner before its fallback searches.
    /// The proof visits at most @p maxCells cells (Unknown past them: "").
    static std::string provenUnreachable(const CarLatticeQuery &q, bool &startShutIn,
                                         std::size_t maxCells = std::size_t(1) << 22);

private:
    friend struct CarExpander;
    struct Key
    {
        int i, j, h;
    };
    std::uint64_t pack(int i, int j, int h) const;
    Key unpack(std::uint64_t k) const;
    std::uint32_t intern(int i, int j, int h);
    /// The state of node (i, j, h) if this run has seen it, else StateInterner::kNone.
    std::uint32_t known(int i, int j, int h) const { return states_.find(pack(i, j, h)); }
    bool setFrame(const CarLatticeQuery &q);  ///< true: the last run was the same family query's
    bool fitsAtNode(int i, int j) const;
    /// The analytic expansion from state @p s (AnalyticExpansion: when, which curves, free).
    bool tryShot(std::uint32_t s, const LatticeCostModel &cost, std::uint64_t expansions);
    /// The primitive's samples from lattice-frame pose @p at (a node's, or a hybrid state's) in
    /// world coordinates, into @p out.
    void worldSamples(const Pose2 &at, const LatticePrimitive &p, std::vector<Pose2> &out) const;
    /// One of those samples, @p c and @p s the cosine and sine of @p at's yaw.
    Pose2 sampleWorld(const Pose2 &at, double c, double s, const Pose2 &b) const;
    /// curveFree() of primitive @p p from lattice-frame pose @p at (world pose @p from), its
    /// world samples computed only where the check looks (most are skipped in open ground).
    bool primitiveFree(const Pose2 &at, const Pose2 &from, const LatticePrimitive &p) const;
    /// A lattice-frame pose in world coordinates (yaw not wrapped).
    Pose2 toWorld(const Pose2 &lat) const
    {
        return {ox_ + cphi_ * lat.x - sphi_ * lat.y, oy_ + sphi_ * lat.x + cphi_ * lat.y, phi_ + lat.yaw};
    }
    /// The same with the yaw wrapped (as nodePose()).
    Pose2 worldPose(const Pose2 &lat) const
    {
        Pose2 p = toWorld(lat);
        p.yaw = wrapYaw(p.yaw);
        return p;
    }
    std::vector<Pose2> buildPath(std::uint32_t end) const;
    double measureRatio() const;
    /// One search of run()'s query from the start states (the states of any before cleared).
    SearchResult searchOnce(const CarLatticeQuery &q, const LatticeCostModel &cost, const std::function<bool()> &cancelled,
                            std::atomic<std::uint64_t> *progress);

    std::shared_ptr<CarCollision> col_;
    const FootprintCollision *fc_{nullptr};  ///< col_ when it is gridcar's checker (primitiveFree()'s inlined path)
    std::shared_ptr<const CarLattice> lattice_;
    double ratio_{1.0};
    // the last run's frame, states and heuristic
    double ox_{0}, oy_{0}, phi_{0}, cphi_{1}, sphi_{0};
    int i0_{0}, j0_{0}, ni_{1}, nj_{1};
    CarLatticeQuery query_;
    std::unique_ptr<ObstacleHeuristic> ownH2d_;
    std::uint64_t epoch_{0};  ///< the last run's CarLatticeQuery::boundsEpoch
    ObstacleHeuristic *h2d_{nullptr};  ///< the last run's 2D distances: ownH2d_ or borrowed (borrowBounds())
    bool use2d_{true};
    /// the 2D heuristic with turning counted (cost models that charge turning), kept across runs
    std::unique_ptr<TurnHeuristic> ownTurn_;
    TurnHeuristic *turn_{nullptr};  ///< the last run's: ownTurn_ or borrowed (borrowBounds())
    std::unique_ptr<ObstacleHeuristic> fromStart_;  ///< turn_'s guide: 2D distances from the start
    bool useTurn_{false};
    /// True if the turn bound applies to the query: a cost model that charges turning, on a
    /// node lattice, an aimed search whose goal region the seeds stand for.
    bool turnBoundApplies(const CarLatticeQuery &q, const LatticeCostModel &cost) const;
    /// run() with CarLatticeQuery::boundsFrom: points h2d_ (and turn_, where that search used
    /// its turn bound and this run's cost model applies one) at that search's when it laid the
    /// same graph over the same frame from the same goal (true).
    bool borrowBounds(const CarLatticeQuery &q, const LatticeCostModel &cost, const std::function<bool()> &cancelled);
    /// Resets turn_ for this run (after h2d_; turnBoundApplies()): sets useTurn_ (false when
    /// the box is too large).
    void setUpTurnHeuristic(const LatticeCostModel &cost, const std::vector<std::pair<std::array<int, 2>, double>> &seeds,
                            const std::function<bool()> &cancelled);
    double seedRadius_{0};
    StateInterner states_;  ///< lattice node key -> dense state id
    std::vector<std::int16_t> prim_;  ///< primitive that reached each state (-1: a start state)
    std::vector<std::int8_t> gear_;   ///< how each state was reached: 1 forwards, -1 backwards, 0 a start
    std::vector<Pose2> pose_;         ///< each state's pose in the lattice frame (a node's, or a hybrid state's own)
    GrowingSearchSpace space_;
    std::uint32_t shotFrom_{SearchSpace::kNoParent};
    std::vector<Pose2> shot_;
    double shotCost_{0};
    int shotsTried_{0};
    std::unique_ptr<CurveTable> curveTable_;  ///< kept across runs (curveTable())
    std::unique_ptr<AnalyticExpansion> analytic_;  ///< the shot to the goal (tryShot())
    const std::function<bool()> *cancelled_{nullptr};  ///< the running query's (run())
};

}  // namespace gridcar
