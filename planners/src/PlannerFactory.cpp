#include <cctype>
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/core/Errors.h"

#include "gridcar/planners/CornerAStar.h"
#include "gridcar/planners/GridAStar.h"
#include "gridcar/planners/ImprovedAStar.h"
#include "gridcar/planners/SmoothedPlanner.h"

#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <algorithm>
#include <stdexcept>

namespace gridcar
{
namespace
{
/// BIT* without the two progress properties that read its graph while it changes: OMPL's
/// Benchmark samples progress properties from another thread during solve(), and in OMPL
/// 1.5.2 these two race with BIT*'s pruning and crash the process (ompl/ompl issue #779, fixed
/// upstream by pull request #784 after 1.5.2; our main job's Reeds-Shepp race hit it once).
/// And without pruning (`use_graph_pruning` = 0 by default; it may be set back): in OMPL 1.5.2 BIT*'s
/// pruning of its samples (removals from its GNAT) ran on for over 40 minutes past a 10 s
/// limit on the parking suite's paper I parallel-leave query on the Reeds-Shepp space, the
/// termination condition unchecked inside it, and hung the benchmark.
class BenchmarkSafeBITstar : public ompl::geometric::BITstar
{
public:
    // named as OMPL names its default (k-nearest) version: constructed as "BITstar", its setup()
    // renames it "kBITstar" with a warning at every solve's first set-up
    explicit BenchmarkSafeBITstar(const ompl::base::SpaceInformationPtr &si) : BITstar(si, "kBITstar")
    {
        plannerProgressProperties_.erase("current free states INTEGER");
        plannerProgressProperties_.erase("current graph vertices INTEGER");
        setPruning(false);
    }
};

/// True (and @p base set to NAME) if @p name is "NAME" + @p suffix.
bool splitSuffix(const std::string &name, std::string &base, const std::string &suffix)
{
    if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
    base = name.substr(0, name.size() - suffix.size());
    return true;
}
}  // namespace

const std::vector<PlannerEntry> &plannerRegistry()
{
    namespace og = ompl::geometric;
    using SI = ompl::base::SpaceInformationPtr;
    auto grid = [](GridHeuristic h, const char *name) {
        return [h, name](const SI &si) { return std::make_shared<GridAStar>(si, h, name); };
    };
    static const std::vector<PlannerEntry> registry{
        {"dijkstra", "8-connected Dijkstra on the map's cells", true, grid(GridHeuristic::Zero, "dijkstra")},
        {"astar-manhattan", "8-connected A*, Manhattan heuristic (inadmissible on diagonals)", true,
         grid(GridHeuristic::Manhattan, "astar-manhattan")},
        {"astar-euclidean", "8-connected A*, Euclidean heuristic", true, grid(GridHeuristic::Euclidean, "astar-euclidean")},
        {"astar-octile", "8-connected A*, octile heuristic", true, grid(GridHeuristic::Octile, "astar-octile")},
        {"corner-astar", "paper C's corner-weighted A* on the car lattice (drivable paths)", true,
         [](const SI &si) { return std::make_shared<CornerAStar>(si); }},
        {"improved-astar", "paper I's improved A* on the car lattice (drivable paths)", true,
         [](const SI &si) { return std::make_shared<ImprovedAStar>(si); }},
        {"corner-astar-grid", "paper C's search as published: (cell, direction) on the map's cells", true,
         [](const SI &si) { return std::make_shared<CornerAStarGrid>(si); }},
        {"improved-astar-grid", "paper I's search as published: (cell, direction, run) on the map's cells, smoothed", true,
         [](const SI &si) { return std::make_shared<ImprovedAStarGrid>(si); }},
        {"rrt", "OMPL's RRT", false, [](const SI &si) { return std::make_shared<og::RRT>(si); }},
        {"rrtconnect", "OMPL's RRTConnect", false, [](const SI &si) { return std::make_shared<og::RRTConnect>(si); }},
        {"rrtstar", "OMPL's RRT*", false, [](const SI &si) { return std::make_shared<og::RRTstar>(si); }},
        {"prm", "OMPL's PRM", false, [](const SI &si) { return std::make_shared<og::PRM>(si); }},
        {"prmstar", "OMPL's PRM*", false, [](const SI &si) { return std::make_shared<og::PRMstar>(si); }},
        {"lazyprmstar", "OMPL's LazyPRM*", false, [](const SI &si) { return std::make_shared<og::LazyPRMstar>(si); }},
        {"bitstar", "OMPL's BIT* (without the two progress properties that race under Benchmark, and without sample pruning, which can hang in OMPL 1.5.2)", false,
         [](const SI &si) { return std::make_shared<BenchmarkSafeBITstar>(si); }},
        {"informedrrtstar", "OMPL's Informed RRT*", false, [](const SI &si) { return std::make_shared<og::InformedRRTstar>(si); }},
    };
    return registry;
}

namespace
{
std::string lowered(std::string s)
{
    for (char &c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// Levenshtein distance (the names are short).
std::size_t editDistance(const std::string &a, const std::string &b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}
}  // namespace

const PlannerEntry *findPlanner(const std::string &name)
{
    // case-insensitive: OMPL's own class names (RRTConnect, BITstar, LazyPRMstar, ...) are ours
    // in lower case
    const std::string key = lowered(name);
    for (const PlannerEntry &e : plannerRegistry())
        if (e.name == key) return &e;
    return nullptr;
}

std::string suggestPlanner(const std::string &name)
{
    const std::string key = lowered(name);
    std::string best;
    std::size_t bestD = std::max<std::size_t>(3, key.size() / 3) + 1;  // a typo, not another word
    for (const PlannerEntry &e : plannerRegistry())
    {
        const std::size_t d = editDistance(key, e.name);
        if (d < bestD)
        {
            bestD = d;
            best = e.name;
        }
    }
    return best;
}

namespace
{
std::vector<std::string> namesWhere(int ours)
{
    std::vector<std::string> out;
    for (const PlannerEntry &e : plannerRegistry())
        if (ours < 0 || int(e.ours) == ours) out.push_back(e.name);
    return out;
}
}  // namespace

std::vector<std::string> gridPlannerNames() { return namesWhere(1); }
std::vector<std::string> omplPlannerNames() { return namesWhere(0); }
std::vector<std::string> plannerNames() { return namesWhere(-1); }

bool isPlannerName(const std::string &name)
{
    std::string base = name;
    if (!splitSuffix(name, base, "+smooth")) splitSuffix(name, base, "+simplify");
    return findPlanner(base) != nullptr;
}

std::string resolvePlannerAlias(const std::string &name, std::vector<std::pair<std::string, std::string>> &params)
{
    std::string base = name, suffix;
    for (const char *s : {"+smooth", "+simplify"})
        if (splitSuffix(name, base, s))
        {
            suffix = s;
            break;
        }
    const std::string key = lowered(base);
    const bool corner = key == "corner-astar" || key == "corner-astar-grid";
    const bool improved = key == "improved-astar" || key == "improved-astar-grid";
    if (!corner && !improved) return name;
    // the family the old switches ask for, if any: "grid", "car" or ""
    std::string family;
    std::vector<std::pair<std::string, std::string>> rest;
    for (const auto &[k, v] : params)
    {
        const std::string value = lowered(v);
        if (k == "lattice" && (value == "grid" || value == "car"))
            family = value;
        else if (corner && k == "mode" && (value == "paper" || value == "drivable"))
            family = value == "paper" ? "grid" : "car";
        else
            rest.push_back({k, v});
    }
    if (family.empty()) return name;
    const bool gridName = key.size() > 5 && key.compare(key.size() - 5, 5, "-grid") == 0;
    const std::string stem = gridName ? key.substr(0, key.size() - 5) : key;
    if (gridName && family == "car")
        throw std::invalid_argument("planner " + key + " searches the map's cells; the car lattice is " + stem +
                                    " (lattice=car does not apply to it)");
    params = rest;
    return (family == "grid" ? stem + "-grid" : stem) + suffix;
}

ompl::base::PlannerPtr makePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
{
    for (const auto &[suffix, method] : {std::make_pair(std::string("+smooth"), SmoothedPlanner::Method::PaperI),
                                          std::make_pair(std::string("+simplify"), SmoothedPlanner::Method::OmplSimplifier)})
        if (std::string base; splitSuffix(name, base, suffix))
        {
            auto p = std::make_shared<SmoothedPlanner>(makePlanner(si, base), method);
            p->setName(name);
            return p;
        }
    if (const PlannerEntry *e = findPlanner(name)) return e->make(si);
    std::string known;
    for (const auto &n : plannerNames()) known += (known.empty() ? "" : ", ") + n;
    const std::string guess = suggestPlanner(name);
    throw std::invalid_argument("unknown planner '" + printable(name) + "'" +
                                (guess.empty() ? std::string() : "; did you mean '" + guess + "'?") + " (known: " + known +
                                "; any of them + \"+smooth\" adds paper I's post-processing, + \"+simplify\" OMPL's path simplifier)");
}

}  // namespace gridcar
