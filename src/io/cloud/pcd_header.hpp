#pragma once
// The header of a PCD v0.7 file (PCL's format; spec: pointclouds.org "The PCD (Point Cloud
// Data) file format"), parsed and checked. Private to io.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/point_cloud.hpp"

namespace rigdesign::io {

enum class PcdEncoding { ascii, binary, binary_compressed };

/// One FIELDS entry with its SIZE, TYPE and COUNT.
struct PcdField {
  std::string name;
  std::size_t size = 0;    ///< bytes per value: 1, 2, 4 or 8
  char type = 'F';         ///< 'F' floating point, 'I' signed or 'U' unsigned integer
  std::size_t count = 1;   ///< values per point
  std::size_t offset = 0;  ///< bytes from the start of a binary record
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::size_t record_size = 0;  ///< bytes per point in a binary body
  std::size_t width = 0;
  std::size_t height = 0;
  std::size_t points = 0;
  model::Point3f origin = model::Point3f::Zero();                   ///< VIEWPOINT tx ty tz
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();  ///< VIEWPOINT qw qx qy qz
  PcdEncoding encoding = PcdEncoding::ascii;
  std::size_t body_offset = 0;  ///< first byte after the DATA line
  int data_line = 0;            ///< 1-based line of DATA; an ascii body starts on the next
  std::array<std::size_t, 3> xyz_fields{};  ///< indices of x, y, z in `fields`
};

/// Parses the header at the start of `bytes`. VERSION, COUNT (1 per field) and VIEWPOINT
/// (identity) may be left out, as PCL's own reader allows; the other keywords are required.
/// Throws InputError at the offending line for an unknown, repeated, missing or malformed
/// keyword, SIZE/TYPE/COUNT lists that disagree with FIELDS, no x, y or z (or one that is not
/// a single F 4 / F 8 value), and WIDTH x HEIGHT differing from POINTS.
PcdHeader parse_pcd_header(const std::string& path, std::string_view bytes);

std::string to_string(PcdEncoding encoding);

}  // namespace rigdesign::io
