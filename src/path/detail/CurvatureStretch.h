#pragma once
/// @file CurvatureStretch.h
/// @brief The parts smoothCurvature() and widenTurns() share (private to gridcar_core): a path
/// piece with its arc length and curvature, a G2 quintic fitted to a stretch of it within the
/// limits, and the path taken piece by piece between its cusps.

#include "gridcar/core/Angles.h"
#include "gridcar/path/ContinuousCurvature.h"
#include "gridcar/core/Cusps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <functional>
#include <string>
#include <vector>

namespace gridcar::detail
{
/// Metres within which two arc lengths along a piece count as equal where a stretch's window
/// is laid: a lattice path's straights and turns are whole cells long, so window edges and
/// vertices fall together, and the last bits of a sum (which differ with the map's origin)
/// must not decide which vertices a stretch takes.
constexpr double kArcTie = 1e-9;

/// One piece (one direction of motion) being smoothed: its poses with the yaw of motion.
struct Piece
{
    std::vector<Pose2> pts;  ///< yaw = direction of motion
    std::vector<double> s;   ///< arc length at each pose
    std::vector<double> k;   ///< curvature of each interval i -> i + 1
    std::vector<char> bad;   ///< vertex where the curvature jumps faster than the limit
};

/// The piece of @p poses (driven backwards: yaws turned to the motion); a vertex is bad where
/// the curvature changes faster than @p sigma.
Piece makePiece(const std::vector<Pose2> &poses, bool backward, double sigma);

/// A candidate replacement of pts[a..b]: its poses strictly between a and b (motion yaws), or
/// empty when it breaks a limit.
std::vector<Pose2> fitStretch(const Piece &p, std::size_t a, std::size_t b, double ka, double kb, double eta,
                              const CurvatureSmoothingOptions &o);

/// The body poses written for a piece as it is smoothed or widened: its own poses up to done(),
/// and the replacements of the stretches replaced (yaws turned back to the body's for a piece
/// driven backwards).
class PieceWriter
{
public:
    PieceWriter(const Piece &p, bool backward) : p_(p), flip_(backward ? M_PI : 0.0)
    {
        if (!p.pts.empty()) out_.push_back(body(p.pts[0]));
    }
    Pose2 body(const Pose2 &q) const { return {q.x, q.y, wrapAngle(q.yaw + flip_)}; }
    /// The last of the piece's poses written (those before it may not be replaced).
    std::size_t done() const { return done_; }
    /// Writes the piece's poses up to @p e.
    void copyTo(std::size_t e)
    {
        for (std::size_t i = done_ + 1; i <= e; ++i) out_.push_back(body(p_.pts[i]));
        done_ = std::max(done_, e);
    }
    /// Writes pts[a], @p mid (motion yaws) and pts[b] in place of pts[a..b] when @p free
    /// finds the body free along them; true if it did.
    bool replace(std::size_t a, std::size_t b, const std::vector<Pose2> &mid,
                 const std::function<bool(const std::vector<Pose2> &)> &free)
    {
        std::vector<Pose2> test{body(p_.pts[a])};
        for (const Pose2 &q : mid) test.push_back(body(q));
        test.push_back(body(p_.pts[b]));
        if (!free(test)) return false;
        copyTo(a);
        out_.insert(out_.end(), test.begin() + 1, test.end() - 1);
        out_.push_back(body(p_.pts[b]));
        done_ = b;
        return true;
    }
    /// The poses written, with the rest of the piece.
    std::vector<Pose2> finish()
    {
        if (!p_.pts.empty()) copyTo(p_.pts.size() - 1);
        return std::move(out_);
    }

private:
    const Piece &p_;
    double flip_;
    std::vector<Pose2> out_;
    std::size_t done_{0};
};

/// smoothCurvature() and widenTurns(): each piece (split at cusps when reversing) by @p each.
template <class Each>
CurvatureSmoothing byPieces(const std::vector<Pose2> &path, const CurvatureSmoothingOptions &o, const char *what,
                            const Each &each)
{
    if (!o.free) throw std::invalid_argument(std::string(what) + ": no free test given");
    if (!(o.maxCurvature > 0) || !(o.maxCurvatureRate > 0) || !(o.step > 0))
        throw std::invalid_argument(std::string(what) + ": K_max, the curvature rate and the step must be positive");
    CurvatureSmoothing r;
    std::vector<PathPiece> pieces;
    if (o.reversing)
        pieces = splitAtCusps(path);
    else
        pieces.push_back({path, false});
    for (const PathPiece &piece : pieces)
    {
        std::vector<Pose2> done = each(piece.poses, piece.backward, o, r);
        const std::size_t skip = r.path.empty() ? 0 : 1;  // the shared cusp pose
        r.path.insert(r.path.end(), done.begin() + std::ptrdiff_t(std::min(skip, done.size())), done.end());
        if (r.cancelled) break;
    }
    if (r.cancelled) r.path = path;
    for (const PathPiece &piece : o.reversing ? splitAtCusps(r.path) : std::vector<PathPiece>{{r.path, false}})
        r.maxRate = std::max(r.maxRate, curvatureRateProfile(piece.poses).maxRate);
    return r;
}

}  // namespace gridcar::detail
