#pragma once
// A path as the follower tracks it: arc length, corners, velocity profile, clearance and
// curvature (private to gridcar_core; see sim/Follower.h).
#include "gridcar/collision/FootprintChecker.h"
#include "gridcar/core/Angles.h"
#include "gridcar/path/PostProcess.h"
#include "gridcar/vehicle/Dynamics.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gridcar::detail
{
/// A path with its arc length, corners (sub-goals), velocity profile and clearance.
struct TrackedPath
{
    std::vector<Pose2> pts;
    std::vector<double> cum;      ///< arc length at each vertex
    std::vector<double> cornerS;  ///< arc length of the corners that turn by more than 10 degrees
    std::vector<double> clear;    ///< d_O - half width at each vertex (min with the previous one)
    /// d_O - half width at the body's centre and front (the points the repulsion acts on) with
    /// the body on the path at each vertex (min with the previous one): what the path itself
    /// leaves, against which the repulsion is measured
    std::vector<double> clearCentre, clearFront;
    std::vector<double> kappa;    ///< signed curvature of the path at each vertex (1/m, turning-angle)
    std::vector<double> heading;  ///< direction of the segment from each vertex (rad)
    /// The curvature stays within K_max (5 % slack) everywhere: a path the car can drive as it
    /// is (a lattice path), not a grid path's corners
    bool followable{true};
    VelocityProfile profile;
    double total{0.0};

    /// @p startSpeed: m/s the vehicle rolls into the path with (0: it starts from rest)
    TrackedPath(const std::vector<Pose2> &path, const FootprintChecker &checker, double startSpeed = 0.0)
    {
        for (const Pose2 &p : path)
            if (pts.empty() || !samePosition(p, pts.back())) pts.push_back(p);
        if (pts.size() < 2) return;
        cum.push_back(0.0);
        for (std::size_t i = 1; i < pts.size(); ++i)
            cum.push_back(cum.back() + std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y));
        total = cum.back();
        const std::vector<Pose2> tp = turningPoints(pts);
        std::size_t j = 0;
        for (std::size_t i = 1; i + 1 < tp.size(); ++i)
        {
            const double h0 = std::atan2(tp[i].y - tp[i - 1].y, tp[i].x - tp[i - 1].x);
            const double h1 = std::atan2(tp[i + 1].y - tp[i].y, tp[i + 1].x - tp[i].x);
            while (j < pts.size() && (pts[j].x != tp[i].x || pts[j].y != tp[i].y)) ++j;
            if (j < pts.size() && std::abs(wrapAngle(h1 - h0)) > 10.0 * M_PI / 180.0) cornerS.push_back(cum[j]);
        }
        const VehicleParams &veh = checker.vehicle();
        DrivingTimeParams dp;
        dp.startSpeed = startSpeed;
        profile = velocityProfile(pts, veh, dp);
        const DistanceField &field = checker.field();
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            const double c = field.distance(pts[i].x, pts[i].y) - veh.width / 2;
            clear.push_back(i ? std::min(c, field.distance(pts[i - 1].x, pts[i - 1].y) - veh.width / 2) : c);
        }
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) heading.push_back(std::atan2(pts[i + 1].y - pts[i].y, pts[i + 1].x - pts[i].x));
        heading.push_back(heading.back());
        const double off = veh.centreOffset(), front = std::max(off, veh.length - veh.rearOverhang - veh.width / 2);
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            const double h = heading[i];
            const double cc = field.distance(pts[i].x + off * std::cos(h), pts[i].y + off * std::sin(h)) - veh.width / 2;
            const double cf = field.distance(pts[i].x + front * std::cos(h), pts[i].y + front * std::sin(h)) - veh.width / 2;
            clearCentre.push_back(cc);
            clearFront.push_back(cf);
        }
        // each vertex's value the smaller of its own and the previous vertex's (as `clear`), not
        // a running minimum: past the path's tightest point the repulsion is measured again
        // against what the path leaves there
        for (std::size_t i = pts.size() - 1; i > 0; --i)
        {
            clearCentre[i] = std::min(clearCentre[i], clearCentre[i - 1]);
            clearFront[i] = std::min(clearFront[i], clearFront[i - 1]);
        }
        // curvature over a window of about 0.3 m each side (a lattice path's arcs are sampled
        // every few centimetres; the window smooths the rounding of single samples)
        kappa.assign(pts.size(), 0.0);
        for (std::size_t i = 0; i < pts.size(); ++i)
        {
            std::size_t a = i, b = i;
            while (a > 0 && cum[i] - cum[a] < 0.3) --a;
            while (b + 1 < pts.size() && cum[b] - cum[i] < 0.3) ++b;
            if (b <= a || cum[b] - cum[a] < 1e-6) continue;
            kappa[i] = wrapAngle(heading[b == pts.size() - 1 ? b - 1 : b] - heading[a]) / (cum[b] - cum[a]);
        }
        // followable: the turning-angle curvature at every vertex (the drivable check's test)
        for (std::size_t i = 1; i + 1 < pts.size() && followable; ++i)
        {
            const double ds = 0.5 * (cum[i + 1] - cum[i - 1]);
            if (ds > 0 && std::abs(wrapAngle(heading[i] - heading[i - 1])) / ds > 1.05 * veh.maxCurvature()) followable = false;
        }
        // (a grid path's kinks are not followed exactly: no steering-rate cap there)
        if (followable) capForSteering(veh);
    }

    /// The steering wheel turns at most maxSteerRateDeg: where the path's curvature changes by
    /// dk/ds the front wheels must turn at v x L / (1 + (L k)^2) x dk/ds, so the profile is
    /// capped at the speed where they keep up (curvature over the 0.6 m window above, so a jump
    /// between two samples reads as a change over 0.6 m), then accelerated and braked again.
    void capForSteering(const VehicleParams &veh)
    {
        if (profile.v.size() < 3 || pts.size() < 3) return;
        const double rate = veh.maxSteerRateDeg * M_PI / 180.0, L = veh.wheelbase;
        bool capped = false;
        for (std::size_t k = 0; k < profile.v.size(); ++k)
        {
            const std::size_t i = segmentAt(profile.s[k]);
            const std::size_t a = segmentAt(profile.s[k] - 0.15), b = std::min(segmentAt(profile.s[k] + 0.15) + 1, pts.size() - 1);
            if (b <= a || cum[b] - cum[a] < 1e-6) continue;
            const double dk = std::abs(kappa[b] - kappa[a]) / (cum[b] - cum[a]);
            const double lk = L * kappa[i];
            const double dSteer = L / (1.0 + lk * lk) * dk;  // rad of wheel angle per metre
            if (dSteer > 1e-9 && rate / dSteer < profile.v[k])
            {
                profile.v[k] = rate / dSteer;
                capped = true;
            }
        }
        if (!capped) return;
        for (std::size_t k = 1; k < profile.v.size(); ++k)
        {
            const double ds = profile.s[k] - profile.s[k - 1];
            profile.v[k] = std::min(profile.v[k], std::sqrt(profile.v[k - 1] * profile.v[k - 1] + 2 * veh.acceleration * ds));
        }
        for (std::size_t k = profile.v.size() - 1; k-- > 0;)
        {
            const double ds = profile.s[k + 1] - profile.s[k];
            profile.v[k] = std::min(profile.v[k], std::sqrt(profile.v[k + 1] * profile.v[k + 1] + 2 * veh.deceleration * ds));
        }
        profile.time = 0.0;  // the time limit of a run is taken from it
        for (std::size_t k = 1; k < profile.v.size(); ++k)
            profile.time += 2 * (profile.s[k] - profile.s[k - 1]) / std::max(profile.v[k - 1] + profile.v[k], 1e-9);
    }

    /// The index of the segment holding arc length s.
    std::size_t segmentAt(double s) const
    {
        s = std::clamp(s, 0.0, total);
        const std::size_t i = std::size_t(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin());
        return i == 0 ? 0 : std::min(i - 1, pts.size() - 2);
    }

    void pointAt(double s, double &x, double &y) const
    {
        s = std::clamp(s, 0.0, total);
        const std::size_t i =
            std::min<std::size_t>(pts.size() - 1, std::size_t(std::upper_bound(cum.begin(), cum.end(), s) - cum.begin()));
        const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? 1 : i;
        const double len = cum[b] - cum[a];
        const double f = len > 0 ? (s - cum[a]) / len : 0.0;
        x = pts[a].x + f * (pts[b].x - pts[a].x);
        y = pts[a].y + f * (pts[b].y - pts[a].y);
    }
};

}  // namespace gridcar::detail
