#include "gridcar/collision/FootprintChecker.h"

#include "gridcar/core/Angles.h"

#include "collision/detail/ExactTiles.h"
#include "collision/detail/FclShapes.h"
#include "collision/detail/Polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

namespace gridcar
{
using detail::makeBox;

FootprintChecker::FootprintChecker(std::shared_ptr<const OccupancyGrid> grid, std::shared_ptr<const DistanceField> field,
                                   const VehicleParams &vehicle)
  : grid_(std::move(grid)), field_(std::move(field)), vehicle_(vehicle)
{
    if (!grid_ || !field_) throw std::invalid_argument("FootprintChecker needs a grid and a distance field");
    if (field_->width() != grid_->width() || field_->height() != grid_->height())
        throw std::invalid_argument("FootprintChecker: distance field does not match the grid");
    vehicle_.validate();
    rIn_ = vehicle_.inscribedRadius();
    rOut_ = vehicle_.circumscribedRadius();
    halfDiag_ = grid_->resolution() * std::sqrt(2.0) / 2.0;
    reach_ = vehicle_.isPoint() ? 0.0 :
                                  std::hypot(std::max(vehicle_.rearOverhang, vehicle_.length - vehicle_.rearOverhang),
                                             vehicle_.width / 2);
    discReach_ = 3 * halfDiag_ + 1e-3;  // a point vehicle's one "disc": the point's own cell
    if (vehicle_.isPoint())
    {
        buildDiscBits();  // (radius 0: the point's own cell)
        return;
    }
    body_ = makeBody(vehicle_, 0.0);
    if (vehicle_.hasPolygon())
    {
        reach_ = 0;
        for (const auto &p : vehicle_.footprint) reach_ = std::max(reach_, std::hypot(p[0], p[1]));
        std::vector<detail::Pt> candidates;
        for (const detail::Tri &t : detail::triangulate(vehicle_.footprint))
        {
            tris_.push_back({t.a[0], t.a[1], t.b[0], t.b[1], t.c[0], t.c[1]});
            candidates.push_back({(t.a[0] + t.b[0] + t.c[0]) / 3, (t.a[1] + t.b[1] + t.c[1]) / 3});
        }
        // discs inside the polygon that prove a collision: at triangle centroids, the radius
        // half the largest clearance any of them has, kept where they have that much
        double best = 0;
        std::vector<double> clear;
        for (const auto &c : candidates)
        {
            clear.push_back(detail::inPolygon(c, vehicle_.footprint) ? detail::boundaryDistance(c, vehicle_.footprint) : 0.0);
            best = std::max(best, clear.back());
        }
        provenR_ = best / 2;
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (clear[i] >= provenR_ && provenR_ > 0) provenDiscs_.push_back(candidates[i]);
    }
    std::vector<std::array<double, 2>> discs;
    discOffsetsInto(0.0, discs);
    double far = 0;
    for (const auto &d : discs) far = std::max(far, std::hypot(d[0], d[1]));
    discR_ = vehicle_.hasPolygon() ? provenR_ : std::min(vehicle_.length, vehicle_.width) / 2;
    discReach_ = far + discR_ + 3 * halfDiag_ + 1e-3;  // (1 mm for the field's float rounding)
    buildDiscBits();

    // The exact check's obstacles: FCL boxes over the obstacle boundary cells, made per tile
    // of the map on the first exact check that reaches the tile (a 24 M-cell map has 170 000
    // such boxes, 0.4-0.6 s to make and sort into a tree, where a path's checks reach a few
    // hundred tiles), and walls round the map thick enough that no footprint reaches past them.
    exact_ = std::make_unique<ExactTiles>(*grid_, 2.0 * rOut_ + 1.0);
}

FootprintChecker::~FootprintChecker() = default;

bool FootprintChecker::cellBlockedAt(double x, double y) const
{
    const Cell c = grid_->worldToCell(x, y);
    return grid_->isBlocked(c.col, c.row);
}

void FootprintChecker::corners(double x, double y, double yaw, double cx[4], double cy[4]) const
{
    const double c = std::cos(yaw), s = std::sin(yaw);
    const double xr = -vehicle_.rearOverhang, xf = vehicle_.length - vehicle_.rearOverhang, hw = vehicle_.width / 2;
    const double bx[4] = {xr, xf, xf, xr}, by[4] = {-hw, -hw, hw, hw};
    for (int i = 0; i < 4; ++i)
    {
        cx[i] = x + c * bx[i] - s * by[i];
        cy[i] = y + s * bx[i] + c * by[i];
    }
}

namespace
{
/// FCL prisms (height 1) of the footprint's triangles, in the body frame.
std::vector<std::unique_ptr<fcl::CollisionObjectd>> trianglePrisms(const std::vector<std::array<double, 6>> &tris)
{
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> out;
    for (const auto &t : tris)
    {
        auto verts = std::make_shared<std::vector<fcl::Vector3d>>();
        for (double z : {-0.5, 0.5})
            for (int i = 0; i < 3; ++i) verts->push_back(fcl::Vector3d(t[2 * i], t[2 * i + 1], z));
        // faces: bottom (clockwise seen from above: outward down), top, three sides
        auto faces = std::make_shared<std::vector<int>>(std::vector<int>{3, 0, 2, 1, 3, 3, 4, 5, 4, 0, 1, 4, 3, 4, 1, 2, 5, 4,
                                                                         4, 2, 0, 3, 5});
        auto geom = std::make_shared<fcl::Convexd>(verts, 5, faces);
        out.push_back(std::make_unique<fcl::CollisionObjectd>(geom, fcl::Transform3d::Identity()));
    }
    return out;
}
}  // namespace

bool FootprintChecker::exactBody(const Body &b, double x, double y, double yaw) const
{
    if (!tris_.empty())
    {
        // the polygon: one FCL prism per triangle, per thread and footprint
        struct CachedPolygon
        {
            std::vector<std::array<double, 6>> tris;
            std::vector<std::unique_ptr<fcl::CollisionObjectd>> objs;
        };
        thread_local CachedPolygon poly;
        if (poly.tris != tris_)
        {
            poly.tris = tris_;
            poly.objs = trianglePrisms(tris_);
        }
        fcl::Transform3d tf = fcl::Transform3d::Identity();
        tf.translation() = fcl::Vector3d(x, y, 0.0);
        tf.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        for (auto &o : poly.objs)
        {
            o->setTransform(tf);
            o->computeAABB();
            if (collidesExact(o.get())) return false;
        }
        return true;
    }
    // one FCL box per thread and body size, moved to the pose (no allocation per check)
    struct Cached
    {
        double length{-1}, width{-1};
        std::unique_ptr<fcl::CollisionObjectd> obj;
    };
    thread_local Cached cache;
    const double cs = std::cos(yaw), sn = std::sin(yaw), off = b.length / 2 - b.rear;
    if (!cache.obj || cache.length != b.length || cache.width != b.width)
    {
        cache.obj = detail::makeBox(0, 0, std::max(b.length, 1e-3), std::max(b.width, 1e-3));
        cache.length = b.length;
        cache.width = b.width;
    }
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    tf.translation() = fcl::Vector3d(x + off * cs, y + off * sn, 0.0);
    tf.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    cache.obj->setTransform(tf);
    cache.obj->computeAABB();
    return !collidesExact(cache.obj.get());
}

bool FootprintChecker::validBody(const Body &b, double x, double y, double yaw) const
{
    if (!std::isfinite(yaw)) return false;
    return validBody(b, x, y, yaw, std::cos(yaw), std::sin(yaw));
}

bool FootprintChecker::validBody(const Body &b, double x, double y, double yaw, double cs, double sn) const
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw)) return false;
    const int q = quickBody(b, x, y, yaw, cs, sn);
    if (q == 0)
    {
        nFastCollision_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    if (q == 1)
    {
        nFastFree_.fetch_add(1, std::memory_order_relaxed);
        return true;
    }
    if (q == 2)
    {
        nDiscFree_.fetch_add(1, std::memory_order_relaxed);
        return true;
    }
    nExact_.fetch_add(1, std::memory_order_relaxed);
    if (b.polygon) return polygonFree(b, x, y, cs, sn);
    const double off = b.length / 2 - b.rear;
    return rectFree(x + off * cs, y + off * sn, cs, sn, b.length / 2, b.width / 2);
}

bool FootprintChecker::isValidExact(double x, double y, double yaw) const
{
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw)) return false;
    if (vehicle_.isPoint()) return !cellBlockedAt(x, y);
    // a point of the body inside an obstacle or off the map (a body wholly inside an obstacle
    // touches no boundary box): the rectangle's centre, or a polygon's first triangle's centroid
    double px = vehicle_.centreOffset(), py = 0.0;
    if (!tris_.empty())
    {
        const auto &t = tris_.front();
        px = (t[0] + t[2] + t[4]) / 3;
        py = (t[1] + t[3] + t[5]) / 3;
    }
    const double cs = std::cos(yaw), sn = std::sin(yaw);
    if (cellBlockedAt(x + cs * px - sn * py, y + sn * px + cs * py)) return false;
    return exactBody(body_, x, y, yaw);
}

bool FootprintChecker::isValid(double x, double y, double yaw) const
{
    if (vehicle_.isPoint()) return std::isfinite(x) && std::isfinite(y) && std::isfinite(yaw) && !cellBlockedAt(x, y);
    return validBody(body_, x, y, yaw);
}

bool FootprintChecker::isValidInflated(const Pose2 &p, double margin) const
{
    if (!(margin > 0.0) || vehicle_.isPoint()) return isValid(p);
    if (!std::isfinite(margin)) return false;
    return validBody(bodyFor(margin), p.x, p.y, p.yaw);
}

bool FootprintChecker::isValidInflated(const Pose2 &p, double cs, double sn, double margin) const
{
    if (!(margin > 0.0) || vehicle_.isPoint()) return isValid(p);
    if (!std::isfinite(margin)) return false;
    return validBody(bodyFor(margin), p.x, p.y, p.yaw, cs, sn);
}

bool FootprintChecker::fitsAtSomeHeading(double x, double y, int headings, double *yaw) const
{
    for (int k = 0; k < headings; ++k)
    {
        const double a = wrapYaw(k * 2.0 * M_PI / headings);
        if (isValid(x, y, a))
        {
            if (yaw) *yaw = a;
            return true;
        }
    }
    return false;
}

void FootprintChecker::setSweepFraction(double f)
{
    if (!(f > 0.0 && f <= 1.0)) throw std::invalid_argument("sweep fraction must be in (0, 1]");
    sweepFraction_ = f;
}

int FootprintChecker::sweepSteps(const Pose2 &a, const Pose2 &b) const
{
    const double dyaw = wrapAngle(b.yaw - a.yaw);
    const double travel = std::hypot(b.x - a.x, b.y - a.y) + std::abs(dyaw) * reach_;
    const double step = sweepFraction_ * grid_->resolution();
    if (!std::isfinite(travel)) return -1;
    return std::max(1, int(std::ceil(travel / step)));
}

bool FootprintChecker::isMotionValid(const Pose2 &a, const Pose2 &b, double *lastValidT) const
{
    if (lastValidT) *lastValidT = 0.0;
    const int n = sweepSteps(a, b);
    if (n < 0 || n > 10000000) return false;
    // without a report of how far the motion is valid, the end pose first (a quick reject)
    if (!lastValidT && !isValid(b)) return false;
    const double dyaw = wrapAngle(b.yaw - a.yaw);
    const int first = lastValidT ? 1 : 0, last = lastValidT ? n : n - 1;
    for (int i = first; i <= last; ++i)
    {
        const double t = double(i) / n;
        if (!isValid(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.yaw + t * dyaw)) return false;
        if (lastValidT) *lastValidT = t;
    }
    return true;
}

double FootprintChecker::clearance(double x, double y, double yaw) const
{
    if (!isValid(x, y, yaw)) return 0.0;
    if (vehicle_.isPoint()) return field_->distance(x, y);
    const auto body = vehicle_.outline();  // the rectangle's corners or the polygon
    const double cs = std::cos(yaw), sn = std::sin(yaw);
    const std::size_t n = body.size();
    double best = std::numeric_limits<double>::infinity();
    const double step = grid_->resolution() / 2;
    for (std::size_t e = 0; e < n; ++e)
    {
        const auto &p = body[e], &q = body[(e + 1) % n];
        const double x0 = x + cs * p[0] - sn * p[1], y0 = y + sn * p[0] + cs * p[1];
        const double x1 = x + cs * q[0] - sn * q[1], y1 = y + sn * q[0] + cs * q[1];
        const int n = std::max(1, int(std::ceil(std::hypot(x1 - x0, y1 - y0) / step)));
        for (int i = 0; i < n; ++i)
        {
            const double t = double(i) / n;
            best = std::min(best, field_->distance(x0 + t * (x1 - x0), y0 + t * (y1 - y0)));
        }
    }
    return best;
}

bool FootprintChecker::isValidDetectionPoints(double x, double y) const
{
    if (!std::isfinite(x) || !std::isfinite(y)) return false;
    if (cellBlockedAt(x, y)) return false;
    const double r = vehicle_.width / 2;
    if (r <= 0) return true;
    for (int k = 0; k < 8; ++k)
    {
        const double a = k * M_PI / 4;
        if (cellBlockedAt(x + r * std::cos(a), y + r * std::sin(a))) return false;
    }
    return true;
}

FootprintChecker::Stats FootprintChecker::stats() const
{
    return Stats{nFastFree_.load(), nFastCollision_.load(), nExact_.load(), nDiscFree_.load()};
}

}  // namespace gridcar
