/// @file CurvatureStep.cpp
/// @brief The car lattice's continuous-curvature post-processor.
#include "gridcar/planners/search/CurvatureStep.h"

#include "gridcar/path/ContinuousCurvature.h"

#include <utility>

namespace gridcar
{
CurvatureStep::CurvatureStep(const CarLatticeSearch &search, double maxCurvature, double curvatureRate)
  : search_(search), maxCurvature_(maxCurvature), curvatureRate_(curvatureRate)
{
}

CurvatureStepReport CurvatureStep::apply(std::vector<Pose2> &path, const std::function<bool()> &cancelled) const
{
    // poses no farther apart than lets a body point move the lattice's spacing, so that the
    // search's own swept-motion test certifies each replacement
    const CarLatticeConfig &cfg = search_.lattice().config();
    CurvatureSmoothingOptions o;
    o.maxCurvature = maxCurvature_;
    o.maxCurvatureRate = curvatureRate_;
    o.step = cfg.spacing / (1.0 + cfg.reach * maxCurvature_);
    o.reversing = true;
    o.cancelled = cancelled;
    o.free = [this](const std::vector<Pose2> &poses) {
        return search_.curveFree(poses[0], int(poses.size()) - 1, [&poses](int i) { return poses[std::size_t(i)]; });
    };
    CurvatureSmoothing s = smoothCurvature(path, o);
    CurvatureStepReport rep{s.stretches, s.replaced, s.cancelled};
    if (!s.cancelled) path = std::move(s.path);
    // clothoid turns keep the rate but turn at full lock: wider where the map leaves room, with
    // 5 cm more room than the search's margin (as the shortcut: for the follower)
    if (!s.cancelled && cfg.curvatureRate > 0)
    {
        o.free = [this](const std::vector<Pose2> &poses) {
            return search_.curveFree(poses[0], int(poses.size()) - 1, [&poses](int i) { return poses[std::size_t(i)]; }, 0.05);
        };
        CurvatureSmoothing w = widenTurns(path, o);
        rep.cancelled = w.cancelled;
        if (!w.cancelled) path = std::move(w.path);
    }
    return rep;
}

}  // namespace gridcar
