#pragma once
/// @file CarCollision.h
/// @brief What the car lattice search asks about collisions, answered either by gridcar's
/// FootprintChecker (distance-field fast paths, grown rectangle) or by any OMPL
/// SpaceInformation (its own validity checker, pose by pose).

#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Pose2.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace gridcar
{
/// The one collision model of the search families: the car lattice (CarLatticeSearch) and the
/// grid lattice (GridFamily, whose move cache decorates it) both ask it, whether the validity
/// checker is gridcar's (FootprintCollision) or any OMPL application's (SpaceCollision).
class CarCollision
{
public:
    virtual ~CarCollision() = default;
    /// World rectangle the lattice may use: x0, y0, x1, y1.
    virtual std::array<double, 4> extent() const = 0;
    /// The car at pose @p p is valid (in bounds, free).
    virtual bool poseFree(const Pose2 &p) const = 0;
    /// The car fits at one of @p steps equally spaced headings at (x, y).
    bool fitsAtSomeHeading(double x, double y, int steps) const;
    /// The motion from @p from through poses 1..n (poseAt(i)) is free. The poses are spaced so
    /// that no body point moves more than 2 @p margin (m) from one to the next: a checker that
    /// can grow the rectangle by the margin certifies the sweep; one that cannot checks the
    /// poses alone.
    virtual bool curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double margin) const = 0;
    /// How far the farthest body point is from the reference point (m): sample counts of
    /// curves scale by 1 + reach / R so that body points move at most the lattice spacing.
    virtual double reach() const = 0;
    /// Once per query: the world yaws of the lattice headings (the 2D heuristic's axes).
    virtual void setHeadings(const std::vector<double> &yaws) = 0;
    /// False only if the car cannot stand at (x, y) lined up with heading @p h or its reverse.
    virtual bool mayStandOnAxis(double x, double y, int h) const = 0;
    /// Bit h set where mayStandOnAxis(x, y, h), for h below @p axes; std::invalid_argument for
    /// more than 32 axes (or, on gridcar's checker, more than the headings set).
    virtual std::uint32_t axesStanding(double x, double y, int axes) const;
    /// False only if the car cannot stand at (x, y) at any of the headings.
    virtual bool mayStandAt(double x, double y) const = 0;
    /// True if the answers are relaxations (the heuristic is then a lower bound).
    virtual bool relaxed() const = 0;
    /// The straight move from @p a to @p b at their (equal) heading: both end poses and the
    /// swept motion between them are free (the grid lattice's 8-connected moves).
    virtual bool segmentFree(const Pose2 &a, const Pose2 &b) const = 0;
    /// The map's cells when the model has them (gridcar's checker), else null.
    virtual const OccupancyGrid *cells() const { return nullptr; }
    /// A point vehicle on gridcar's checker: a grid move is free when its target cell is.
    virtual bool pointVehicle() const { return false; }
    /// The map's cells changed (FootprintChecker::cellsChanged()): forget what was learnt of them.
    virtual void mapChanged() {}
};

/// A pose with the cosine and sine of its yaw (a caller that has them spares the motion check
/// the trigonometric calls).
struct OrientedPose
{
    Pose2 p;
    double c, s;
};

/// gridcar's own checker: the distance field's disc cover and inscribed discs, the rectangle
/// grown by the margin, so a free curve is a free sweep. The heuristic tests are relaxations.
class FootprintCollision : public CarCollision
{
public:
    explicit FootprintCollision(const FootprintChecker &checker) : c_(checker) {}
    std::array<double, 4> extent() const override;
    bool poseFree(const Pose2 &p) const override { return c_.isValid(p); }
    bool curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double margin) const override;
    /// curveFree() with poseAt(i) an OrientedPose, any callable (inlined: the car lattice's
    /// primitives give the cosines and sines of their samples, turned by the frame).
    template <class PoseAt>
    bool curveFreeOriented(const Pose2 &from, int n, PoseAt &&poseAt, double margin) const;
    double reach() const override { return c_.reach(); }
    void setHeadings(const std::vector<double> &yaws) override;
    bool mayStandOnAxis(double x, double y, int h) const override;
    /// One lookup answers every axis in open ground.
    std::uint32_t axesStanding(double x, double y, int axes) const override;
    bool mayStandAt(double x, double y) const override;
    bool relaxed() const override { return true; }
    bool segmentFree(const Pose2 &a, const Pose2 &b) const override { return c_.isMotionValid(a, b); }
    const OccupancyGrid *cells() const override { return &c_.grid(); }
    bool pointVehicle() const override { return c_.vehicle().isPoint(); }
    void mapChanged() override
    {
        lastFrom_ = {std::nan(""), std::nan(""), std::nan("")};
        lastMargin_ = std::nan("");
    }

private:
    const FootprintChecker &c_;
    /// freeSlack() of the last start pose curveFree() was asked about, at that margin (NaN: none yet)
    mutable Pose2 lastFrom_{std::nan(""), std::nan(""), std::nan("")};
    mutable double lastMargin_{std::nan("")}, lastSlack_{0};
    /// Inscribed-disc offsets per heading and its reverse.
    std::vector<std::vector<std::array<double, 2>>> discs_, discsBack_;
};

template <class PoseAt>
bool FootprintCollision::curveFreeOriented(const Pose2 &from, int n, PoseAt &&poseAt, double m) const
{
    // No body point moves more than 2 m from one pose to the next (the caller's spacing). A
    // pose whose body the distance field proves free with slack r (freeSlack(): every body
    // point may move r) proves the next (r - sqrt(2) m) / 2 m poses free with the margin (the
    // grown rectangle's corners reach sqrt(2) m out): in open space one lookup stands for many
    // poses. Where it proves too little, the pose is checked exactly with the margin (FCL only
    // where the distance field cannot decide). Stops at the first pose in collision. Which
    // proofs are tried changes the cost, never the answer: true exactly when every pose is free.
    const double step = 2 * m, grown = M_SQRT2 * m;
    const auto reach = [&](double slack) {
        return slack > grown && step > 0 ? std::min(double(n), std::floor((slack - grown) / step)) : 0.0;
    };
    // the room at the start: the search asks it for each motion of one expansion in turn
    // (its value is exact only above this margin's threshold: kept per margin)
    if (!(lastFrom_.x == from.x && lastFrom_.y == from.y && lastFrom_.yaw == from.yaw && lastMargin_ == m))
    {
        lastFrom_ = from;
        lastMargin_ = m;
        lastSlack_ = c_.freeSlack(from, grown);
    }
    int proven = int(reach(lastSlack_));  // poses 1..proven are free
    if (proven >= n) return true;
    // the cheap proof of a collision (inscribed discs) at the last pose first; with the every
    // 16th poses below, these proofs find the motions they found when all were tested first,
    // with 30 % of the tests (paper I's car on its 20 Tsudanuma pairs: 304 991 motions)
    constexpr int kCoarse = 16;
    {
        const OrientedPose q = poseAt(n);
        if (c_.provenBlocked(q.p, q.c, q.s)) return false;
    }
    bool coarse = false;
    for (int i = proven + 1; i <= n; ++i)
    {
        const OrientedPose q = poseAt(i);
        const double slack = c_.freeSlack(q.p, q.c, q.s, grown);
        if (slack > grown)
        {
            i += int(std::min(reach(slack), double(n - i)));
            continue;
        }
        // before the first exact test, the same proof at every kCoarse-th pose from the end
        // down to here, so that a motion ending in collision is not tested pose by pose on its
        // way there; a motion proven free by its slack all along never pays for it
        if (!coarse)
        {
            coarse = true;
            for (int k = n - kCoarse; k > i; k -= kCoarse)
            {
                const OrientedPose c = poseAt(k);
                if (c_.provenBlocked(c.p, c.c, c.s)) return false;
            }
        }
        if (!c_.isValidInflated(q.p, q.c, q.s, m)) return false;
    }
    return true;
}

/**
 * Any OMPL SpaceInformation over an SE(2)-derived space: validity is `si->isValid()` (bounds
 * included, and a thousandth of their diagonal, at most 1 cm, inside them) at every pose, so a curve is as safe as the checker at the lattice's spacing. The
 * heuristic's axis test asks the checker at the node lined up with the step (either way): not a
 * proven relaxation for an unknown body, so the path is near-optimal rather than bounded.
 */
class SpaceCollision : public CarCollision
{
public:
    explicit SpaceCollision(ompl::base::SpaceInformationPtr si);
    ~SpaceCollision() override;
    SpaceCollision(const SpaceCollision &) = delete;
    SpaceCollision &operator=(const SpaceCollision &) = delete;
    std::array<double, 4> extent() const override;
    bool poseFree(const Pose2 &p) const override;
    bool curveFree(const Pose2 &from, int n, const std::function<Pose2(int)> &poseAt, double margin) const override;
    double reach() const override { return 0.0; }
    void setHeadings(const std::vector<double> &yaws) override { yaws_ = yaws; }
    bool mayStandOnAxis(double x, double y, int h) const override;
    bool mayStandAt(double, double) const override { return true; }
    bool relaxed() const override { return false; }
    /// The application's checker at both ends and its motion validator between them.
    bool segmentFree(const Pose2 &a, const Pose2 &b) const override;

private:
    ompl::base::SpaceInformationPtr si_;
    ompl::base::State *scratch_;
    ompl::base::State *scratchB_;
    std::vector<double> yaws_;
    std::array<double, 2> boundsLow_{}, boundsHigh_{};
    double boundsMargin_{0.0};  ///< poses keep this far inside the bounds (see poseFree())
};

}  // namespace gridcar
