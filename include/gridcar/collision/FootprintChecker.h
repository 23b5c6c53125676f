#pragma once
/// @file FootprintChecker.h
/// @brief Body-contour collision checking of a vehicle rectangle or polygon on an occupancy grid (FCL).

#include "gridcar/core/Pose2.h"
#include "gridcar/vehicle/VehicleParams.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/OccupancyGrid.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace fcl
{
template <typename S>
class BroadPhaseCollisionManager;
template <typename S>
class CollisionObject;
}  // namespace fcl

namespace gridcar
{
/**
 * @brief Exact collision checking of the vehicle rectangle against the blocked cells of a map.
 *
 * Semantics: a pose is in collision when the closed vehicle rectangle and the closed square of
 * some blocked cell (occupied, or unknown unless unknown is free, or outside the map) overlap.
 * (Poses whose rectangle only touches a cell edge within floating-point precision may go
 * either way.)
 *
 * isValid() first asks the DistanceField about the cell under the rectangle's centre: with
 * h = resolution * sqrt(2) / 2, it is free if d_O - 2h > circumscribed radius, and in collision
 * if d_O + h < inscribed radius (or the centre's cell is blocked). Next a cover of the rectangle
 * by n discs along its axis (n = ceil(2 length / width), radius sqrt((w/2)^2 + (l/2n)^2)): free if
 * every disc centre has d_O - 2h > that radius (d_O is a centre-to-centre distance: one h for the
 * query point's place in its cell, one for the obstacle cell's extent, so a free verdict is never
 * wrong). Beside a wall, where the circumscribed circle already touches, the discs usually still
 * fit. What they leave undecided is settled exactly without FCL: the rectangle is halved
 * (along its longer side) until each piece is either proven free by the distance field at its
 * centre or is at most a cell long, and such a piece is tested against every blocked cell square
 * within reach by the separating-axis theorem (rectangle and square axes). isValidExact() keeps
 * the independent FCL test (the reference the tests compare against): the vehicle box against
 * runs: the vehicle box against the map's obstacle boundary cells, merged into rectangles (runs
 * along rows, then stacked runs of equal extent) and held in an FCL dynamic AABB tree, plus four
 * boxes that wall off the outside of the map. A rectangle wholly inside an obstacle has its centre
 * on a blocked cell, which the fast path catches, so boundary cells suffice.
 *
 * The "point" vehicle checks only the cell under the point.
 *
 * A polygon footprint (VehicleParams::setFootprint, convex or not) is checked exactly too: the
 * quick verdicts of the rectangle around it still prove it free; a collision is only concluded
 * from the rectangle's centre when that centre lies inside the polygon (with the polygon's own
 * inscribed radius there); what they leave undecided is settled per triangle of the polygon's
 * triangulation, halved until proven free by the distance field or a cell long and then tested
 * against each blocked cell square by separating axes. isValidExact() collides FCL prisms of
 * the triangles with the obstacle boxes. Grown bodies (isValidInflated) grow every triangle by
 * the margin (mitred), which contains the polygon grown by it.
 *
 * @par External documentation
 * J. Pan, S. Chitta, D. Manocha, FCL: A General Purpose Library for Collision and Proximity
 * Queries, ICRA 2012. Paper I (Yao et al. 2020), section 3.3, body-contour cost s(n).
 */
class FootprintChecker
{
public:
    /// @p field must be the distance field of @p grid as it is (its blocked cells are those at
    /// distance 0: the fast tests read the field alone). Throws std::invalid_argument for a
    /// missing grid or field or one of another size.
    FootprintChecker(std::shared_ptr<const OccupancyGrid> grid, std::shared_ptr<const DistanceField> field,
                     const VehicleParams &vehicle);
    ~FootprintChecker();
    FootprintChecker(const FootprintChecker &) = delete;
    FootprintChecker &operator=(const FootprintChecker &) = delete;

    const VehicleParams &vehicle() const { return vehicle_; }
    const OccupancyGrid &grid() const { return *grid_; }
    const DistanceField &field() const { return *field_; }
    std::shared_ptr<const OccupancyGrid> gridPtr() const { return grid_; }
    std::shared_ptr<const DistanceField> fieldPtr() const { return field_; }

    /// True if the vehicle rectangle at the pose overlaps no blocked cell. NaN/inf: false.
    bool isValid(double x, double y, double yaw) const;
    bool isValid(const Pose2 &p) const { return isValid(p.x, p.y, p.yaw); }
    /**
     * @brief The same test for the rectangle grown by @p margin >= 0 on every side. The car
     * lattice checks its motions at poses spaced so that no body point moves more than 2 margin
     * between two of them: every intermediate rectangle then lies inside the grown rectangle of
     * one of the two poses, so the swept motion is certified, not only the sampled poses.
     */
    bool isValidInflated(const Pose2 &p, double margin) const;
    /// The same with @p cs, @p sn = cos and sin of p.yaw given (a caller that has them spares
    /// the trigonometric calls; the answer is the same).
    bool isValidInflated(const Pose2 &p, double cs, double sn, double margin) const;
    /// The distance-field tests alone for the rectangle grown by @p margin: true only when
    /// they prove it free (no FCL; false means "not proven", not "in collision").
    bool provenFree(const Pose2 &p, double margin) const;
    /**
     * @brief How far (m) every point of the body at @p p may move with the body still free,
     * as the distance field proves it: the least slack of the discs that cover the rectangle
     * (each disc's distance to the nearest blocked cell, less its radius and the cells'
     * rounding): the body moved so that no point of it travels farther is free, and so is the
     * rectangle grown by any margin below slack / sqrt(2) (its corners). 0 or less: nothing proven
     * (always so for a point vehicle and for a pose that is not finite). A few lookups, no FCL.
     * The lookups stop at the first disc whose slack is @p below or less: the value returned
     * is then at most @p below, not the least.
     */
    double freeSlack(const Pose2 &p, double below = 0.0) const;
    /// The same with cos and sin of p.yaw given.
    double freeSlack(const Pose2 &p, double cs, double sn, double below) const;
    /**
     * @brief True only if the distance field proves the rectangle in collision: a blocked
     * cell under its centre, or a blocked cell centre within r of a point of its axis where the
     * disc of radius r = min(length, width) / 2 lies inside the rectangle (points at most 2 r apart from
     * end to end). A few lookups; false means "not proven", so a test built on it is a
     * relaxation (the car lattice's 2D heuristic uses it).
     */
    bool provenBlocked(const Pose2 &p) const;
    /// The same with cos and sin of p.yaw given.
    bool provenBlocked(const Pose2 &p, double cs, double sn) const;
    /// The same test split for speed: the world offsets of the inscribed discs' centres from
    /// the reference point at a yaw (computed once per heading), then the lookups at a point.
    std::vector<std::array<double, 2>> inscribedDiscOffsets(double yaw) const;
    /// One bit per disc: the checker keeps the test's answer for every cell of the map.
    bool provenBlockedAt(double x, double y, const std::vector<std::array<double, 2>> &offsets) const;
    /// True only if provenBlockedAt() is false at (x, y) for the discs at every yaw, from one
    /// lookup: @p pointDistance (d_O at the cell of (x, y)) is at least the discs' farthest reach
    /// (offset plus radius) and three half cell diagonals (the point's and each disc's place in
    /// its cell, and the map's border ring), since d_O is 1-Lipschitz between cell centres and 0
    /// on blocked cells. False means "not shown", not "blocked".
    bool discsClearAtEveryYaw(double pointDistance) const { return pointDistance >= discReach_; }
    /// discsClearAtEveryYaw() of d_O at the cell of (x, y) (0 off the map), from a bit per cell
    /// kept for it.
    bool discsClearAtEveryYawAt(double x, double y) const;
    /// What reachability() proved.
    struct Reach
    {
        enum Verdict
        {
            Separated,  ///< proven: no motion of the body joins the two poses
            Joined,     ///< the relaxation joins them (a path may exist, or may not)
            Unknown     ///< not decided within the cell budget, or nothing to decide it on
        } verdict{Unknown};
        int shutEnd{-1};            ///< Separated: the end whose region was run out of (0: a, 1: b)
        std::size_t shutCells{0};   ///< Separated: that region's cells
    };
    /**
     * @brief Fast failure: whether any continuous motion of the body (forwards, backwards,
     * turning on the spot or not) could take it from pose @p a to pose @p b, on the map's
     * cells. A point of the body carries an inscribed disc (the one nearest the reference
     * point of those provenBlocked() reads); at every free pose the disc is free, so the cell
     * under that point is not one where a disc is proven blocked, and as the body moves the
     * point crosses 8-connected such cells. If no 8-connected path of them joins a cell the
     * point can occupy at @p a to one it can occupy at @p b, no motion joins the poses:
     * Separated. With @p anyYawA (@p anyYawB) every heading at that position counts (the
     * cells of the point's circle round it). Two breadth-first searches run in turns from the
     * two ends, the smaller one first, and stop when one runs out (Separated), they meet
     * (Joined) or @p maxCells cells were visited (Unknown): a goal shut in a room is proven
     * unreachable after visiting the room. Unknown for a polygon with no proven disc.
     */
    Reach reachability(const Pose2 &a, bool anyYawA, const Pose2 &b, bool anyYawB, std::size_t maxCells) const;
    /// Farthest point of the rectangle from the reference point (m): how far a body point moves
    /// per radian of rotation.
    double reach() const { return reach_; }
    /// True if the vehicle fits at (x, y) at one of @p headings equally spaced yaws (k 2 pi /
    /// headings, from 0 up, wrapped into [-pi, pi)); @p yaw receives the first that fits.
    bool fitsAtSomeHeading(double x, double y, int headings, double *yaw = nullptr) const;
    /// The exact FCL test alone, no distance-field shortcut (for tests and benchmarks).
    bool isValidExact(double x, double y, double yaw) const;

    /**
     * @brief Swept check: the straight motion from @p a to @p b (yaw along the shorter way) is
     * valid if the footprint is free at poses spaced so that no point of the rectangle moves
     * more than sweepFraction() * resolution between two checks (both ends included).
     * With @p lastValidT, the poses are checked in order from @p a and *lastValidT is set to
     * the largest fraction of the motion found valid before the first collision (for OMPL's
     * MotionValidator); @p a itself is then taken as checked.
     */
    bool isMotionValid(const Pose2 &a, const Pose2 &b, double *lastValidT = nullptr) const;
    double sweepFraction() const { return sweepFraction_; }
    void setSweepFraction(double f);
    /// Number of poses isMotionValid() checks for this motion.
    int sweepSteps(const Pose2 &a, const Pose2 &b) const;

    /**
     * @brief Clearance of the footprint (m): the smallest obstacle distance d_O (bilinear,
     * centre-to-centre, see DistanceField) over points spaced half a cell apart along the
     * rectangle's outline; 0 if the pose is in collision. Accurate to about one cell
     * (the distance to a cell's boundary is up to h less than to its centre).
     */
    double clearance(double x, double y, double yaw) const;

    /**
     * @brief Paper I's detection-point contour check: the node and points on a circle of radius
     * D/2 (half the vehicle width) around it every 45 degrees; valid if none is on a blocked
     * cell. Cheaper than the rectangle, and blind to the vehicle's length.
     */
    bool isValidDetectionPoints(double x, double y) const;

    /// Corners of the rectangle at a pose (counter-clockwise from rear-right).
    void corners(double x, double y, double yaw, double cx[4], double cy[4]) const;

    /// Counters of which path isValid() took (relaxed atomics; for benchmarks and tests).
    struct Stats
    {
        std::uint64_t fastFree{0}, fastCollision{0}, exact{0}, discFree{0};
    };
    Stats stats() const;
    /**
     * @brief After cells of its grid changed within @p cells and its distance field was
     * brought up to date (DistanceField::update() returned @p field): the per-cell tests and
     * the exact check's obstacle boxes made again where they read those cells, so that the
     * checker answers as one made anew on the changed map. Not while other threads check.
     */
    void cellsChanged(const CellWindow &cells, const CellWindow &field);
    /// How many times cellsChanged() was called: a planner that sees it move forgets what it
    /// learnt of the old map (not its set-up).
    std::uint64_t mapVersion() const { return mapVersion_; }
    /// The windows (cells, field) of the cellsChanged() calls after version @p since, oldest
    /// first, for another checker on the same grid and field (a body grown by a margin) to be
    /// brought up to date the same way; nullopt if some are no longer kept (the last 64 are).
    std::optional<std::vector<std::pair<CellWindow, CellWindow>>> changesSince(std::uint64_t since) const;

    /// The FCL boxes the exact check tests against over the whole map (they are made per tile on
    /// first use; this counts them all, a scan of the map).
    std::size_t obstacleBoxCount() const;

private:
    bool cellBlockedAt(double x, double y) const;
    /// Geometry of the (grown) rectangle the fast paths test.
    struct Body
    {
        double length, width, rear;  ///< rear = distance from the reference point to the back
        double rIn, rOut, discR, discStep, firstDisc;
        int discs;
        bool polygon;       ///< a polygon footprint: the rectangle is only its bounding box
        bool centreInside;  ///< the rectangle's centre lies inside the polygon (rIn: its distance to the boundary)
        double margin;
    };
    static Body makeBody(const VehicleParams &v, double margin);
    const Body &bodyFor(double margin) const;
    /// inscribedDiscOffsets() into @p out (cleared first).
    void discOffsetsInto(double yaw, std::vector<std::array<double, 2>> &out) const;
    /// The same at the yaw of cos @p cs, sin @p sn.
    void discOffsetsInto(double cs, double sn, std::vector<std::array<double, 2>> &out) const;
    bool validBody(const Body &b, double x, double y, double yaw) const;
    bool validBody(const Body &b, double x, double y, double yaw, double cs, double sn) const;
    /// True if an inscribed disc (radius discR_) centred in this cell is proven blocked: the
    /// cell itself blocked, or the field closer than the radius less the cell's rounding.
    bool discBlockedCell(int col, int row) const;
    /// discBits_ from discBlockedCell() and clearBits_ from discsClearAtEveryYaw() at every cell.
    void buildDiscBits();
    /// The same bits over the cells of @p w only.
    void setDiscBits(const CellWindow &w);
    /// Bit @p k (row-major cell index) of @p bits.
    static bool cellBit(const std::vector<std::uint64_t> &bits, std::size_t k) { return (bits[k / 64] >> (k % 64)) & 1u; }
    /// 1 proven free, 0 proven blocked, -1 undecided by the distance field.
    int quickBody(const Body &b, double x, double y, double yaw, double cs, double sn) const;
    bool exactBody(const Body &b, double x, double y, double yaw) const;
    /// True if the FCL object @p o (its AABB computed) meets an obstacle box or a wall.
    bool collidesExact(fcl::CollisionObject<double> *o) const;
    /// Exact test of the rectangle centred at (cx, cy) with unit axis (cs, sn), half-length a
    /// and half-width b, by recursive halving against the distance field down to a cell, then
    /// a separating-axis test against each blocked cell square in reach.
    bool rectFree(double cx, double cy, double cs, double sn, double a, double b) const;
    /// Exact test of a world triangle (x0, y0, x1, y1, x2, y2, counter-clockwise) by halving
    /// at its longest edge against the distance field, then separating axes per blocked cell.
    bool triangleFree(const std::array<double, 6> &t, int depth) const;
    /// The polygon footprint (grown by the body's margin) at a pose, exactly.
    bool polygonFree(const Body &b, double x, double y, double cs, double sn) const;

    std::shared_ptr<const OccupancyGrid> grid_;
    std::shared_ptr<const DistanceField> field_;
    VehicleParams vehicle_;
    double rIn_{0}, rOut_{0}, halfDiag_{0}, reach_{0};
    double discReach_{0};  ///< discsClearAtEveryYaw()'s threshold
    double discR_{0};      ///< the radius of provenBlocked()'s discs
    std::vector<std::uint64_t> discBits_;  ///< discBlockedCell() per cell, row-major, one bit each
    std::vector<std::uint64_t> clearBits_;  ///< discsClearAtEveryYaw() per cell, as discBits_
    Body body_{};
    /// A polygon footprint: its triangles in the body frame (x0, y0, x1, y1, x2, y2, CCW), the
    /// discs inside it that prove a collision (provenBlocked) and their radius.
    std::vector<std::array<double, 6>> tris_;
    std::vector<std::array<double, 2>> provenDiscs_;
    double provenR_{0};
    double sweepFraction_{0.5};
    struct ExactTiles;
    std::unique_ptr<ExactTiles> exact_;
    std::uint64_t mapVersion_{0};
    std::deque<std::pair<CellWindow, CellWindow>> changes_;  ///< the last cellsChanged() windows
    mutable std::atomic<std::uint64_t> nFastFree_{0}, nFastCollision_{0}, nExact_{0}, nDiscFree_{0};
};

}  // namespace gridcar
