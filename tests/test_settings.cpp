// The settings tables (Settings.h, CarLatticeParams.h): every car-lattice setting parsed once,
// in its setter, into CarLatticeSettings; what each accepts, refuses and prints.
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/CarLatticeParams.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/planners/GridPlanner.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>

#include <set>
#include <stdexcept>
#include <string>

using namespace gridcar;

namespace
{
const SettingField<CarLatticeSettings> &field(const std::string &name)
{
    for (const auto &f : carLatticeSettingFields())
        if (f.name == name) return f;
    throw std::logic_error("no car-lattice setting " + name);
}

/// The message parsing @p value into @p name gives ("" if accepted).
std::string refusal(const std::string &name, const std::string &value)
{
    CarLatticeSettings s;
    try
    {
        field(name).parse(s, value);
    }
    catch (const std::invalid_argument &e)
    {
        return e.what();
    }
    return "";
}
}  // namespace

// Every field prints its default, and what it prints parses back to the same settings: the
// getter and the setter agree, so ompl::tools::Benchmark's logged values can be set again.
TEST(Settings, EveryCarLatticeFieldRoundTrips)
{
    const CarLatticeSettings defaults;
    std::set<std::string> names;
    for (const auto &f : carLatticeSettingFields())
    {
        EXPECT_TRUE(names.insert(f.name).second) << "declared twice: " << f.name;
        EXPECT_FALSE(f.range.empty()) << f.name;
        EXPECT_FALSE(f.help.empty()) << f.name;
        CarLatticeSettings s;
        const std::string printed = f.print(defaults);
        f.parse(s, printed);
        for (const auto &g : carLatticeSettingFields()) EXPECT_EQ(g.print(s), g.print(defaults)) << f.name << "=" << printed;
    }
    // the table's settings (a new one is a row of it: no count to keep here)
    for (const char *n : {"headings", "heuristic_weight", "reverse", "reverse_penalty", "cusp_penalty", "curve_heuristic",
                          "primitives", "continuous_curvature", "curvature_rate", "cost_layer_weight", "turns", "shortcut"})
        EXPECT_EQ(names.count(n), 1u) << n;
}

// A switch takes 1 / 0, true / false, on / off in any case, wherever a setting is one.
TEST(Settings, SwitchesTakeEveryWayOfSayingOnAndOff)
{
    for (const char *on : {"1", "true", "TRUE", "on", "On"})
    {
        CarLatticeSettings s;
        field("reverse").parse(s, on);
        field("shortcut").parse(s, on);
        field("continuous_curvature").parse(s, "0");
        field("continuous_curvature").parse(s, on);
        EXPECT_EQ(s.reverse, AutoSwitch::On) << on;
        EXPECT_EQ(s.shortcut, AutoSwitch::On) << on;
        EXPECT_TRUE(s.continuousCurvature) << on;
    }
    for (const char *off : {"0", "false", "False", "off", "OFF"})
    {
        CarLatticeSettings s;
        field("reverse").parse(s, "on");
        field("reverse").parse(s, off);
        field("shortcut").parse(s, off);
        field("continuous_curvature").parse(s, off);
        EXPECT_EQ(s.reverse, AutoSwitch::Off) << off;
        EXPECT_EQ(s.shortcut, AutoSwitch::Off) << off;
        EXPECT_FALSE(s.continuousCurvature) << off;
    }
    CarLatticeSettings s;
    field("curve_heuristic").parse(s, "1");  // as before the table existed: the exact bound
    EXPECT_EQ(s.curveHeuristic, CurveHeuristic::Exact);
}

// A refused value names the setting, the value and what is accepted, and leaves the settings.
TEST(Settings, RefusalsNameTheSettingTheValueAndTheChoices)
{
    const struct
    {
        const char *name, *value, *accepted;
    } bad[] = {{"reverse", "sometimes", "auto"},       {"shortcut", "yes", "auto"},
               {"primitives", "lattices", "hybrid"},   {"turns", "spline", "clothoid"},
               {"curve_heuristic", "fast", "table"},   {"headings", "72", "8 or 16"},
               {"headings", "8.5", "8 or 16"},         {"heuristic_weight", "abc", "[1, 100]"},
               {"heuristic_weight", "0.5", "[1, 100]"}, {"heuristic_weight", "1.5x", "[1, 100]"},
               {"heuristic_weight", "", "[1, 100]"},   {"reverse_penalty", "nan", "[1, 1000]"},
               {"cusp_penalty", "-1", "auto"},         {"curvature_rate", "inf", "10000"},
               {"cost_layer_weight", "1e400", "1000"}, {"continuous_curvature", "2", "on (1, true)"}};
    for (const auto &b : bad)
    {
        const std::string why = refusal(b.name, b.value);
        EXPECT_NE(why.find(b.name), std::string::npos) << b.name << "=" << b.value << ": " << why;
        EXPECT_NE(why.find(std::string("'") + b.value + "'"), std::string::npos) << why;
        EXPECT_NE(why.find(b.accepted), std::string::npos) << why;
    }
    // numbers in range, with blanks around, are accepted
    EXPECT_EQ(refusal("heuristic_weight", " 1.25 "), "");
    EXPECT_EQ(refusal("headings", "8"), "");
}

// cusp_penalty: unset (auto) is a value of the setting, not the absence of a set parameter.
TEST(Settings, CuspPenaltyUnsetIsAValue)
{
    CarLatticeSettings s;
    EXPECT_FALSE(s.cuspPenalty.has_value());
    EXPECT_EQ(field("cusp_penalty").print(s), "auto");
    field("cusp_penalty").parse(s, "2.5");
    ASSERT_TRUE(s.cuspPenalty.has_value());
    EXPECT_DOUBLE_EQ(*s.cuspPenalty, 2.5);
    field("cusp_penalty").parse(s, "AUTO");
    EXPECT_FALSE(s.cuspPenalty.has_value());
}

// The planners of the car lattice declare every setting of the table, as OMPL string
// parameters; OMPL's setParam() then sets the one struct the search reads.
TEST(Settings, CarLatticePlannersDeclareTheTable)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = test::carSetup(SpaceKind::SE2);
    for (const char *name : {"corner-astar", "improved-astar"})
    {
        auto p = std::dynamic_pointer_cast<CarLatticePlanner>(makePlanner(s.ss->getSpaceInformation(), name));
        ASSERT_TRUE(p) << name;
        for (const auto &f : carLatticeSettingFields())
        {
            ASSERT_TRUE(p->params().hasParam(f.name)) << name << " " << f.name;
            EXPECT_EQ(p->params().getParam(f.name)->getRangeSuggestion(), f.range) << f.name;
            EXPECT_EQ(p->params().getParam(f.name)->getValue(), f.print(CarLatticeSettings{})) << f.name;
        }
        ASSERT_TRUE(p->params().setParam("reverse", "true"));
        ASSERT_TRUE(p->params().setParam("headings", "8"));
        ASSERT_TRUE(p->params().setParam("cost_layer_weight", "2.5"));
        EXPECT_EQ(p->carSettings().reverse, AutoSwitch::On);
        EXPECT_EQ(p->carSettings().headings, 8);
        EXPECT_DOUBLE_EQ(p->carSettings().costLayerWeight, 2.5);
        EXPECT_TRUE(p->reversing());
        EXPECT_FALSE(p->params().setParam("headings", "12"));
        EXPECT_EQ(p->carSettings().headings, 8);
    }
}
