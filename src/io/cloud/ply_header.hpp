#pragma once
// The header of a PLY 1.0 file (Greg Turk's polygon file format, as Stanford, Open3D and PCL
// write it), parsed and checked. Private to io.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::io {

enum class PlyEncoding { ascii, binary_little_endian };

enum class PlyScalar { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

struct PlyProperty {
  std::string name;
  PlyScalar type = PlyScalar::float32;  ///< a list's item type
  bool is_list = false;
  PlyScalar list_count_type = PlyScalar::uint8;  ///< for a list: the type of its length
  int line = 0;
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;             ///< in body order
  std::size_t vertex_element = 0;               ///< index of `vertex` in `elements`
  std::array<std::size_t, 3> xyz_properties{};  ///< indices of x, y, z among its properties
  /// From a `comment viewpoint tx ty tz qw qx qy qz` line (write_cloud's), else identity.
  model::Point3f origin = model::Point3f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  std::size_t body_offset = 0;  ///< first byte after end_header
  int end_header_line = 0;
};

/// Bytes one value of `type` takes in a binary body.
std::size_t size_of(PlyScalar type);

/// The little-endian binary value of `type` at byte `at` (the caller checked the bytes are
/// there). Every PLY scalar type fits a double exactly (PLY has no 64-bit integers).
double read_ply_scalar(std::string_view bytes, std::size_t at, PlyScalar type);

/// Parses the header at the start of `bytes`. Throws InputError at the offending line for a
/// missing `ply` magic, a missing or unsupported format (binary_big_endian is refused), an
/// unknown keyword or type, a property outside an element, a missing `end_header`, no
/// `vertex` element, and a vertex element without float or double x, y, z or with a list
/// property.
PlyHeader parse_ply_header(const std::string& path, std::string_view bytes);

std::string to_string(PlyEncoding encoding);

}  // namespace rigdesign::io
