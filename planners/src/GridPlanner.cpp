#include "gridcar/planners/GridPlanner.h"

#include "gridcar/planners/SmoothedPlanner.h"
#include "gridcar/spaces/OmplAdapters.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalRegion.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <cstdio>
#include <cmath>

namespace gridcar
{
GridPlanner::GridPlanner(const ompl::base::SpaceInformationPtr &si, const std::string &name)
  : ompl::base::Planner(si, name)
{
    specs_.approximateSolutions = true;
    specs_.optimizingPaths = false;  // optimal for their own search cost, not for an objective
    specs_.directed = true;
    specs_.multithreaded = false;
    specs_.recognizedGoal = ompl::base::GOAL_REGION;
    declareParam<bool>("allow_corner_cutting", this, &GridPlanner::setAllowCornerCutting,
                       &GridPlanner::allowCornerCutting, "0,1");
    declareParam<bool>("free_start_heading", this, &GridPlanner::setFreeStartHeading,
                       &GridPlanner::freeStartHeading, "0,1");
    declareParam<double>("turning_radius", this, &GridPlanner::setTurningRadius, &GridPlanner::turningRadiusParam,
                         "0.:0.1:100.");
    declareParam<double>("max_memory_mb", this, &GridPlanner::setMaxMemoryMb, &GridPlanner::maxMemoryMb, "0.:256.:65536.");
    declareParam<double>("lattice_cell", this, &GridPlanner::setLatticeCell, &GridPlanner::latticeCell, "0.:0.05:5.");
    declareParam<bool>("match_goal_heading", this, &GridPlanner::setMatchGoalHeading,
                       &GridPlanner::matchGoalHeading, "0,1");
    addPlannerProgressProperty("expanded nodes INTEGER",
                               [this] { return std::to_string(progressExpanded_.load()); });
    // the planner's own cost of its last solution and the seconds its search loop took, to
    // full precision (PlanQuery and the Moving AI runner read them)
    auto exact = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        return std::string(buf);
    };
    addPlannerProgressProperty("search cost REAL", [this, exact] { return exact(lastCost_); });
    addPlannerProgressProperty("search time REAL", [this, exact] { return exact(lastSearchSeconds_); });
}

GridPlanner::~GridPlanner()
{
    freeDataStates();
    if (scratchA_) si_->freeState(scratchA_);
    if (scratchB_) si_->freeState(scratchB_);
}

void GridPlanner::setAllowCornerCutting(bool v)
{
    if (v != allowCornerCutting_) moveCache_.zero();
    allowCornerCutting_ = v;
    parameterSet("allow_corner_cutting");
}

void GridPlanner::checkParametersAct() const
{
    const bool car = usesCarLattice();
    const std::vector<std::string> other = car ? gridLatticeOnlyParams() : carLatticeOnlyParams();
    for (const std::string &p : setParams_)
        if (std::find(other.begin(), other.end(), p) != other.end())
            throw std::invalid_argument(getName() + ": parameter '" + p + "' acts only on the " +
                                        (car ? "grid lattice (the paper's search on the map's cells: lattice=grid)"
                                             : "car lattice (lattice=car)") +
                                        ", and this planner is configured for the " + (car ? "car" : "grid") + " lattice");
}

bool GridPlanner::builtOnCurrentWorld() const
{
    return builtOnChecker_ == si_->getStateValidityChecker() && builtOnMotion_ == si_->getMotionValidator();
}

const ompl::base::State *GridPlanner::currentStart()
{
    pis_.restart();
    return pis_.nextStart();
}

void GridPlanner::setup()
{
    checkParametersAct();
    ompl::base::Planner::setup();
    if (!builtOnCurrentWorld())
    {
        // a new map (validity checker) or motion validator: nothing built on the old one stays
        car_.reset();
        moveCache_.zero();
        builtOnChecker_ = si_->getStateValidityChecker();
        builtOnMotion_ = si_->getMotionValidator();
    }
    if (!dynamic_cast<const ompl::base::SE2StateSpace *>(si_->getStateSpace().get()))
        throw ompl::Exception(getName(), "needs a state space derived from ompl::base::SE2StateSpace (plain SE2, "
                                         "Dubins, Reeds-Shepp or gridcar::GridSE2StateSpace)");
    auto vc = std::dynamic_pointer_cast<FootprintValidityChecker>(si_->getStateValidityChecker());
    checker_ = vc ? &vc->checker() : nullptr;
    genericVehicle_ = genericVehicle();
    space_ = std::dynamic_pointer_cast<GridSE2StateSpace>(si_->getStateSpace());
    if (!space_) space_ = ownGridSpace();  // any other SE(2) space: the map's cells, or cells from the parameters
    width_ = space_->width();
    height_ = space_->height();
    straightStep_ = space_->cellSize();
    diagStep_ = space_->cellSize() * std::sqrt(2.0);
    if (!scratchA_) scratchA_ = si_->allocState();
    if (!scratchB_) scratchB_ = si_->allocState();
    if (usesCarLattice())
    {
        const CarLatticeConfig cfg = carLatticeConfig();
        const CarLatticeConfig *old = car_ ? &car_->lattice().config() : nullptr;
        if (!old || old->cell != cfg.cell || old->headings != cfg.headings || old->turnRadius != cfg.turnRadius ||
            old->spacing != cfg.spacing || old->reach != cfg.reach)
        {
            auto lattice = std::make_shared<const CarLattice>(cfg);
            car_ = checker_ ? std::make_unique<CarLatticeSearch>(*checker_, lattice)
                            : std::make_unique<CarLatticeSearch>(std::make_shared<SpaceCollision>(si_), lattice);
        }
        return;  // no per-cell move cache or dense search arrays on the car lattice
    }
    car_.reset();
    const std::size_t cells = std::size_t(width_) * height_;
    // the per-map arrays of the grid lattice, refused (solve() then returns ABORT with the
    // reason) when they alone would exceed max_memory_mb
    const double mb = (double(cells) * 8 + (usesDenseSearch() ? 16.0 * double(stateCount()) : 0.0)) / (1024.0 * 1024.0);
    tooBig_.clear();
    if (maxMemoryMb_ > 0 && mb > maxMemoryMb_)
    {
        tooBig_ = "the grid lattice of " + std::to_string(cells) + " cells needs " + std::to_string(long(mb)) +
                  " MB of move cache and search records, more than max_memory_mb " + std::to_string(long(maxMemoryMb_));
        moveCache_.release();
        search_.reset();
        return;
    }
    if (moveCache_.size() != cells * 8) moveCache_.assignZeros(cells * 8);
    if (usesDenseSearch() && (!search_ || search_->size() != stateCount()))
        search_ = std::make_unique<SearchSpace>(stateCount());
}

void GridPlanner::clear()
{
    ompl::base::Planner::clear();
    freeDataStates();
    lastPath_.clear();
    lastExpanded_ = 0;
    progressExpanded_ = 0;
    lastCost_ = 0.0;
    // the move cache depends only on the map and the vehicle: kept
}

bool GridPlanner::poseValid(double x, double y, double yaw) const
{
    if (checker_) return checker_->isValid(x, y, yaw);
    auto *s = scratchA_->as<ompl::base::SE2StateSpace::StateType>();
    s->setXY(x, y);
    s->setYaw(wrapYaw(yaw));
    return si_->satisfiesBounds(scratchA_) && si_->isValid(scratchA_);
}

bool GridPlanner::checkMoveUncached(int col, int row, int d) const
{
    const int nc = col + Moves::dcol[d], nr = row + Moves::drow[d];
    if (nc < 0 || nr < 0 || nc >= width_ || nr >= height_) return false;
    const OccupancyGrid *grid = checker_ ? &checker_->grid() : nullptr;
    if ((d & 1) && !allowCornerCutting_)
    {
        // both side cells of a diagonal must be free (Moving AI rule)
        if (grid)
        {
            if (grid->isBlocked(nc, row) || grid->isBlocked(col, nr)) return false;
        }
        else if (!poseValid(space_->cellCenterX(nc), space_->cellCenterY(row), Moves::yaw(d)) ||
                 !poseValid(space_->cellCenterX(col), space_->cellCenterY(nr), Moves::yaw(d)))
            return false;
    }
    const double yaw = wrapYaw(Moves::yaw(d));
    const Pose2 a{space_->cellCenterX(col), space_->cellCenterY(row), yaw};
    const Pose2 b{space_->cellCenterX(nc), space_->cellCenterY(nr), yaw};
    if (checker_)
    {
        if (checker_->vehicle().isPoint())  // plain grid: the target cell (and the rule above)
            return !grid->isBlocked(nc, nr);
        return checker_->isMotionValid(a, b);
    }
    auto *sa = scratchA_->as<ompl::base::SE2StateSpace::StateType>();
    auto *sb = scratchB_->as<ompl::base::SE2StateSpace::StateType>();
    sa->setXY(a.x, a.y);
    sa->setYaw(yaw);
    sb->setXY(b.x, b.y);
    sb->setYaw(yaw);
    return si_->isValid(scratchA_) && si_->isValid(scratchB_) && si_->checkMotion(scratchA_, scratchB_);
}

bool GridPlanner::fillMoveCache(int col, int row, int d) const
{
    std::uint8_t &c = moveCache_[(std::size_t(row) * width_ + col) * 8 + d];
    c = checkMoveUncached(col, row, d) ? 1 : 2;
    return c == 1;
}

double GridPlanner::octile(int c0, int r0, int c1, int r1) const
{
    const int dx = std::abs(c1 - c0), dy = std::abs(r1 - r0);
    return straightStep_ * std::max(dx, dy) + (diagStep_ - straightStep_) * std::min(dx, dy);
}

bool GridPlanner::isGoal(int col, int row, int dir) const
{
    if (query_.goalIsState)
        return col == query_.goalCol && row == query_.goalRow &&
               (query_.goalDir < 0 || dir < 0 || dir == query_.goalDir);
    setPose(scratchB_, {space_->cellCenterX(col), space_->cellCenterY(row), dir >= 0 ? Moves::yaw(dir) : 0.0});
    return goalRegion_->isSatisfied(scratchB_);
}

ompl::base::PlannerStatus GridPlanner::solve(const ompl::base::PlannerTerminationCondition &timeLimit)
{
    using ompl::base::PlannerStatus;
    if (!builtOnCurrentWorld())
    {
        OMPL_INFORM("%s: the validity checker or motion validator changed since setup(): setting up again", getName().c_str());
        setup_ = false;
    }
    checkValidity();
    freeDataStates();  // PlannerData states are cached by search state, which a new search renumbers
    const ompl::base::PlannerTerminationCondition ptc = withMemoryBound(timeLimit);
    if (car_) return solveCarLattice(ptc);
    if (!tooBig_.empty())
    {
        lastStopReason_ = tooBig_;
        return memoryStatus(false);
    }
    lastPath_.clear();
    lastExpanded_ = 0;
    progressExpanded_ = 0;
    const ompl::base::State *start = currentStart();
    if (!start)
    {
        OMPL_ERROR("%s: no valid start state (off the map or in collision)", getName().c_str());
        return PlannerStatus::INVALID_START;
    }
    const auto *st = start->as<ompl::base::SE2StateSpace::StateType>();
    const LatticeState sl = space_->toLattice(start);
    if (!space_->inBounds(sl))
        return PlannerStatus::INVALID_START;
    query_ = Query();
    query_.startCol = sl.col;
    query_.startRow = sl.row;
    query_.startDir = freeStartHeading_ ? -1 : Moves::fromYaw(st->getYaw());

    auto *goal = pdef_->getGoal().get();
    goalRegion_ = dynamic_cast<const ompl::base::GoalRegion *>(goal);
    if (!goalRegion_)
    {
        OMPL_ERROR("%s: the goal must be a GoalRegion (e.g. GoalState)", getName().c_str());
        return PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
    }
    if (auto *gs = dynamic_cast<const ompl::base::GoalState *>(goal))
    {
        const ompl::base::State *g = gs->getState();
        if (!si_->satisfiesBounds(g) || !si_->isValid(g))
        {
            OMPL_ERROR("%s: goal state is off the map or in collision", getName().c_str());
            return PlannerStatus::INVALID_GOAL;
        }
        const LatticeState gl = space_->toLattice(g);
        query_.goalIsState = true;
        query_.goalCol = gl.col;
        query_.goalRow = gl.row;
        query_.goalDir = matchGoalHeading_ ? Moves::fromYaw(g->as<ompl::base::SE2StateSpace::StateType>()->getYaw()) : -1;
    }

    const std::vector<std::uint32_t> starts = startStates(query_);
    const auto t0 = std::chrono::steady_clock::now();
    const SearchResult res = runSearch(query_, starts, ptc);
    lastSearchSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    lastExpanded_ = res.expanded;
    progressExpanded_ = res.expanded;
    if (res.outcome == SearchOutcome::Cancelled && res.closest == SearchSpace::kNoParent)
        return memoryStopped_ ? memoryStatus(false) : PlannerStatus(PlannerStatus::TIMEOUT);
    const std::uint32_t end = res.outcome == SearchOutcome::Found ? res.goal : res.closest;
    if (end == SearchSpace::kNoParent) return memoryStopped_ ? memoryStatus(false) : PlannerStatus(PlannerStatus::TIMEOUT);
    for (std::uint32_t s = end; s != SearchSpace::kNoParent; s = parentOf(s)) lastPath_.push_back(s);
    std::reverse(lastPath_.begin(), lastPath_.end());
    lastCost_ = gOf(end);

    auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
    path->append(start);
    ompl::base::State *tmp = si_->allocState();
    for (std::size_t i = 1; i < lastPath_.size(); ++i)
    {
        int c, r, d;
        decode(lastPath_[i], c, r, d);
        int pc, pr, pd;
        decode(lastPath_[i - 1], pc, pr, pd);
        setPose(tmp, {space_->cellCenterX(c), space_->cellCenterY(r), std::atan2(double(pr - r), double(c - pc))});  // rows grow downwards
        path->append(tmp);
    }
    si_->freeState(tmp);
    const bool exact = res.outcome == SearchOutcome::Found;
    if (exact)
        if (auto *gs = dynamic_cast<const ompl::base::GoalState *>(goal))
            if (lastPath_.size() > 1 || !si_->equalStates(start, gs->getState())) path->append(gs->getState());
    bool exactAndDrivable = exact;
    // an approximate path stopped by the time limit is returned as it is: smoothing it would
    // run past the limit
    const bool smooth = exact || !ptc.eval();
    notExactBecause_.clear();
    const bool replaced = smooth && postProcess(*path, ptc);
    if (exact && !notExactBecause_.empty())
    {
        exactAndDrivable = false;
        lastStopReason_ = notExactBecause_;
    }
    else if (replaced && exact && checker_)
    {
        // a smoothed path is a drivable solution only if the independent check says so
        const std::string why = smoothedPathVerdict(toPoses(*path), *checker_, ptc);
        if (!why.empty())
        {
            exactAndDrivable = false;
            lastStopReason_ = "the smoothed path is not drivable: " + why;
            OMPL_WARN("%s: %s", getName().c_str(), lastStopReason_.c_str());
        }
    }
    double dist = 0.0;
    goalRegion_->isSatisfied(path->getState(path->getStateCount() - 1), &dist);
    pdef_->addSolutionPath(path, !exactAndDrivable, exact ? 0.0 : dist, getName());
    if (exactAndDrivable) return PlannerStatus::EXACT_SOLUTION;
    if (exact) return PlannerStatus::APPROXIMATE_SOLUTION;
    if (memoryStopped_) return memoryStatus(true);
    if (res.outcome == SearchOutcome::Cancelled) return PlannerStatus(PlannerStatus::TIMEOUT);
    return PlannerStatus::APPROXIMATE_SOLUTION;
}

void GridPlanner::forEachClosed(const std::function<void(std::uint32_t)> &fn) const
{
    if (!search_) return;
    const std::size_t n = stateCount();
    for (std::size_t s = 0; s < n; ++s)
        if (search_->closed(std::uint32_t(s))) fn(std::uint32_t(s));
}

void GridPlanner::getPlannerData(ompl::base::PlannerData &data) const
{
    ompl::base::Planner::getPlannerData(data);
    if (!space_) return;
    if (car_)
    {
        getCarPlannerData(data);
        return;
    }
    // PlannerData identifies vertices by state pointer: one state per expanded search state,
    // owned here until clear() (decoupleFromPlanner() copies them)
    auto stateOf = [&](std::uint32_t s) {
        auto it = dataStates_.find(s);
        if (it != dataStates_.end()) return it->second;
        int c, r, d;
        decode(s, c, r, d);
        ompl::base::State *st = si_->allocState();
        setPose(st, {space_->cellCenterX(c), space_->cellCenterY(r), d >= 0 ? Moves::yaw(d) : 0.0});
        dataStates_.emplace(s, st);
        return st;
    };
    forEachClosed([&](std::uint32_t s) {
        const std::uint32_t p = parentOf(s);
        if (p == SearchSpace::kNoParent)
            data.addStartVertex(ompl::base::PlannerDataVertex(stateOf(s)));
        else
            data.addEdge(ompl::base::PlannerDataVertex(stateOf(p)), ompl::base::PlannerDataVertex(stateOf(s)));
    });
}

void GridPlanner::freeDataStates()
{
    for (auto &kv : dataStates_) si_->freeState(kv.second);
    dataStates_.clear();
    for (auto *st : carDataStates_) si_->freeState(st);
    carDataStates_.clear();
}

}  // namespace gridcar
