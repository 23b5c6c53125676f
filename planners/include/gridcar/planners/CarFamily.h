#pragma once
/// @file CarFamily.h
/// @brief The car-lattice search family: a CarLatticeSearch over a primitive set
/// (CarLatticeConfig) and the collision model, with a cost model per query.

#include "gridcar/planners/FallbackSchedule.h"
#include "gridcar/planners/GoalAdapter.h"
#include "gridcar/planners/GridFamily.h"
#include "gridcar/planners/SolverSupport.h"
#include "gridcar/planners/search/CarLatticeSearch.h"

#include <ompl/base/PlannerData.h>

#include <atomic>
#include <functional>
#include <memory>

namespace gridcar
{
/// What is done to a path the car lattice found (after the search, before it is returned).
struct CarPostProcessing
{
    /// Curves PathShortcut::apply() may try on a found path (0: no shortcut)
    int shortcutCurves{0};
    /// Continuous curvature (CurvatureStep): a found path's curvature jumps replaced so that
    /// curvature changes no faster than this (1/m^2; 0: the path as searched)
    double curvatureRate{0.0};
    double maxCurvature{0.0};  ///< K_max (1/m) the replacements keep
};

/**
 * @brief The car lattice as a search family: set up from a plain CarLatticeConfig (the
 * primitive set: cell, headings, turning radius, sample spacing) over the collision model;
 * the search and its lattice are kept while both stay the same. A query aims at the goal
 * target: a GoalState or PositionGoal is joined by the analytic expansion (a Dubins curve,
 * footprint checked) or reached at a node within the yaw tolerance, a sampleable region is
 * aimed at and decided by the region, any other region is searched in Dijkstra order.
 */
class CarFamily
{
public:
    /// (Re)builds the search when @p cfg or @p collision differ from the last set-up; with
    /// @p fallback, further searches on that primitive set (the hybrid one) and on it at half
    /// its cell, that a query runs when the first ends without reaching the goal and time is
    /// left (in the order and on the budgets of FallbackSchedule).
    /// With @p forPoses, a query whose goal heading is to be met starts on that primitive
    /// set instead of @p cfg (`turns=auto`: arcs for a manoeuvre, clothoid turns for a route).
    void setup(const CarLatticeConfig &cfg, std::shared_ptr<CarCollision> collision,
               const CarLatticeConfig *fallback = nullptr, const CarLatticeConfig *forPoses = nullptr);
    /// The search of the last query (the first one before any; null before setup()).
    const CarLatticeSearch *search() const { return last_ ? last_ : search_.get(); }
    /// The search of the last query, to read its bounds (CarLatticeQuery::boundsFrom; null before any).
    CarLatticeSearch *lastSearch() { return last_; }

    /// One query from @p start to @p goal: @p terms carries the settings and what they resolve
    /// to (its start and goal fields are set here), @p post what is done to the path found.
    FamilyRun solve(const ompl::base::SpaceInformationPtr &si, const ompl::base::State *start, CarLatticeQuery terms,
                    const CarPostProcessing &post, const GoalTarget &goal, const LatticeCostModel &cost,
                    const std::function<bool()> &cancelled, std::atomic<std::uint64_t> *progress);
    /// The explored graph of the last search.
    void plannerData(ompl::base::PlannerData &data, PlannerDataStates &states) const;

private:
    /// The search a stage of the fallback schedule runs (the half-cell one built on first use).
    CarLatticeSearch *stageSearch(FallbackSearch which, CarLatticeSearch *main);
    /// The hybrid fallback run from within the first search's termination condition until the
    /// probes' work (@p expanded, its expansions so far, and its bound states) reaches @p budget:
    /// true with its path in @p out when it reached the goal. @p main's headings are set on
    /// the collision model again after it.
    bool probeHybrid(const CarLatticeQuery &q, const LatticeCostModel &cost, std::uint64_t budget,
                     const std::function<bool()> &cancelled, CarLatticeSearch &main, CarLatticeResult &out,
                     std::uint64_t &expanded);
    std::shared_ptr<CarCollision> collision_;
    /// the lattice; the hybrid fallback; the hybrid at half its cell, where both ran out; the
    /// lattice for a goal heading to meet (null: search_)
    std::unique_ptr<CarLatticeSearch> search_, fallback_, fine_, forPoses_;
    CarLatticeConfig fineConfig_;  ///< fine_'s primitive set (fine_ is built on first use)
    CarLatticeSearch *last_{nullptr};
    std::uint64_t queries_{0};  ///< queries solved (CarLatticeQuery::boundsEpoch)
};

}  // namespace gridcar
