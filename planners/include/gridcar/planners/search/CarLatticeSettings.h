#pragma once
/// @file CarLatticeSettings.h
/// @brief The car lattice's settings: one plain struct of enums and numbers that the planner's
/// OMPL parameters parse into (CarLatticeParams.cpp) and the search reads as it is
/// (CarLatticeQuery::settings).

#include <optional>

namespace gridcar
{
/// A switch that may also follow the query: `auto` decides per space or per goal.
enum class AutoSwitch
{
    Off,
    On,
    Auto,
};

/// The car lattice's primitive sets (`primitives`).
enum class PrimitiveSet
{
    Auto,     ///< the lattice, then Hybrid A*'s in the time left when it does not reach the goal
    Lattice,  ///< nodes joined exactly, 8 or 16 headings
    Hybrid,   ///< Hybrid A*: continuous poses in 72 heading bins, short arcs
};

/// How the heuristic takes the Reeds-Shepp / Dubins length to a goal pose (`curve_heuristic`).
enum class CurveHeuristic
{
    Off,
    Table,  ///< read from the lattice's CurveTable (within 10 R_min per axis)
    Exact,  ///< computed at every state (within 30 R_min)
};

/// The lattice's turns (`turns`).
enum class TurnShape
{
    Auto,      ///< clothoid turns towards a goal position (a route), arcs towards a goal pose (a manoeuvre)
    Arc,       ///< arcs at R_min
    Clothoid,  ///< clothoid turns within the curvature rate
};

/**
 * @brief Every setting of a car-lattice planner, as set (defaults: what a planner does with no
 * parameter set). One field per OMPL parameter; the table in CarLatticeParams.cpp names,
 * parses and prints each, and docs/planners.md says what each measured.
 */
struct CarLatticeSettings
{
    int headings{16};                ///< `headings`: 8 or 16
    double heuristicWeight{1.1};     ///< `heuristic_weight`, >= 1 (weighted A*)
    /// `reverse`: off; on (backwards wherever it pays); auto (forwards only on a Dubins space,
    /// else backwards within reverseZone of the start and the goal, where manoeuvres are, and
    /// everywhere only if that finds no path: FallbackSchedule)
    AutoSwitch reverse{AutoSwitch::Auto};
    /// `reverse_zone`, m: with reverse=auto, how far from the start and the goal positions the
    /// first search may drive backwards; 0: 2 R_min + the vehicle's length (room for a
    /// three-point turn or a parking manoeuvre)
    double reverseZone{0.0};
    double reversePenalty{2.0};      ///< `reverse_penalty`: factor on reversed cost, >= 1
    std::optional<double> cuspPenalty;  ///< `cusp_penalty`, m; unset: the vehicle's gearChangeDistance()
    CurveHeuristic curveHeuristic{CurveHeuristic::Off};  ///< `curve_heuristic`
    PrimitiveSet primitives{PrimitiveSet::Auto};           ///< `primitives`
    /// `continuous_curvature`: the found path's curvature jumps replaced by G2 quintics within
    /// the curvature rate (smoothCurvature())
    bool continuousCurvature{true};
    double curvatureRate{0.0};       ///< `curvature_rate`, 1/m^2; 0 = the vehicle's
    /// `cost_layer_weight`: extra cost per metre = weight x the map's cost layer value / 252
    double costLayerWeight{0.0};
    /// `clearance`, m: a soft margin (as Nav2's inflation): a motion whose body passes nearer
    /// an obstacle than this costs up to twice as much, (1 - room / clearance)^2 extra metres
    /// per metre at each pose, room the body's free slack in the distance field
    /// (FootprintChecker::freeSlack()); the body may still pass closer where it must. 0: off
    double clearance{0.0};
    /// `safety_margin`, m: a hard margin. Where the path found passes nearer an obstacle than
    /// this, it is searched again for the body grown by it on every side (CarLatticePlanner);
    /// that path is kept if it costs at most 5 % more, else the first (a doorway the grown body
    /// does not pass is not given up). Unset: auto, 0.1 m, or a quarter of the vehicle's
    /// width if less; 0: off
    std::optional<double> safetyMargin;
    TurnShape turns{TurnShape::Auto};  ///< `turns`
    /// `shortcut`: a found path shortened by the analytic expansion's curves where they are
    /// free, shorter and cheaper (auto: on with reverse=on)
    AutoSwitch shortcut{AutoSwitch::Auto};

    /// The settings of a query built by hand on the search alone: unweighted A*, no penalty on
    /// reversing (the planners copy in their own).
    static CarLatticeSettings plainSearch()
    {
        CarLatticeSettings s;
        s.heuristicWeight = 1.0;
        s.reversePenalty = 1.0;
        return s;
    }
};

}  // namespace gridcar
