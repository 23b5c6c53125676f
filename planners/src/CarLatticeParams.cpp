/// @file CarLatticeParams.cpp
/// @brief The table of the car lattice's parameters (CarLatticeParams.h): one entry per
/// CarLatticeSettings field.
#include "gridcar/planners/CarLatticeParams.h"

#include <cstddef>
#include <string>

namespace gridcar
{
namespace
{
using Field = SettingField<CarLatticeSettings>;
using S = CarLatticeSettings;

// the enums' words, in the enums' order
constexpr const char *kAutoSwitch[] = {"off", "on", "auto"};
constexpr const char *kPrimitives[] = {"auto", "lattice", "hybrid"};
constexpr const char *kCurve[] = {"off", "table", "exact"};
constexpr const char *kTurns[] = {"auto", "arc", "clothoid"};

/// The index of @p value among an enum's @p words.
template <std::size_t N>
int pick(const char *name, const std::string &value, const char *const (&words)[N], const char *what)
{
    return settings::oneOf(name, value, std::vector<std::string>(words, words + N), what);
}

/// A field of a double member in [lo, hi].
Field number(const char *name, double S::*member, double lo, double hi, const char *range, const char *what,
             const char *help)
{
    return {name, range, help,
            [=](S &s, const std::string &v) { s.*member = settings::real(name, v, lo, hi, what); },
            [=](const S &s) { return settings::print(s.*member); }};
}

/// A field of an AutoSwitch member.
Field autoSwitch(const char *name, AutoSwitch S::*member, const char *what, const char *help)
{
    return {name, "off,on,auto", help,
            [=](S &s, const std::string &v) { s.*member = AutoSwitch(pick(name, v, kAutoSwitch, what)); },
            [=](const S &s) { return std::string(word(s.*member)); }};
}

std::vector<Field> makeFields()
{
    std::vector<Field> f;
    f.push_back({"headings", "8,16", "heading count of the lattice",
                 [](S &s, const std::string &v) {
                     s.headings = settings::integer("headings", v, {8, 16},
                                                    "8 or 16 on the car lattice (the directions of lattice vectors: 32 or "
                                                    "72 equal steps do not land on nodes)");
                 },
                 [](const S &s) { return std::to_string(s.headings); }});
    f.push_back(number("heuristic_weight", &S::heuristicWeight, 1.0, 100.0, "1.:0.05:3.", "a number in [1, 100]",
                       "weighted A*: the path costs at most this x the lattice optimum"));
    f.push_back(autoSwitch("reverse", &S::reverse, "off (0, false), on (1, true) or auto",
                           "reverse motion: off, on (wherever it pays), auto (near the start and the goal, everywhere "
                           "only if no path is found so; off on a Dubins space)"));
    f.push_back(number("reverse_zone", &S::reverseZone, 0.0, 1000.0, "0.:0.5:50.", "a length in [0, 1000] m",
                       "with reverse=auto, how far from the start and the goal the first search reverses, m "
                       "(0: 2 R_min + the vehicle's length)"));
    f.push_back(number("reverse_penalty", &S::reversePenalty, 1.0, 1000.0, "1.:0.5:10.", "a factor in [1, 1000]",
                       "factor on the cost of motion driven backwards"));
    f.push_back({"cusp_penalty", "0.:1.:100.", "cost of a gear change, m (unset: the vehicle's stop and start)",
                 [](S &s, const std::string &v) {
                     if (settings::switchWord(v) == "auto")
                         s.cuspPenalty.reset();
                     else
                         s.cuspPenalty = settings::real("cusp_penalty", v, 0.0, 1e4, "a length in [0, 10000] m or auto");
                 },
                 // unset: auto (the vehicle's, which the settings do not know)
                 [](const S &s) { return s.cuspPenalty ? settings::print(*s.cuspPenalty) : std::string("auto"); }});
    f.push_back({"curve_heuristic", "off,table,exact",
                 "the Reeds-Shepp / Dubins length to a goal pose in the heuristic: off, table, exact (1: exact)",
                 [](S &s, const std::string &v) {
                     // 0 and 1 as before the table existed: off, and the exact bound
                     const std::string w = settings::switchWord(v) == "on" ? "exact" : v;
                     s.curveHeuristic = CurveHeuristic(pick("curve_heuristic", w, kCurve, "off, table or exact"));
                 },
                 [](const S &s) { return std::string(word(s.curveHeuristic)); }});
    f.push_back({"primitives", "auto,lattice,hybrid", "primitive set: auto (lattice, then hybrid), lattice, hybrid",
                 [](S &s, const std::string &v) {
                     s.primitives = PrimitiveSet(pick("primitives", v, kPrimitives, "lattice, hybrid or auto"));
                 },
                 [](const S &s) { return std::string(word(s.primitives)); }});
    f.push_back({"continuous_curvature", "0,1", "a found path's curvature jumps smoothed within the curvature rate",
                 [](S &s, const std::string &v) { s.continuousCurvature = settings::onOff("continuous_curvature", v); },
                 [](const S &s) { return std::string(s.continuousCurvature ? "1" : "0"); }});
    f.push_back(number("curvature_rate", &S::curvatureRate, 0.0, 1e4, "0.:0.05:100.",
                       "in [0, 10000] 1/m^2 (0: the vehicle's)", "curvature rate limit, 1/m^2 (0: the vehicle's)"));
    f.push_back(number("cost_layer_weight", &S::costLayerWeight, 0.0, 1000.0, "0.:0.5:100.",
                       "in [0, 1000] (extra metres per metre at cost 252)", "weight of the map's cost layer"));
    f.push_back(number("clearance", &S::clearance, 0.0, 10.0, "0.:0.05:2.", "a length in [0, 10] m",
                       "soft margin, m: motions nearer an obstacle than this cost more (0: off)"));
    f.push_back({"safety_margin", "0.:0.05:1.",
                 "hard margin, m: searched again for the body grown by it where the path passes nearer, kept if at "
                 "most 5 % dearer (auto: 0.1 m, a quarter of the width if less; 0: off)",
                 [](S &s, const std::string &v) {
                     if (settings::switchWord(v) == "auto")
                         s.safetyMargin.reset();
                     else
                         s.safetyMargin = settings::real("safety_margin", v, 0.0, 10.0, "a length in [0, 10] m or auto");
                 },
                 [](const S &s) { return s.safetyMargin ? settings::print(*s.safetyMargin) : std::string("auto"); }});
    f.push_back({"turns", "auto,arc,clothoid", "the lattice's turns: auto, arc, clothoid",
                 [](S &s, const std::string &v) {
                     s.turns = TurnShape(pick("turns", v, kTurns, "auto, arc or clothoid"));
                 },
                 [](const S &s) { return std::string(word(s.turns)); }});
    f.push_back(autoSwitch("shortcut", &S::shortcut, "auto, on (1, true) or off (0, false)",
                           "a found path shortcut by free analytic curves: auto (on with reverse=on), on, off"));
    return f;
}
}  // namespace

const std::vector<SettingField<CarLatticeSettings>> &carLatticeSettingFields()
{
    static const std::vector<Field> fields = makeFields();
    return fields;
}

const char *word(AutoSwitch v) { return kAutoSwitch[std::size_t(v)]; }
const char *word(PrimitiveSet v) { return kPrimitives[std::size_t(v)]; }
const char *word(CurveHeuristic v) { return kCurve[std::size_t(v)]; }
const char *word(TurnShape v) { return kTurns[std::size_t(v)]; }

}  // namespace gridcar
