#include "gridcar/planners/GridAStar.h"

#include <cmath>

namespace gridcar
{
namespace
{
template <class Owner>
struct CellExpander
{
    const Owner &o;
    CellIndex cells;
    GridHeuristic h;
    double straight, diag;
    int goalCol, goalRow;
    bool goalKnown;
    double heuristicAt(int c, int r) const
    {
        if (h == GridHeuristic::Zero || !goalKnown) return 0.0;
        const int dx = std::abs(goalCol - c), dy = std::abs(goalRow - r);
        switch (h)
        {
            case GridHeuristic::Manhattan: return straight * (dx + dy);
            case GridHeuristic::Euclidean: return straight * std::sqrt(double(dx) * dx + double(dy) * dy);
            case GridHeuristic::Octile: return straight * std::max(dx, dy) + (diag - straight) * std::min(dx, dy);
            default: return 0.0;
        }
    }
    double heuristic(std::uint32_t s) const
    {
        int c, r;
        cells.split(s, c, r);
        return heuristicAt(c, r);
    }
    bool isGoal(std::uint32_t s) const
    {
        // a goal state is one cell: compare indices (no division on the hot path)
        if (goalKnown) return s == cells.of(goalCol, goalRow);
        int c, r;
        cells.split(s, c, r);
        return o.goalTest(c, r, -1);
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r;
        cells.split(s, c, r);
        for (int d = 0; d < 8; ++d)
            if (o.move(c, r, d))
            {
                const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
                emit(cells.of(nc, nr), (d & 1) ? diag : straight, [this, nc, nr] { return heuristicAt(nc, nr); });
            }
    }
};
}  // namespace

GridAStar::GridAStar(const ompl::base::SpaceInformationPtr &si, GridHeuristic h, const std::string &name)
  : GridPlanner(si, name), heuristic_(h)
{
}

std::size_t GridAStar::stateCount() const { return std::size_t(width_) * height_; }

std::vector<std::uint32_t> GridAStar::startStates(const Query &q) const
{
    return {cellIndex().of(q.startCol, q.startRow)};
}

void GridAStar::decode(std::uint32_t s, int &col, int &row, int &dir) const
{
    cellIndex().split(s, col, row);
    dir = -1;
}

SearchResult GridAStar::runSearch(const Query &q, const std::vector<std::uint32_t> &starts,
                                  const ompl::base::PlannerTerminationCondition &ptc)
{
    struct Access
    {
        const GridAStar *self;
        bool goalTest(int c, int r, int d) const { return self->isGoal(c, r, d); }
        bool move(int c, int r, int d) const { return self->moveValid(c, r, d); }
    } access{this};
    CellExpander<Access> ex{access, cellIndex(), heuristic_, straightStep_, diagStep_, q.goalCol, q.goalRow, q.goalIsState};
    return astar(*search_, starts, ex, [&] { return ptc.eval(); }, &progressExpanded_);
}

}  // namespace gridcar
