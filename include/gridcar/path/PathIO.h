#pragma once
/// @file PathIO.h
/// @brief Paths as files: CSV, YAML or JSON poses, the angle unit named in the file, so that a
/// path written by `gridcar plan --out` reads back in `gridcar drive --path`, in a spreadsheet
/// or in a ROS tool without guessing whether the yaw is in degrees or radians.
///
/// Formats, chosen by the file's extension:
/// - `.csv`: a header `x,y,yaw_rad` (or `yaw_deg`), then one pose per line. Read: the header may
///   also say `yaw` (radians, the older form) or name no yaw column (`x,y`: yaw 0).
/// - `.yaml` / `.yml` and `.json`: `{frame_id: map, angle_unit: deg | rad, poses: [{x, y, yaw}]}`
///   (x, y in metres in the map frame, yaw counter-clockwise from +x, as ROS's map frame).

#include "gridcar/core/Pose2.h"

#include <string>
#include <vector>

namespace gridcar
{
/// Unit of the yaw in a path file.
enum class AngleUnit
{
    Degrees,
    Radians
};

/// The format a file name asks for: "csv", "yaml" or "json"; empty for anything else.
std::string pathFormatOf(const std::string &file);

/// Writes @p path to @p file in the format of its extension (see the file comment); throws
/// std::invalid_argument for an unknown extension and MapLoadError(file, reason) when the file
/// cannot be written.
void writePath(const std::string &file, const std::vector<Pose2> &path, AngleUnit unit = AngleUnit::Degrees,
               const std::string &frameId = "map");

/// Reads a path written by writePath() (or by hand in the same forms); yaw in radians.
/// MapLoadError naming the file and the line or pose for anything malformed: an unknown unit, a
/// non-finite number, fewer than two poses.
std::vector<Pose2> readPath(const std::string &file);

}  // namespace gridcar
