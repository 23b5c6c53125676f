#include "gridcar/map/ParkingScenes.h"

#include "gridcar/core/Angles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace gridcar
{
namespace
{
/// A scene under construction: a free grid over a world box, obstacles drawn in world terms.
class Canvas
{
public:
    Canvas(double x0, double y0, double x1, double y1, double res)
      : grid_(int(std::ceil((x1 - x0) / res - 1e-9)), int(std::ceil((y1 - y0) / res - 1e-9)), res)
    {
        grid_.setOrigin(x0, y0);
    }
    /// Occupies the cells whose centres lie in the axis-aligned box.
    void rect(double x0, double y0, double x1, double y1)
    {
        for (int r = 0; r < grid_.height(); ++r)
        {
            const double y = grid_.cellCenterY(r);
            if (y < y0 || y > y1) continue;
            for (int c = 0; c < grid_.width(); ++c)
            {
                const double x = grid_.cellCenterX(c);
                if (x >= x0 && x <= x1) grid_.set(c, r, CellState::Occupied);
            }
        }
    }
    /// Occupies the cells whose centres lie in the car's body at reference pose @p p.
    void car(const VehicleParams &v, const Pose2 &p)
    {
        const double c = std::cos(p.yaw), s = std::sin(p.yaw);
        for (int r = 0; r < grid_.height(); ++r)
            for (int col = 0; col < grid_.width(); ++col)
            {
                const double dx = grid_.cellCenterX(col) - p.x, dy = grid_.cellCenterY(r) - p.y;
                const double bx = c * dx + s * dy, by = -s * dx + c * dy;
                if (bx >= -v.rearOverhang && bx <= v.length - v.rearOverhang && std::abs(by) <= v.width / 2)
                    grid_.set(col, r, CellState::Occupied);
            }
    }
    /// Walls round the whole box.
    void border(double t)
    {
        const double x0 = grid_.originX(), y0 = grid_.originY(), x1 = x0 + grid_.sizeX(), y1 = y0 + grid_.sizeY();
        rect(x0, y0, x1, y0 + t);
        rect(x0, y1 - t, x1, y1);
        rect(x0, y0, x0 + t, y1);
        rect(x1 - t, y0, x1, y1);
    }
    OccupancyGrid take() { return std::move(grid_); }

private:
    OccupancyGrid grid_;
};

/// The reference (rear-axle) pose of a car whose body centre is at (cx, cy), heading yaw.
Pose2 fromCentre(const VehicleParams &v, double cx, double cy, double yaw)
{
    const double d = v.centreOffset();
    return {cx - d * std::cos(yaw), cy - d * std::sin(yaw), yaw};
}

struct Sizes
{
    double L, W, sl, sw, aisle, t, front, rear;
};

ParkingScene perpendicular(const VehicleParams &v, const Sizes &z, double res)
{
    const int n = 7, target = 3;
    const double E = 2.5 * z.L;
    const double X = 2 * E + n * z.sw, Y = 2 * z.t + 2 * z.sl + z.aisle;
    Canvas cv(0, 0, X, Y, res);
    cv.border(z.t);
    const double yBottom = z.t + z.sl / 2, yTop = Y - z.t - z.sl / 2, yAisle = z.t + z.sl + z.aisle / 2;
    // the slot rows exist only between the two ends of the aisle; beyond them, walls
    cv.rect(0, 0, E, z.t + z.sl);
    cv.rect(E + n * z.sw, 0, X, z.t + z.sl);
    cv.rect(0, Y - z.t - z.sl, E, Y);
    cv.rect(E + n * z.sw, Y - z.t - z.sl, X, Y);
    ParkingScene sc;
    sc.name = "perpendicular";
    for (int k = 0; k < n; ++k)
    {
        const double cx = E + (k + 0.5) * z.sw;
        const double yaw = k % 2 ? M_PI / 2 : -M_PI / 2;  // nose-in and backed-in in turn
        if (k != target) sc.parkedCars.push_back(fromCentre(v, cx, yBottom, yaw));
        sc.parkedCars.push_back(fromCentre(v, cx, yTop, -yaw));
    }
    for (const Pose2 &p : sc.parkedCars) cv.car(v, p);
    sc.grid = cv.take();
    const double cx = E + (target + 0.5) * z.sw;
    const Pose2 noseIn = fromCentre(v, cx, yBottom, -M_PI / 2), backedIn = fromCentre(v, cx, yBottom, M_PI / 2);
    const Pose2 aisleStart{z.t + 1.0 + z.rear, yAisle, 0.0}, aisleEnd{X - z.t - 1.0 - z.front, yAisle, 0.0};
    sc.queries = {{"perpendicular/park-forwards", aisleStart, noseIn},
                  {"perpendicular/back-in", aisleStart, backedIn},
                  {"perpendicular/leave-nose-in", noseIn, aisleEnd},
                  {"perpendicular/leave-backed-in", backedIn, aisleEnd}};
    return sc;
}

ParkingScene parallel(const VehicleParams &v, const Sizes &z, double gapLengths, double res)
{
    const double lane = z.W + 0.6, road = 7.0;
    const double gap = gapLengths * z.L, a = 3.0 * z.L;  // a: front bumper of the car behind the gap
    const double X = a + gap + 3.0 * z.L, Y = 2 * z.t + lane + road;
    Canvas cv(0, 0, X, Y, res);
    cv.border(z.t);
    const double yParked = z.t + 0.3 + z.W / 2, yLane = z.t + lane + road / 4;
    ParkingScene sc;
    sc.name = "parallel";
    sc.parkedCars = {fromCentre(v, a - z.L / 2, yParked, 0.0), fromCentre(v, a - 1.5 * z.L - 1.0, yParked, 0.0),
                     fromCentre(v, a + gap + z.L / 2, yParked, 0.0), fromCentre(v, a + gap + 1.5 * z.L + 1.0, yParked, 0.0)};
    for (const Pose2 &p : sc.parkedCars) cv.car(v, p);
    sc.grid = cv.take();
    const Pose2 parked = fromCentre(v, a + gap / 2, yParked, 0.0);
    sc.queries = {{"parallel/park", {z.t + 1.0 + z.rear, yLane, 0.0}, parked},
                  {"parallel/leave", parked, {X - z.t - 1.0 - z.front, yLane, 0.0}}};
    return sc;
}

ParkingScene deadEnd(const VehicleParams &v, const Sizes &z, double width, double length, double res)
{
    const double yard = std::max(16.0, 3.0 * z.L), Y = std::max(26.0, width + 4.0 * z.L);
    const double X = length;
    Canvas cv(-yard, 0, X, Y, res);
    cv.border(z.t);
    const double y0 = (Y - width) / 2, y1 = (Y + width) / 2, yc = Y / 2;
    cv.rect(0, 0, X, y0);  // the street's side walls (solid blocks) and its closed end (the border)
    cv.rect(0, y1, X, Y);
    ParkingScene sc;
    sc.name = "dead-end";
    sc.grid = cv.take();
    (void)v;
    const Pose2 deepIn{X - z.t - 1.0 - z.front, yc, 0.0};        // facing the closed end
    const Pose2 deepOut{X - z.t - 1.0 - z.rear, yc, M_PI};       // backed up to it, facing out
    const Pose2 yardOut{-yard / 2 - z.front / 2, yc, M_PI};       // in the yard, driving away
    const Pose2 yardIn{-yard + z.t + 1.0 + z.rear, yc, 0.0};      // in the yard, facing the street
    sc.queries = {{"dead-end/turn-round-and-leave", deepIn, yardOut}, {"dead-end/enter-and-face-out", yardIn, deepOut}};
    return sc;
}

ParkingScene lot(const VehicleParams &v, const Sizes &z, double res)
{
    const int n = 8;
    const double A = z.aisle, road = 8.0;
    const double LX = 2 * A + n * z.sw, LY = 4 * z.sl + 2 * A;  // the lot's inside
    const double X0 = -road - 2 * z.t, X1 = LX + z.t, Y1 = LY + 2 * z.t;
    Canvas cv(X0, 0, X1, Y1, res);
    cv.border(z.t);
    // the lot's left wall, with the entrance opposite the lower aisle
    const double yIn = z.t + z.sl, yInTop = yIn + A;
    cv.rect(-z.t, 0, 0, yIn);
    cv.rect(-z.t, yInTop, 0, Y1);
    // rows of slots (lower edge y, the yaw of a car parked nose-in)
    struct Row
    {
        double y;
        double noseIn;
    };
    const std::array<Row, 4> rows{{{z.t, -M_PI / 2},
                                   {z.t + z.sl + A, M_PI / 2},
                                   {z.t + 2 * z.sl + A, -M_PI / 2},
                                   {z.t + 3 * z.sl + 2 * A, M_PI / 2}}};
    auto centre = [&](int row, int k) { return std::array<double, 2>{A + (k + 0.5) * z.sw, rows[std::size_t(row)].y + z.sl / 2}; };
    auto pose = [&](int row, int k, bool noseIn) {
        const auto c = centre(row, k);
        const double yaw = rows[std::size_t(row)].noseIn + (noseIn ? 0.0 : M_PI);
        return fromCentre(v, c[0], c[1], std::atan2(std::sin(yaw), std::cos(yaw)));
    };
    // empty slots: the four queries' ends
    const int backInRow = 0, backInK = 5, forwardRow = 1, forwardK = 2, leaveNoseRow = 3, leaveNoseK = 6,
              leaveBackRow = 2, leaveBackK = 4;
    ParkingScene sc;
    sc.name = "lot";
    for (int row = 0; row < 4; ++row)
        for (int k = 0; k < n; ++k)
        {
            if ((row == backInRow && k == backInK) || (row == forwardRow && k == forwardK) ||
                (row == leaveNoseRow && k == leaveNoseK) || (row == leaveBackRow && k == leaveBackK))
                continue;
            sc.parkedCars.push_back(pose(row, k, (row + k) % 3 != 0));
        }
    for (const Pose2 &p : sc.parkedCars) cv.car(v, p);
    sc.grid = cv.take();
    const double xRoad = -z.t - road / 2;
    const Pose2 roadNorth{xRoad, z.t + 1.0 + z.rear, M_PI / 2};
    const Pose2 roadSouthEnd{xRoad, z.t + 1.0 + z.front, -M_PI / 2};
    const Pose2 roadNorthEnd{xRoad, Y1 - z.t - 1.0 - z.front, M_PI / 2};
    sc.queries = {{"lot/enter-and-park-forwards", roadNorth, pose(forwardRow, forwardK, true)},
                  {"lot/enter-and-back-in", roadNorth, pose(backInRow, backInK, false)},
                  {"lot/leave-nose-in", pose(leaveNoseRow, leaveNoseK, true), roadSouthEnd},
                  {"lot/leave-backed-in", pose(leaveBackRow, leaveBackK, false), roadNorthEnd}};
    return sc;
}

bool positive(double v) { return std::isfinite(v) && v > 0; }
}  // namespace

std::vector<ParkingScene> parkingScenes(const VehicleParams &car, const ParkingSceneParams &p)
{
    car.validate();
    if (car.isPoint()) throw std::invalid_argument("parking scenes: a point vehicle has no body to park");
    for (double x : {p.resolution, p.aisle, p.parallelGap, p.streetWidth, p.streetLength, p.wall})
        if (!positive(x)) throw std::invalid_argument("parking scenes: every size must be a finite number > 0");
    if (!(std::isfinite(p.slotExtraLength) && p.slotExtraLength >= 0 && std::isfinite(p.slotExtraWidth) &&
          p.slotExtraWidth >= 0))
        throw std::invalid_argument("parking scenes: slot margins must be finite numbers >= 0");
    if (p.resolution > 0.5) throw std::invalid_argument("parking scenes: resolution must be at most 0.5 m");
    if (p.streetWidth <= car.width + 0.2 || p.streetLength <= 2 * car.length)
        throw std::invalid_argument("parking scenes: the dead-end street must be wider than the car and two car lengths long");
    Sizes z;
    z.L = car.length;
    z.W = car.width;
    z.sl = car.length + p.slotExtraLength;
    z.sw = car.width + p.slotExtraWidth;
    z.aisle = p.aisle * std::max(1.0, car.length / 4.5);
    z.t = p.wall;
    z.front = car.length - car.rearOverhang;
    z.rear = car.rearOverhang;
    std::vector<ParkingScene> out = {perpendicular(car, z, p.resolution), parallel(car, z, p.parallelGap, p.resolution),
                                     deadEnd(car, z, p.streetWidth, p.streetLength, p.resolution), lot(car, z, p.resolution)};
    for (ParkingScene &s : out)  // yaws in [-pi, pi), OMPL's SO(2) bounds
    {
        for (Pose2 &c : s.parkedCars) c.yaw = wrapYaw(c.yaw);
        for (ParkingQuery &q : s.queries) q.start.yaw = wrapYaw(q.start.yaw), q.goal.yaw = wrapYaw(q.goal.yaw);
    }
    return out;
}

}  // namespace gridcar
