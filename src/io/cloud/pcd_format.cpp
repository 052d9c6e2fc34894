// PCD bodies (ascii, binary, binary_compressed) and the PCD writer.
#include <cstdint>
#include <cstring>

#include "io/cloud/ascii_points.hpp"
#include "io/cloud/cloud_formats.hpp"
#include "io/cloud/cloud_text.hpp"
#include "io/cloud/lzf.hpp"
#include "io/cloud/pcd_header.hpp"
#include "io/cloud/point_body_writer.hpp"
#include "io/cloud/point_columns.hpp"
#include "io/text_encoding.hpp"

namespace rigdesign::io {
namespace {

// binary_compressed starts with two little-endian uint32: compressed and decompressed size.
constexpr std::size_t kCompressedPrologue = 2 * sizeof(std::uint32_t);

CoordinateType coordinate_type(const PcdField& field) {
  return field.size == sizeof(float) ? CoordinateType::float32 : CoordinateType::float64;
}

std::string point_count_text(const PcdHeader& header) {
  return std::to_string(header.points) + " points of " + std::to_string(header.record_size) +
         " bytes";
}

void read_ascii_body(const std::string& path, std::string_view bytes, const PcdHeader& header,
                     CollectedPoints& collected) {
  AsciiLayout layout;
  for (std::size_t f = 0; f < header.fields.size(); ++f) {
    const PcdField& field = header.fields[f];
    for (std::size_t axis = 0; axis < 3; ++axis) {
      if (header.xyz_fields[axis] == f) layout.xyz[axis] = layout.value_names.size();
    }
    for (std::size_t k = 0; k < field.count; ++k) {
      layout.value_names.push_back(field.count == 1 ? field.name
                                                    : field.name + "[" + std::to_string(k) + "]");
    }
  }
  LineCursor cursor(bytes, header.body_offset, header.data_line);
  read_ascii_points(path, cursor, layout, header.points, collected);
  std::vector<std::string_view> words;
  while (const auto line = cursor.next()) {
    split_words(*line, words);
    if (!words.empty()) {
      throw_data_error(
          path, cursor.line_number(),
          "more lines than the " + std::to_string(header.points) + " points POINTS declares",
          "one line per declared point");
    }
  }
}

// Rows of records: value i of a field sits at record i, at the field's offset.
std::array<CoordinateColumn, 3> record_columns(const PcdHeader& header, std::size_t first_byte) {
  std::array<CoordinateColumn, 3> columns;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const PcdField& field = header.fields[header.xyz_fields[axis]];
    columns[axis] = {first_byte + field.offset, header.record_size, coordinate_type(field)};
  }
  return columns;
}

// binary_compressed stores each field's values for all points together, field after field,
// so a field's block starts at points times its offset within a record.
std::array<CoordinateColumn, 3> field_block_columns(const PcdHeader& header) {
  std::array<CoordinateColumn, 3> columns;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const PcdField& field = header.fields[header.xyz_fields[axis]];
    columns[axis] = {header.points * field.offset, field.size, coordinate_type(field)};
  }
  return columns;
}

void read_binary_body(const std::string& path, std::string_view bytes, const PcdHeader& header,
                      CollectedPoints& collected) {
  if (!collect_points(bytes, header.points, record_columns(header, header.body_offset),
                      collected)) {
    throw_data_error(path, 0,
                     "binary body is truncated: " + point_count_text(header) +
                         " do not fit in the " + std::to_string(bytes.size() - header.body_offset) +
                         " bytes from byte offset " + std::to_string(header.body_offset),
                     "POINTS x record size bytes after the DATA line");
  }
}

std::uint32_t read_uint32(std::string_view bytes, std::size_t at) {
  std::uint32_t value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

void read_compressed_body(const std::string& path, std::string_view bytes, const PcdHeader& header,
                          CollectedPoints& collected) {
  const std::size_t start = header.body_offset;
  const std::string expected =
      "uint32 compressed size, uint32 decompressed size, then that many LZF bytes";
  if (bytes.size() - start < kCompressedPrologue) {
    throw_data_error(
        path, 0,
        "binary_compressed body is truncated: no sizes at byte offset " + std::to_string(start),
        expected);
  }
  const std::size_t compressed_size = read_uint32(bytes, start);
  const std::size_t decompressed_size = read_uint32(bytes, start + sizeof(std::uint32_t));
  const std::size_t stream_start = start + kCompressedPrologue;
  if (compressed_size > bytes.size() - stream_start) {
    throw_data_error(path, 0,
                     "compressed size " + std::to_string(compressed_size) + " at byte offset " +
                         std::to_string(start) + " exceeds the " +
                         std::to_string(bytes.size() - stream_start) + " bytes left in the file",
                     expected);
  }
  std::size_t declared = 0;
  if (__builtin_mul_overflow(header.points, header.record_size, &declared) ||
      declared != decompressed_size) {
    throw_data_error(path, 0,
                     "decompressed size " + std::to_string(decompressed_size) + " at byte offset " +
                         std::to_string(start + sizeof(std::uint32_t)) + " is not the " +
                         point_count_text(header) + " the header declares",
                     "POINTS x record size");
  }
  const LzfResult fields =
      lzf_decompress(bytes.substr(stream_start, compressed_size), decompressed_size);
  if (!fields.ok()) {
    throw_data_error(path, 0,
                     "corrupt LZF stream (starting at byte offset " + std::to_string(stream_start) +
                         "): " + fields.problem,
                     expected);
  }
  if (!collect_points(fields.bytes, header.points, field_block_columns(header), collected)) {
    throw_data_error(path, 0, "decompressed fields are shorter than the header declares",
                     "POINTS x record size");
  }
}

std::string header_text(const model::PointCloud& cloud, CloudEncoding encoding) {
  const std::string n = std::to_string(cloud.size());
  std::string text = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n";
  text += "SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH " + n + "\nHEIGHT 1\nVIEWPOINT";
  append_viewpoint_values(text, cloud);
  text += "\nPOINTS " + n + "\nDATA ";
  text += encoding == CloudEncoding::ascii ? "ascii\n" : "binary\n";
  return text;
}

}  // namespace

model::PointCloud parse_pcd(const std::string& path, std::string_view bytes,
                            CloudReadReport& report) {
  const PcdHeader header = parse_pcd_header(path, bytes);
  // Field and property names reach the JSON reports: the header must be text (UTF-8).
  require_utf8(bytes.substr(0, header.body_offset), path);
  report.format = "pcd " + to_string(header.encoding);
  report.points_in_file = header.points;
  for (std::size_t f = 0; f < header.fields.size(); ++f) {
    const bool coordinate =
        f == header.xyz_fields[0] || f == header.xyz_fields[1] || f == header.xyz_fields[2];
    if (!coordinate) report.ignored_fields.push_back(header.fields[f].name);
  }
  CollectedPoints collected;
  if (header.points > 0) {
    switch (header.encoding) {
      case PcdEncoding::ascii: read_ascii_body(path, bytes, header, collected); break;
      case PcdEncoding::binary: read_binary_body(path, bytes, header, collected); break;
      case PcdEncoding::binary_compressed:
        read_compressed_body(path, bytes, header, collected);
        break;
    }
  }
  report.dropped_non_finite = collected.dropped_non_finite;
  collected.require_in_range(path);
  return std::move(collected).into_cloud(header.origin, header.orientation);
}

std::string encode_pcd(const model::PointCloud& cloud, CloudEncoding encoding) {
  std::string text = header_text(cloud, encoding);
  append_point_body(text, cloud, encoding);
  return text;
}

}  // namespace rigdesign::io
