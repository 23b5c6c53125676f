#include "gridcar/planners/GridAStar.h"

#include <cmath>

namespace gridcar
{
namespace
{
struct CellExpander
{
    const GridFamily &f;
    CellIndex cells;
    GridHeuristic h;
    double straight, diag;
    const GridQuery &q;
    double heuristicAt(int c, int r) const
    {
        if (h == GridHeuristic::Zero || !q.goalKnown) return 0.0;
        const int dx = std::abs(q.goalCol - c), dy = std::abs(q.goalRow - r);
        switch (h)
        {
            case GridHeuristic::Manhattan: return f.towardGoal(straight * (dx + dy));
            case GridHeuristic::Euclidean: return f.towardGoal(straight * std::sqrt(double(dx) * dx + double(dy) * dy));
            case GridHeuristic::Octile: return f.towardGoal(straight * std::max(dx, dy) + (diag - straight) * std::min(dx, dy));
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
        // the target cell: compare indices (no division on the hot path)
        if (q.goalKnown && s == cells.of(q.goalCol, q.goalRow)) return true;
        if (!q.regionTest) return false;
        int c, r;
        cells.split(s, c, r);
        return f.isGoal(c, r, -1);
    }
    double closeness(std::uint32_t s) const
    {
        int c, r;
        cells.split(s, c, r);
        return f.closeness(c, r, -1);
    }
    template <class Emit>
    void successors(std::uint32_t s, Emit &&emit) const
    {
        int c, r;
        cells.split(s, c, r);
        for (int d = 0; d < 8; ++d)
            if (f.moveValid(c, r, d))
            {
                const int nc = c + Moves::dcol[d], nr = r + Moves::drow[d];
                emit(cells.of(nc, nr), (d & 1) ? diag : straight, [this, nc, nr] { return heuristicAt(nc, nr); });
            }
    }
};

/// The plain grid search's node type: a cell, dense.
class CellNodes : public GridNodes
{
public:
    explicit CellNodes(GridHeuristic h) : h_(h) {}
    std::size_t denseStates(const GridFamily &f) const override { return std::size_t(f.width()) * f.height(); }
    std::vector<std::uint32_t> starts(const GridFamily &f) override
    {
        return {f.cellIndex().of(f.query().startCol, f.query().startRow)};
    }
    SearchResult search(GridFamily &f, const std::vector<std::uint32_t> &starts, const std::function<bool()> &cancelled,
                        std::atomic<std::uint64_t> *progress) override
    {
        CellExpander ex{f, f.cellIndex(), h_, f.stepLength(0), f.stepLength(1), f.query()};
        return astar(f.dense(), starts, ex, cancelled, progress);
    }
    void decode(const GridFamily &f, std::uint32_t s, int &col, int &row, int &dir) const override
    {
        f.cellIndex().split(s, col, row);
        dir = -1;
    }

private:
    GridHeuristic h_;
};
}  // namespace

GridAStar::GridAStar(const ompl::base::SpaceInformationPtr &si, GridHeuristic h, const std::string &name)
  : GridLatticePlanner(si, name), heuristic_(h)
{
}

std::unique_ptr<GridNodes> GridAStar::makeGridNodes() { return std::make_unique<CellNodes>(heuristic_); }

}  // namespace gridcar
