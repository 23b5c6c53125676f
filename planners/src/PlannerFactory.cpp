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
std::vector<std::string> gridPlannerNames()
{
    return {"dijkstra", "astar-manhattan", "astar-euclidean", "astar-octile", "corner-astar", "improved-astar"};
}

std::vector<std::string> omplPlannerNames()
{
    return {"rrt", "rrtconnect", "rrtstar", "prm", "prmstar", "lazyprmstar", "bitstar", "informedrrtstar"};
}

std::vector<std::string> plannerNames()
{
    auto n = gridPlannerNames();
    for (const auto &o : omplPlannerNames()) n.push_back(o);
    return n;
}

namespace
{
/// BIT* without the two progress properties that read its graph while it changes: OMPL's
/// Benchmark samples progress properties from another thread during solve(), and in OMPL
/// 1.5.2 these two race with BIT*'s pruning and crash the process (ompl/ompl issue #779, fixed
/// upstream by pull request #784 after 1.5.2; our main job's Reeds-Shepp race hit it once).
class BenchmarkSafeBITstar : public ompl::geometric::BITstar
{
public:
    explicit BenchmarkSafeBITstar(const ompl::base::SpaceInformationPtr &si) : BITstar(si)
    {
        plannerProgressProperties_.erase("current free states INTEGER");
        plannerProgressProperties_.erase("current graph vertices INTEGER");
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

bool isPlannerName(const std::string &name)
{
    std::string base = name;
    if (!splitSuffix(name, base, "+smooth")) splitSuffix(name, base, "+simplify");
    const auto known = plannerNames();
    return std::find(known.begin(), known.end(), base) != known.end();
}

ompl::base::PlannerPtr makePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
{
    namespace og = ompl::geometric;
    for (const auto &[suffix, method] : {std::make_pair(std::string("+smooth"), SmoothedPlanner::Method::PaperI),
                                          std::make_pair(std::string("+simplify"), SmoothedPlanner::Method::OmplSimplifier)})
        if (std::string base; splitSuffix(name, base, suffix))
        {
            auto p = std::make_shared<SmoothedPlanner>(makePlanner(si, base), method);
            p->setName(name);
            return p;
        }
    if (name == "dijkstra") return std::make_shared<GridAStar>(si, GridHeuristic::Zero, name);
    if (name == "astar-manhattan") return std::make_shared<GridAStar>(si, GridHeuristic::Manhattan, name);
    if (name == "astar-euclidean") return std::make_shared<GridAStar>(si, GridHeuristic::Euclidean, name);
    if (name == "astar-octile") return std::make_shared<GridAStar>(si, GridHeuristic::Octile, name);
    if (name == "corner-astar") return std::make_shared<CornerAStar>(si);
    if (name == "improved-astar") return std::make_shared<ImprovedAStar>(si);
    if (name == "rrt") return std::make_shared<og::RRT>(si);
    if (name == "rrtconnect") return std::make_shared<og::RRTConnect>(si);
    if (name == "rrtstar") return std::make_shared<og::RRTstar>(si);
    if (name == "prm") return std::make_shared<og::PRM>(si);
    if (name == "prmstar") return std::make_shared<og::PRMstar>(si);
    if (name == "lazyprmstar") return std::make_shared<og::LazyPRMstar>(si);
    if (name == "bitstar") return std::make_shared<BenchmarkSafeBITstar>(si);
    if (name == "informedrrtstar") return std::make_shared<og::InformedRRTstar>(si);
    std::string known;
    for (const auto &n : plannerNames()) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown planner '" + printable(name) + "' (known: " + known +
                                "; any of them + \"+smooth\" adds paper I's post-processing, + \"+simplify\" OMPL's path simplifier)");
}

}  // namespace gridcar
