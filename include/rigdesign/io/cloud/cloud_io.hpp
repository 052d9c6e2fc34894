#pragma once
/// Point cloud files: PCD v0.7 (ascii, binary, binary_compressed) and PLY 1.0 (ascii,
/// binary_little_endian), the two formats PCL, Open3D and the ROS tools exchange.
#include <cstddef>
#include <string>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::io {

/// What read_cloud found in a file besides the points it returns.
struct CloudReadReport {
  /// "pcd ascii", "pcd binary", "pcd binary_compressed", "ply ascii" or
  /// "ply binary_little_endian".
  std::string format;
  /// Points the header declares (PCD POINTS, PLY `element vertex` count), finite or not.
  std::size_t points_in_file = 0;
  /// Points dropped because a coordinate is NaN or infinite (organised depth-camera clouds
  /// mark every pixel without a return that way), or a double too large for a float.
  std::size_t dropped_non_finite = 0;
  /// Per-point fields other than x, y, z, in file order (e.g. "rgb", "normal_x"): read past,
  /// not kept.
  std::vector<std::string> ignored_fields;
};

/// Reads a .pcd or .ply file (chosen by the extension, case-insensitive) into a cloud of its
/// finite points, in file order. Coordinates are in the file's units (metres by convention).
/// The PCD VIEWPOINT becomes `origin` and `orientation` (normalised); a PLY file written by
/// write_cloud gives them back from its `comment viewpoint` line, any other PLY file gives
/// the identity pose. A file that declares no points gives an empty cloud.
/// Fills `report` when it is not null.
/// Throws InputError when the file cannot be read, has another extension, or its header or
/// data are malformed; the finding names the header line, or the byte offset or point index
/// in the data, and the field ("FIELDS", "element vertex", "data", ...).
model::PointCloud read_cloud(const std::string& path, CloudReadReport* report = nullptr);

enum class CloudEncoding { ascii, binary };

/// Writes `cloud` as .pcd (DATA ascii or binary) or .ply (format ascii or
/// binary_little_endian), chosen by the extension, case-insensitive, with float x y z per
/// point. The file appears whole or not at all (write_file_atomically). The PCD VIEWPOINT
/// carries `origin` and `orientation`; PLY has no standard place for them, so they go in a
/// `comment viewpoint tx ty tz qw qx qy qz` header line that read_cloud understands.
/// ascii output uses the shortest decimal form that reads back to the same float.
/// Throws InputError (field "output") for another extension or an unwritable folder.
void write_cloud(const std::string& path, const model::PointCloud& cloud, CloudEncoding encoding);

}  // namespace rigdesign::io
