#pragma once
/// @file GridLatticePlanner.h
/// @brief The planner of the grid lattice: GridPlanner over GridFamily, with a node type the
/// subclass supplies.

#include "gridcar/planners/GridFamily.h"
#include "gridcar/planners/GridPlanner.h"

#include <memory>
#include <string>

namespace gridcar
{
/**
 * @brief A planner of the grid lattice: the map's cells (or, on an SE(2) space that is not
 * gridcar's, cells of `lattice_cell` over its bounds) searched with the node type the subclass
 * supplies (makeGridNodes(): the papers' searches, plain 8-connected A*). Its paths are cell
 * polylines: straight steps whatever the space.
 *
 * `allow_corner_cutting`: a diagonal move may cut past a blocked side cell (default false: the
 * Moving AI rule). setup() refuses the lattice's per-map arrays when they alone would exceed
 * `max_memory_mb` (solve() then returns ABORT with the reason).
 */
class GridLatticePlanner : public GridPlanner
{
public:
    GridLatticePlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name);

    bool usesCarLattice() const final { return false; }
    bool allowCornerCutting() const { return allowCornerCutting_; }
    void setAllowCornerCutting(bool v);

protected:
    /// The node type of this planner as configured (called by setup()).
    virtual std::unique_ptr<GridNodes> makeGridNodes() = 0;
    void setupFamily(const std::shared_ptr<CarCollision> &collision) override;
    FamilyRun searchFamily(const ompl::base::State *start, const GoalTarget &goal, const std::function<bool()> &cancelled,
                           std::atomic<std::uint64_t> *progress) override;
    void familyData(ompl::base::PlannerData &data, PlannerDataStates &states) const override;
    /// The records of the last search are freed; the move cache (map and vehicle only) is kept.
    void clearFamily() override { grid_.clear(); }
    void mapChangedFamily() override { grid_.forgetMoves(); }
    std::string cannotSearch() const override { return tooBig_; }

private:
    GridFamily grid_;
    bool allowCornerCutting_{false};
    std::string tooBig_;  ///< set by setup() when the lattice's arrays exceed the bound
};

}  // namespace gridcar
