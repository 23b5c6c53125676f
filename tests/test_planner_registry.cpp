// The planner registry (planners/PlannerFactory.h) and how parameters act: the papers' searches
// under names of their own, the old switches as aliases, a parameter that does not act in the
// planner as configured refused with the reason, and a parameter acting the same whether it is
// set before or after setup().
#include "gridcar/query/PlanQuery.h"
#include "gridcar/core/Errors.h"
#include "gridcar/planners/CarLatticePlanner.h"
#include "gridcar/planners/CarLatticeParams.h"
#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/spaces/Setup.h"
#include "PlannerTestUtil.h"

#include <gtest/gtest.h>

#include <ompl/util/Console.h>

using namespace gridcar;
using namespace gridcar::test;
namespace ob = ompl::base;

namespace
{
std::shared_ptr<const OccupancyGrid> wallsMap() { return twoWallsMap(160, 120); }

/// Length of the planner's exact solution (-1 if none).
double lengthOf(GridSetup &s, const ob::PlannerPtr &p)
{
    s.ss->clear();
    s.ss->setPlanner(p);
    s.setStartAndGoal({3, 3, 0}, {37, 27, 0});
    if (s.ss->solve(10.0) != ob::PlannerStatus::EXACT_SOLUTION) return -1.0;
    return s.ss->getSolutionPath().length();
}
}  // namespace

TEST(PlannerRegistry, EveryNameHasOneEntryWithADescription)
{
    const auto &reg = plannerRegistry();
    EXPECT_EQ(reg.size(), plannerNames().size());
    EXPECT_EQ(gridPlannerNames().size() + omplPlannerNames().size(), reg.size());
    for (const PlannerEntry &e : reg)
    {
        EXPECT_FALSE(e.description.empty()) << e.name;
        EXPECT_EQ(findPlanner(e.name), &e);
        EXPECT_TRUE(isPlannerName(e.name + "+smooth"));
    }
    EXPECT_EQ(findPlanner("no-such-planner"), nullptr);
    GridSetup s = testSetup("point");
    EXPECT_THROW(makePlanner(s.ss->getSpaceInformation(), "no-such-planner"), std::invalid_argument);
    EXPECT_EQ(makePlanner(s.ss->getSpaceInformation(), "corner-astar-grid")->getName(), "corner-astar-grid");
}

TEST(PlannerRegistry, ThePapersSearchesHaveNamesAndTheOldSwitchesStayAliases)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = makeGridSetup(wallsMap(), VehicleParams::preset("paper-c-robot"));
    const auto &si = s.ss->getSpaceInformation();
    const double grid = lengthOf(s, makePlanner(si, "corner-astar-grid"));
    ASSERT_GT(grid, 0);
    EXPECT_DOUBLE_EQ(lengthOf(s, configurePlanner(si, {"corner-astar", {{"mode", "paper"}}, false, false})), grid);
    EXPECT_DOUBLE_EQ(lengthOf(s, configurePlanner(si, {"corner-astar", {{"lattice", "grid"}}, false, false})), grid);
    const double car = lengthOf(s, makePlanner(si, "corner-astar"));
    EXPECT_DOUBLE_EQ(lengthOf(s, configurePlanner(si, {"corner-astar", {{"lattice", "car"}}, false, false})), car);
    const double igrid = lengthOf(s, makePlanner(si, "improved-astar-grid"));
    ASSERT_GT(igrid, 0);
    EXPECT_DOUBLE_EQ(lengthOf(s, configurePlanner(si, {"improved-astar", {{"lattice", "grid"}}, false, false})), igrid);
}

TEST(PlannerRegistry, APlannerDeclaresOnlyWhatActsInIt)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = makeGridSetup(wallsMap(), VehicleParams::preset("paper-c-robot"));
    const auto &si = s.ss->getSpaceInformation();
    // grid-lattice parameters on the car lattice, and car-lattice ones on the grid lattice: not
    // declared there, so refused where they are set, naming the parameter and listing those
    // the planner has
    const std::vector<std::pair<std::string, PlannerParams>> refused{
        {"improved-astar", {{"heuristic", "euclidean"}}},
        {"improved-astar", {{"smooth", "0"}}},
        {"improved-astar", {{"contour", "points"}}},
        {"improved-astar", {{"allow_corner_cutting", "1"}}},
        {"corner-astar", {{"allow_corner_cutting", "1"}}},
        {"corner-astar-grid", {{"headings", "8"}}},
        {"corner-astar-grid", {{"cost", "time"}}},
        {"corner-astar", {{"lattice", "grid"}, {"heuristic_weight", "1.5"}}},
        {"improved-astar-grid", {{"headings", "8"}}},
        {"dijkstra", {{"reverse", "on"}}},
    };
    for (const auto &c : refused)
    {
        std::string label = c.first;
        for (const auto &kv : c.second) label += " " + kv.first + "=" + kv.second;
        SCOPED_TRACE(label);
        try
        {
            configurePlanner(si, {c.first, c.second, false, false});
            ADD_FAILURE() << "accepted";
        }
        catch (const InputError &e)
        {
            EXPECT_NE(std::string(e.what()).find("no parameter '" + c.second.back().first + "'"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("its parameters:"), std::string::npos) << e.what();
        }
    }
    // the old switches name the family, not a parameter: lattice=car on a -grid name is refused
    EXPECT_THROW(configurePlanner(si, {"corner-astar-grid", {{"lattice", "car"}}, false, false}), InputError);
    // every declared parameter of our planners acts in them: the car lattice's table is
    // declared by the car-lattice planners only, allow_corner_cutting by the grid ones only
    for (const std::string &name : gridPlannerNames())
    {
        auto p = makePlanner(si, name);
        const bool car = reportOf(*p).searchesCarLattice;
        EXPECT_EQ(p->params().hasParam("headings"), car) << name;
        EXPECT_EQ(p->params().hasParam("reverse"), car) << name;
        EXPECT_EQ(p->params().hasParam("allow_corner_cutting"), !car) << name;
        EXPECT_FALSE(p->params().hasParam("lattice")) << name;
    }
    // the same parameters where they act are fine, in either order
    for (const auto &c : std::vector<std::pair<std::string, PlannerParams>>{
             {"improved-astar", {{"heuristic", "euclidean"}, {"lattice", "grid"}}},
             {"improved-astar-grid", {{"smooth", "0"}, {"contour", "points"}}},
             {"corner-astar", {{"headings", "8"}, {"heuristic_weight", "1.5"}}},
             {"corner-astar-grid", {{"allow_corner_cutting", "1"}}}})
    {
        auto p = configurePlanner(si, {c.first, c.second, false, false});
        p->setProblemDefinition(s.ss->getProblemDefinition());
        EXPECT_NO_THROW(p->setup()) << c.first;
    }
}

// A switch takes each way a switch is written (OMPL's bool parameters take 0 / 1, YAML writes
// true / false): reverse=1 used to be refused where shortcut=1 was taken.
TEST(PlannerRegistry, ASwitchTakesOneZeroTrueFalseOnOff)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    GridSetup s = makeGridSetup(wallsMap(), VehicleParams::preset("paper-c-robot"));
    auto p = makePlanner(s.ss->getSpaceInformation(), "corner-astar");
    for (const char *name : {"reverse", "shortcut"})
    {
        const std::vector<std::pair<std::string, std::string>> words{
            {"1", "on"}, {"true", "on"}, {"True", "on"}, {"ON", "on"}, {"on", "on"},
            {"0", "off"}, {"false", "off"}, {"FALSE", "off"}, {"Off", "off"}, {"auto", "auto"}};
        for (const auto &[word, meaning] : words)
        {
            EXPECT_TRUE(p->params().setParam(name, word)) << name << "=" << word;
            EXPECT_EQ(p->params()[name].getValue(), meaning) << name << "=" << word;
        }
        // anything else is refused, and the last value stays
        EXPECT_FALSE(p->params().setParam(name, "yes please"));
        EXPECT_FALSE(p->params().setParam(name, "2"));
        EXPECT_EQ(p->params()[name].getValue(), "auto");
        try
        {
            // the setter's own message (OMPL's setParam() logs it and returns false)
            CarLatticeSettings settings;
            for (const auto &f : carLatticeSettingFields())
                if (f.name == name) f.parse(settings, "sometimes");
            ADD_FAILURE() << "accepted";
        }
        catch (const std::invalid_argument &e)
        {
            EXPECT_NE(std::string(e.what()).find("'sometimes'"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("1, true"), std::string::npos) << e.what();
        }
    }
    // and the switch acts: reverse=true reverses like reverse=on
    const ob::SpaceInformationPtr &si = s.ss->getSpaceInformation();
    auto a = configurePlanner(si, {"corner-astar", {{"reverse", "true"}}, false, false});
    auto b = configurePlanner(si, {"corner-astar", {{"reverse", "on"}}, false, false});
    const double la = lengthOf(s, a);
    ASSERT_GT(la, 0);
    EXPECT_DOUBLE_EQ(la, lengthOf(s, b));
    EXPECT_TRUE(std::static_pointer_cast<CarLatticePlanner>(a)->reversing());
}

TEST(PlannerRegistry, AWeightActsTheSameSetBeforeOrAfterSetup)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    GridSetup s = makeGridSetup(wallsMap(), VehicleParams::preset("paper-c-robot"));
    const auto &si = s.ss->getSpaceInformation();
    for (const char *lattice : {"car", "grid"})
    {
        SCOPED_TRACE(lattice);
        // weights=physics with one weight of the user's: before setup() ...
        auto before = configurePlanner(si, {"corner-astar", {{"lattice", lattice}, {"weights", "physics"}, {"corner_weight_45", "0.5"}}, false, false});
        const double lBefore = lengthOf(s, before);
        // ... and after it (the planner set up and used first)
        auto after = configurePlanner(si, {"corner-astar", {{"lattice", lattice}, {"weights", "physics"}}, false, false});
        const double lPhysics = lengthOf(s, after);
        ASSERT_TRUE(after->params().setParam("corner_weight_45", "0.5"));
        const double lAfter = lengthOf(s, after);
        ASSERT_GT(lBefore, 0);
        EXPECT_DOUBLE_EQ(lAfter, lBefore);
        const auto corner = std::dynamic_pointer_cast<CornerAStar>(after);
        const auto cornerGrid = std::dynamic_pointer_cast<CornerAStarGrid>(after);
        ASSERT_TRUE(corner || cornerGrid);
        const CornerWeights &w = corner ? corner->weights() : cornerGrid->weights();
        EXPECT_EQ(w.w45, 0.5);
        EXPECT_EQ(w.w90, physicsCornerWeights(s.checker->vehicle()).w90) << "the others from physics";
        (void)lPhysics;
    }
}

// OMPL's own class names find OMPL's planners (case-insensitive); a typo gets a suggestion,
// another word none.
TEST(PlannerRegistry, OmplClassNamesAndSuggestions)
{
    for (const char *n : {"RRTConnect", "RRTstar", "PRMstar", "LazyPRMstar", "BITstar", "InformedRRTstar", "RRT", "PRM"})
    {
        const PlannerEntry *e = findPlanner(n);
        ASSERT_NE(e, nullptr) << n;
        EXPECT_FALSE(e->ours) << n;
    }
    EXPECT_NE(findPlanner("Corner-AStar"), nullptr);
    EXPECT_EQ(suggestPlanner("dijkstar"), "dijkstra");
    EXPECT_EQ(suggestPlanner("improved-a-star"), "improved-astar");
    EXPECT_EQ(suggestPlanner("rrtconect"), "rrtconnect");
    EXPECT_EQ(suggestPlanner("potential-field"), "");
    GridSetup s = test::testSetup();
    EXPECT_EQ(makePlanner(s.ss->getSpaceInformation(), "RRTConnect")->getName(), "RRTConnect");
    try
    {
        makePlanner(s.ss->getSpaceInformation(), "dijkstar");
        FAIL() << "a typo was accepted";
    }
    catch (const std::invalid_argument &e)
    {
        EXPECT_NE(std::string(e.what()).find("did you mean 'dijkstra'"), std::string::npos) << e.what();
    }
}

// OMPL's BIT* comes without sample pruning (its pruning hung past the time limit in OMPL 1.5.2,
// PlannerFactory.cpp), and the parameter still sets it back for whoever wants it.
TEST(PlannerRegistry, BitStarComesWithoutPruning)
{
    GridSetup s = makeGridSetup(wallsMap(), VehicleParams::preset("paper-c-robot"));
    auto p = makePlanner(s.ss->getSpaceInformation(), "bitstar");
    EXPECT_EQ(p->params()["use_graph_pruning"].getValue(), "0");
    p->params().setParam("use_graph_pruning", "1");
    EXPECT_EQ(p->params()["use_graph_pruning"].getValue(), "1");
}
