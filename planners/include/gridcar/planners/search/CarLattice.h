#pragma once
/// @file CarLattice.h
/// @brief The car lattice: nodes on a square grid of its own cell size (not the map's), a few
/// headings that are directions of lattice vectors, and motion primitives of bounded curvature
/// that join node to node exactly.

#include "gridcar/core/Pose2.h"
#include "gridcar/curves/ClothoidTurns.h"

#include <array>
#include <map>
#include <vector>

namespace gridcar
{
/// How to build a CarLattice.
struct CarLatticeConfig
{
    double cell{0.5};        ///< m between lattice nodes
    int headings{16};        ///< 8 or 16
    double turnRadius{2.0};  ///< m, radius of the tightest turning arcs (>= the vehicle's R_min)
    double spacing{0.05};    ///< m: no body point moves more than this between two sampled poses
    double reach{0.0};       ///< m, farthest body point from the reference point (VehicleParams)
    /// m, further arc radii (each > turnRadius): a turn primitive per radius and side where it
    /// ends on a node (and heading) that no tighter turn of this set reaches
    std::vector<double> extraRadii;
    /// Also the primitives driven backwards (each forward one mirrored: the body keeps its
    /// heading, the reference point moves the other way)
    bool reverse{false};
    /// Hybrid A* primitives instead of the lattice's (Dolgov et al.; Nav2's Smac Hybrid-A*):
    /// a state is a continuous pose binned into a square of `cell` metres and one of `headings`
    /// equal heading bins (16 to 360), and every primitive is an arc (R_min, the further radii)
    /// or a straight of one length, a whole number of bins of heading at R_min and at least 1.5
    /// cells, so that manoeuvres far finer than a lattice node's can be made in a tight spot.
    bool hybrid{false};
    /// 1/m^2, > 0: the lattice's turns are clothoid turns instead of arcs (a clothoid from
    /// curvature 0 up at this rate, an arc of the turning radius if the turn needs it, a
    /// clothoid back to 0), so every primitive starts and ends straight and a path of them has
    /// continuous curvature changing no faster than this; 0: arcs (curvature jumps at each end).
    /// With clothoid turns the lattice also has turns of 2 up to headings / 4 heading steps
    /// (90 degrees): a corner of one-step turns would straighten the wheel between them.
    double curvatureRate{0.0};
    bool operator==(const CarLatticeConfig &o) const
    {
        return cell == o.cell && headings == o.headings && turnRadius == o.turnRadius && extraRadii == o.extraRadii &&
               reverse == o.reverse && spacing == o.spacing && reach == o.reach && hybrid == o.hybrid &&
               curvatureRate == o.curvatureRate;
    }
    bool operator!=(const CarLatticeConfig &o) const { return !(*this == o); }
};

/// One motion primitive from a node at heading `from` (lattice frame, start at the origin).
struct LatticePrimitive
{
    int di{0}, dj{0};   ///< end node offset in lattice cells (i along x, j along y)
    int from{0}, to{0};  ///< start and end heading
    double length{0.0};  ///< m, arc length
    double turn{0.0};    ///< rad, signed heading change of the body (0 for a straight)
    double radius{0.0};  ///< m, radius of its arc (0 for a straight)
    bool reverse{false}; ///< driven backwards (the body at heading `from` .. `to` throughout)
    /// Hybrid primitives (CarLatticeConfig::hybrid): samples in the body frame of the start pose
    /// (start at the origin, yaw 0), di / dj / from / to unused.
    /// Poses along it, relative to the start node, spaced so that no body point moves more than
    /// the configured spacing between two of them; the start pose excluded, the end included.
    std::vector<Pose2> samples;
    /// cos and sin of each sample's yaw (the motion checks turn them by the frame's yaw instead
    /// of calling the trigonometric functions per pose).
    std::vector<std::array<double, 2>> sampleCS;
};

/**
 * @brief A state lattice for a car, in the style of the state-lattice planners (Pivtoraiko and
 * Kelly; Nav2's Smac lattice planner): states are (node i, node j, heading h).
 *
 * Headings are the directions of the lattice vectors (1,0), (1,1) and their rotations (8), plus
 * (2,1), (1,2) and theirs (16): a straight primitive moves by one such vector and lands on a node
 * again. A turn primitive changes the heading by one step (45 degrees, or 18.4 / 26.6 degrees
 * with 16 headings): straight s1, an arc of radius turnRadius, straight s2, with s1, s2 >= 0
 * chosen (the shortest such curve whose end is a node) so that it ends exactly on a node. Every
 * primitive therefore has curvature 0 or 1 / turnRadius, headings join without a kink, and a
 * path of primitives is drivable by a car whose R_min <= turnRadius wherever its footprint is
 * free.
 *
 * Collision checking: margin() = spacing / 2. Between two consecutive samples no body point moves
 * more than spacing, so every intermediate rectangle lies inside the rectangle of one of the two
 * samples grown by margin(): checking the grown rectangle at the samples certifies the swept
 * motion (FootprintChecker::isValidInflated).
 *
 * @par External documentation
 * M. Pivtoraiko, R. A. Knepper, A. Kelly, "Differentially constrained mobile robot motion
 * planning in state lattices", J. Field Robotics 2009. Nav2 Smac planner (state lattice).
 */
class CarLattice
{
public:
    /// Throws std::invalid_argument for a cell, radius or spacing that is not finite and
    /// positive, or headings other than 8 and 16.
    explicit CarLattice(const CarLatticeConfig &config);

    const CarLatticeConfig &config() const { return config_; }
    int headings() const { return config_.headings; }
    double cell() const { return config_.cell; }
    bool hybrid() const { return config_.hybrid; }
    /// The yaw of heading h in the lattice frame (a hybrid lattice: its bin's centre).
    double yaw(int h) const { return yaw_[std::size_t(h)]; }
    /// The heading nearest to a lattice-frame yaw (a hybrid lattice: its bin).
    int nearestHeading(double yaw) const;
    /// The primitives from heading h (a hybrid lattice: the same body-frame set for every h).
    const std::vector<LatticePrimitive> &primitives(int h) const { return prims_[config_.hybrid ? 0 : std::size_t(h)]; }
    double margin() const { return config_.spacing / 2; }
    /// The neighbour steps of the 2D heuristic grid: the headings' lattice vectors (a hybrid
    /// lattice: those of 16 headings), in cells, and their yaws.
    int neighbourCount() const { return int(vec_.size()); }
    int vi(int k) const { return vec_[std::size_t(k)][0]; }
    int vj(int k) const { return vec_[std::size_t(k)][1]; }
    double stepYaw(int k) const { return stepYaw_[std::size_t(k)]; }

private:
    void addStraight(int h);
    bool addTurn(int h, int dir, double radius);
    void addReverse(int h);
    void addHybrid();
    void sample(LatticePrimitive &p, double s1) const;
    /// The curved part of a turn of signed deflection @p delta at radius @p R from yaw 0 at the
    /// origin: an arc, or with curvatureRate a clothoid turn; its pose at arc length @p s.
    Pose2 turnPose(double delta, double R, double s) const;
    /// Its length.
    double turnLength(double delta, double R) const;
    /// The clothoid turn at radius @p R and the configured curvature rate (built once per radius).
    const ClothoidTurn &clothoidTurn(double R) const;
    /// (used while the constructor builds the primitives only)
    mutable std::map<double, ClothoidTurn> turns_;

    CarLatticeConfig config_;
    std::vector<std::array<int, 2>> vec_;
    std::vector<double> stepYaw_;
    std::vector<double> yaw_;
    std::vector<std::vector<LatticePrimitive>> prims_;
    /// Fills every primitive's sampleCS (once its samples are final).
    void cacheSampleTrig();
};

}  // namespace gridcar
