#pragma once
// The parts of a cloud file both writers lay out alike: the seven viewpoint numbers and the
// body of float x y z per point. Private to io.
#include <string>

#include "rigdesign/io/cloud/cloud_io.hpp"

namespace rigdesign::io {

/// Appends " tx ty tz qw qx qy qz" for the cloud's origin and orientation.
void append_viewpoint_values(std::string& text, const model::PointCloud& cloud);

/// Appends the points: "x y z\n" lines in the shortest decimal form that reads back to the
/// same floats (ascii), or packed little-endian float triples (binary).
void append_point_body(std::string& text, const model::PointCloud& cloud, CloudEncoding encoding);

}  // namespace rigdesign::io
