/// @file ParameterHelp.cpp
/// @brief parameterHelp(): the settings tables' lines, then the parameters declared one by one.
#include "gridcar/planners/ParameterHelp.h"

#include "gridcar/planners/CarLatticeParams.h"
#include "gridcar/planners/CornerWeights.h"
#include "gridcar/planners/ImprovedAStar.h"

#include <map>

namespace gridcar
{
namespace
{
/// The parameters declared one by one (GridPlanner's, the grid planners' and OMPL's common ones).
const std::map<std::string, std::string> &singles()
{
    static const std::map<std::string, std::string> m = {
        {"free_start_heading", "start at any heading where the vehicle fits (the start state's yaw ignored)"},
        {"turning_radius", "minimum turning radius, m (0: the vehicle's R_min, or OMPL's Dubins / Reeds-Shepp radius)"},
        {"max_memory_mb", "the search stops (approximate answer, with the reason) when the process's resident memory passes this, MB"},
        {"lattice_cell", "cell of the search's lattice, m (0: from the map's resolution and the vehicle; on the car lattice a route's may be twice a goal pose's)"},
        {"match_goal_heading", "arrive at a GoalState's yaw (else at any heading where the vehicle fits)"},
        {"cost", "corner A*'s search cost: corners (length + corner weights) or time (driving time)"},
        {"turn_heuristic", "the 2D heuristic also counts the corner weights of the turning its route needs (with cost=corners)"},
        {"allow_corner_cutting", "diagonal moves between two blocked cells' corners allowed"},
        {"heuristic", "paper I's grid heuristic: euclidean, arc (the turning-arc one) or octile"},
        {"contour", "paper I's body-contour cost s(n): fcl (exact) or points (the paper's contour points)"},
        {"smooth", "paper I's post-processing (line of sight, turning points under K_max, Bezier) after the grid search"},
        // OMPL's common parameters
        {"range", "OMPL: longest motion added to the tree at once, in the space's distance (0: from the space's extent)"},
        {"goal_bias", "OMPL: probability of sampling the goal"},
        {"intermediate_states", "OMPL: keep the states along each motion in the tree"},
        {"rewire_factor", "OMPL: factor on the rewiring radius / neighbour count"},
        {"use_k_nearest", "OMPL: rewire the k nearest neighbours (else those within a radius)"},
        {"delay_collision_checking", "OMPL: check motions only when they could improve a solution"},
        {"max_nearest_neighbors", "OMPL: neighbours a new PRM vertex is joined to"},
        {"samples_per_batch", "OMPL: states sampled per batch (BIT*)"},
        // RRT*'s and Informed RRT*'s
        {"focus_search", "OMPL: tree_pruning and informed_sampling together (only where a better solution can be)"},
        {"informed_sampling", "OMPL: once a solution exists, sample only the states that could improve it (the informed set)"},
        {"new_state_rejection", "OMPL: refuse a new state whose cost to come plus cost to go cannot improve the solution"},
        {"number_sampling_attempts", "OMPL: attempts at drawing a useful sample before an iteration gives up"},
        {"ordered_sampling", "OMPL: draw samples in batches and use them in the order of their heuristic cost"},
        {"ordering_batch_size", "OMPL: samples per batch with ordered_sampling"},
        {"prune_threshold", "OMPL: fraction by which the solution cost must improve before the tree is pruned again"},
        {"pruned_measure", "OMPL: the rewiring radius from the measure of the space left after pruning, not the whole"},
        {"sample_rejection", "OMPL: reject samples whose heuristic cost cannot improve the solution"},
        {"tree_pruning", "OMPL: remove the tree's vertices that cannot improve the solution, once there is one"},
        {"use_admissible_heuristic", "OMPL: pruning and rejection use an admissible cost-to-go bound (else an estimate)"},
        // BIT*'s
        {"delay_rewiring_to_first_solution", "OMPL: BIT* does not rewire its graph before it has a solution"},
        {"drop_unconnected_samples_on_prune", "OMPL: BIT* drops the samples not in its graph when it prunes"},
        {"find_approximate_solutions", "OMPL: BIT* keeps the vertex nearest the goal and returns it when no path is found"},
        {"prune_threshold_as_fractional_cost_change", "OMPL: fraction by which the solution cost must improve before BIT* prunes again"},
        {"stop_on_each_solution_improvement", "OMPL: BIT*'s solve() returns each time the solution improves"},
        {"use_graph_pruning", "OMPL: BIT* removes the vertices and samples that cannot improve the solution"},
        {"use_just_in_time_sampling", "OMPL: BIT* samples only as far out as the current solution cost needs"},
        {"use_strict_queue_ordering", "OMPL: BIT* re-sorts its queue whenever a cost changes (else once per batch)"},
    };
    return m;
}
}  // namespace

std::string parameterHelp(const std::string &name)
{
    for (const auto &f : carLatticeSettingFields())
        if (f.name == name) return f.help;
    for (const auto &f : improvedSettingFields())
        if (f.name == name) return f.help;
    for (const auto &f : cornerWeightFields())
        if (f.name == name) return f.help;
    const auto &m = singles();
    const auto it = m.find(name);
    if (it != m.end()) return it->second;
    return "OMPL's parameter of this planner (see OMPL's documentation of the planner)";
}

std::string parameterType(const std::string &range)
{
    if (range == "0,1") return "flag";
    if (range.find(':') != std::string::npos) return range.find('.') == std::string::npos ? "whole number" : "number";
    if (range.find(',') != std::string::npos) return "choice";
    return "text";
}

}  // namespace gridcar
