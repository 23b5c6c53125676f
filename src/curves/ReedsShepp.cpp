/// @file ReedsShepp.cpp
/// @brief Reeds and Shepp's 48 candidate words: nine closed forms (their section 8), each
/// applied to the goal as it is, time-flipped (driven in the other gear), reflected (left and
/// right swapped) and both; the CCC and CCSC forms also to the reversed problem. Every
/// candidate is checked to land on the goal before it is taken.
#include "gridcar/curves/CarCurves.h"

#include "CurveWords.h"

#include <cmath>

namespace gridcar
{
namespace
{
using curves::modPi;
constexpr Steer L = Steer::Left, S = Steer::Straight, R = Steer::Right;
constexpr double kHalfPi = M_PI / 2;

struct Lengths
{
    double t{0}, u{0}, v{0};
};

void polar(double x, double y, double &r, double &theta)
{
    r = std::hypot(x, y);
    theta = std::atan2(y, x);
}

// ---- the closed forms, each for the goal (x, y, phi) at unit radius

/// L+ S+ L+ (8.1).
bool lsl(double x, double y, double phi, Lengths &o)
{
    polar(x - std::sin(phi), y - 1 + std::cos(phi), o.u, o.t);
    o.v = modPi(phi - o.t);
    return o.t >= 0 && o.v >= 0;
}

/// L+ S+ R+ (8.2).
bool lsr(double x, double y, double phi, Lengths &o)
{
    double r, th;
    polar(x + std::sin(phi), y - 1 - std::cos(phi), r, th);
    if (r * r < 4) return false;
    o.u = std::sqrt(r * r - 4);
    o.t = modPi(th + std::atan2(2.0, o.u));
    o.v = modPi(o.t - phi);
    return o.t >= 0 && o.v >= 0;
}

/// L+ R- L (8.3, 8.4: the last arc in either gear).
bool lrl(double x, double y, double phi, Lengths &o)
{
    double r, th;
    polar(x - std::sin(phi), y - 1 + std::cos(phi), r, th);
    if (r > 4) return false;
    o.u = -2 * std::asin(r / 4);
    o.t = modPi(th + o.u / 2 + M_PI);
    o.v = modPi(phi - o.t + o.u);
    return o.t >= 0 && o.u <= 0;
}

/// t and v of the CCCC words from the middle arcs u and v (8.7, 8.8).
void tauOmega(double u, double v, double xi, double eta, double phi, double &tau, double &omega)
{
    const double delta = modPi(u - v), A = std::sin(u) - std::sin(delta), B = std::cos(u) - std::cos(delta) - 1;
    const double t1 = std::atan2(eta * A - xi * B, xi * A + eta * B);
    const double t2 = 2 * (std::cos(delta) - std::cos(v) - std::cos(u)) + 3;
    tau = t2 < 0 ? modPi(t1 + M_PI) : modPi(t1);
    omega = modPi(tau - u + v - phi);
}

/// L+ R+ L- R- with equal middle arcs (8.7): lengths t, u, -u, v.
bool lrlrSame(double x, double y, double phi, Lengths &o)
{
    const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi);
    const double rho = 0.25 * (2 + std::hypot(xi, eta));
    if (rho > 1) return false;
    o.u = std::acos(rho);
    tauOmega(o.u, -o.u, xi, eta, phi, o.t, o.v);
    return o.t >= 0 && o.v <= 0;
}

/// L+ R- L- R+ with equal middle arcs (8.8): lengths t, u, u, v.
bool lrlrOpposite(double x, double y, double phi, Lengths &o)
{
    const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi);
    const double rho = (20 - xi * xi - eta * eta) / 16;
    if (rho < 0 || rho > 1) return false;
    o.u = -std::acos(rho);
    if (o.u < -kHalfPi) return false;
    tauOmega(o.u, o.u, xi, eta, phi, o.t, o.v);
    return o.t >= 0 && o.v >= 0;
}

/// L+ R-[pi/2] S- L- (8.9): lengths t, -pi/2, u, v.
bool lrsl(double x, double y, double phi, Lengths &o)
{
    double r, th;
    polar(x - std::sin(phi), y - 1 + std::cos(phi), r, th);
    if (r < 2) return false;
    const double s = std::sqrt(r * r - 4);
    o.u = 2 - s;
    o.t = modPi(th + std::atan2(s, -2.0));
    o.v = modPi(phi - kHalfPi - o.t);
    return o.t >= 0 && o.u <= 0 && o.v <= 0;
}

/// L+ R-[pi/2] S- R- (8.10): lengths t, -pi/2, u, v.
bool lrsr(double x, double y, double phi, Lengths &o)
{
    double r, th;
    polar(-(y - 1 - std::cos(phi)), x + std::sin(phi), r, th);
    if (r < 2) return false;
    o.t = th;
    o.u = 2 - r;
    o.v = modPi(o.t + kHalfPi - phi);
    return o.t >= 0 && o.u <= 0 && o.v <= 0;
}

/// L+ R-[pi/2] S- L-[pi/2] R+ (8.11): lengths t, -pi/2, u, -pi/2, v.
bool lrslr(double x, double y, double phi, Lengths &o)
{
    const double xi = x + std::sin(phi), eta = y - 1 - std::cos(phi);
    double r, th;
    polar(xi, eta, r, th);
    if (r < 2) return false;
    o.u = 4 - std::sqrt(r * r - 4);
    if (o.u > 0) return false;
    o.t = modPi(std::atan2((4 - o.u) * xi - 2 * eta, -2 * xi + (o.u - 4) * eta));
    o.v = modPi(o.t - phi);
    return o.t >= 0 && o.v >= 0;
}

// ---- the symmetries

using Form = bool (*)(double, double, double, Lengths &);
using Emit = void (*)(curves::Candidates &, const Lengths &, Steer a, Steer b, double sign);

Steer swapped(Steer s) { return s == L ? R : s == R ? L : S; }

/// @p form on the goal, time-flipped, reflected and both; @p emit adds the word with the
/// letters of the base word (a = its first turn, b = the other) and the gear sign.
void fourWays(curves::Candidates &c, Form form, Emit emit, double x, double y, double phi)
{
    Lengths o;
    if (form(x, y, phi, o)) emit(c, o, L, R, 1.0);
    if (form(-x, y, -phi, o)) emit(c, o, L, R, -1.0);
    if (form(x, -y, -phi, o)) emit(c, o, swapped(L), swapped(R), 1.0);
    if (form(-x, -y, phi, o)) emit(c, o, swapped(L), swapped(R), -1.0);
}

void addCSC(curves::Candidates &c, double x, double y, double phi)
{
    fourWays(c, lsl, [](curves::Candidates &k, const Lengths &o, Steer a, Steer, double g) {
        k.add({{a, g * o.t}, {S, g * o.u}, {a, g * o.v}});
    }, x, y, phi);
    fourWays(c, lsr, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {S, g * o.u}, {b, g * o.v}});
    }, x, y, phi);
}

void addCCC(curves::Candidates &c, double x, double y, double phi, double xb, double yb)
{
    fourWays(c, lrl, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, g * o.u}, {a, g * o.v}});
    }, x, y, phi);
    // the reversed problem: the same word driven last segment first
    fourWays(c, lrl, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.v}, {b, g * o.u}, {a, g * o.t}});
    }, xb, yb, phi);
}

void addCCCC(curves::Candidates &c, double x, double y, double phi)
{
    fourWays(c, lrlrSame, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, g * o.u}, {a, -g * o.u}, {b, g * o.v}});
    }, x, y, phi);
    fourWays(c, lrlrOpposite, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, g * o.u}, {a, g * o.u}, {b, g * o.v}});
    }, x, y, phi);
}

void addCCSC(curves::Candidates &c, double x, double y, double phi, double xb, double yb)
{
    fourWays(c, lrsl, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, -g * kHalfPi}, {S, g * o.u}, {a, g * o.v}});
    }, x, y, phi);
    fourWays(c, lrsr, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, -g * kHalfPi}, {S, g * o.u}, {b, g * o.v}});
    }, x, y, phi);
    fourWays(c, lrsl, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.v}, {S, g * o.u}, {b, -g * kHalfPi}, {a, g * o.t}});
    }, xb, yb, phi);
    fourWays(c, lrsr, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{b, g * o.v}, {S, g * o.u}, {b, -g * kHalfPi}, {a, g * o.t}});
    }, xb, yb, phi);
}

void addCCSCC(curves::Candidates &c, double x, double y, double phi)
{
    fourWays(c, lrslr, [](curves::Candidates &k, const Lengths &o, Steer a, Steer b, double g) {
        k.add({{a, g * o.t}, {b, -g * kHalfPi}, {S, g * o.u}, {a, -g * kHalfPi}, {b, g * o.v}});
    }, x, y, phi);
}
}  // namespace

CarCurve reedsSheppCurve(const Pose2 &a, const Pose2 &b, double radius)
{
    std::vector<CarCurve> one = reedsSheppCurves(a, b, radius, 1);
    return one.empty() ? curves::Candidates().shortestLanding({}, 1.0) : one.front();
}

std::vector<CarCurve> reedsSheppCurves(const Pose2 &a, const Pose2 &b, double radius, int maxCount)
{
    if (!curves::finitePoses(a, b, radius)) return {};
    const Pose2 g = curves::normalisedGoal(a, b, radius);
    const double x = g.x, y = g.y, phi = g.yaw;
    // the reversed problem of Reeds and Shepp's "backwards" symmetry
    const double xb = x * std::cos(phi) + y * std::sin(phi), yb = x * std::sin(phi) - y * std::cos(phi);
    curves::Candidates c;
    c.add({});  // equal poses: no motion at all
    addCSC(c, x, y, phi);
    addCCC(c, x, y, phi, xb, yb);
    addCCCC(c, x, y, phi);
    addCCSC(c, x, y, phi, xb, yb);
    addCCSCC(c, x, y, phi);
    return c.landings(g, radius, maxCount);
}

}  // namespace gridcar
