// PLY bodies (ascii, binary_little_endian) and the PLY writer.
#include <cstdint>

#include "io/cloud/ascii_points.hpp"
#include "io/cloud/cloud_formats.hpp"
#include "io/cloud/cloud_text.hpp"
#include "io/cloud/ply_header.hpp"
#include "io/cloud/point_body_writer.hpp"
#include "io/cloud/point_columns.hpp"
#include "io/text_encoding.hpp"

namespace rigdesign::io {
namespace {

[[noreturn]] void throw_truncated(const std::string& path, const PlyElement& element,
                                  std::size_t offset) {
  throw_data_error(
      path, 0,
      "binary body is truncated in element " + element.name +
          " (its records start at byte offset " + std::to_string(offset) + ")",
      std::to_string(element.count) + " " + element.name + " records as the header declares");
}

// Byte offset just past `element`'s records, which start at `offset`.
std::size_t skip_binary_element(const std::string& path, std::string_view bytes, std::size_t offset,
                                const PlyElement& element) {
  const std::size_t start = offset;
  const auto need = [&](std::size_t size) {
    if (size > bytes.size() - offset) throw_truncated(path, element, start);
  };
  for (std::size_t record = 0; record < element.count; ++record) {
    for (const PlyProperty& property : element.properties) {
      std::size_t size = size_of(property.type);
      if (property.is_list) {
        need(size_of(property.list_count_type));
        // An integer: the header refuses float list lengths.
        const auto length =
            static_cast<std::int64_t>(read_ply_scalar(bytes, offset, property.list_count_type));
        if (length < 0) {
          throw_data_error(path, 0,
                           "negative list length in element " + element.name + " at byte offset " +
                               std::to_string(offset),
                           "a list length >= 0");
        }
        offset += size_of(property.list_count_type);
        if (static_cast<std::uint64_t>(length) > (bytes.size() - offset) / size) {
          throw_truncated(path, element, start);
        }
        size *= static_cast<std::size_t>(length);
      }
      need(size);
      offset += size;
    }
  }
  return offset;
}

std::array<CoordinateColumn, 3> vertex_columns(const PlyHeader& header, std::size_t first_byte) {
  const PlyElement& vertex = header.elements[header.vertex_element];
  std::vector<std::size_t> offsets;
  std::size_t record_size = 0;
  for (const PlyProperty& property : vertex.properties) {
    offsets.push_back(record_size);
    record_size += size_of(property.type);
  }
  std::array<CoordinateColumn, 3> columns;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t index = header.xyz_properties[axis];
    const bool is_float = vertex.properties[index].type == PlyScalar::float32;
    columns[axis] = {first_byte + offsets[index], record_size,
                     is_float ? CoordinateType::float32 : CoordinateType::float64};
  }
  return columns;
}

void read_binary_body(const std::string& path, std::string_view bytes, const PlyHeader& header,
                      CollectedPoints& collected) {
  std::size_t offset = header.body_offset;
  for (std::size_t e = 0; e < header.vertex_element; ++e) {
    offset = skip_binary_element(path, bytes, offset, header.elements[e]);
  }
  const PlyElement& vertex = header.elements[header.vertex_element];
  if (!collect_points(bytes, vertex.count, vertex_columns(header, offset), collected)) {
    throw_truncated(path, vertex, offset);
  }
}

void read_ascii_body(const std::string& path, std::string_view bytes, const PlyHeader& header,
                     CollectedPoints& collected) {
  LineCursor cursor(bytes, header.body_offset, header.end_header_line);
  for (std::size_t e = 0; e < header.vertex_element; ++e) {
    const PlyElement& element = header.elements[e];
    skip_ascii_records(path, cursor, element.count, element.name);
  }
  const PlyElement& vertex = header.elements[header.vertex_element];
  AsciiLayout layout;
  for (const PlyProperty& property : vertex.properties) layout.value_names.push_back(property.name);
  layout.xyz = header.xyz_properties;
  read_ascii_points(path, cursor, layout, vertex.count, collected);
}

}  // namespace

model::PointCloud parse_ply(const std::string& path, std::string_view bytes,
                            CloudReadReport& report) {
  const PlyHeader header = parse_ply_header(path, bytes);
  // Field and property names reach the JSON reports: the header must be text (UTF-8).
  require_utf8(bytes.substr(0, header.body_offset), path);
  const PlyElement& vertex = header.elements[header.vertex_element];
  report.format = "ply " + to_string(header.encoding);
  report.points_in_file = vertex.count;
  for (std::size_t p = 0; p < vertex.properties.size(); ++p) {
    const auto& xyz = header.xyz_properties;
    if (p != xyz[0] && p != xyz[1] && p != xyz[2]) {
      report.ignored_fields.push_back(vertex.properties[p].name);
    }
  }
  CollectedPoints collected;
  if (header.encoding == PlyEncoding::ascii) {
    read_ascii_body(path, bytes, header, collected);
  } else {
    read_binary_body(path, bytes, header, collected);
  }
  report.dropped_non_finite = collected.dropped_non_finite;
  collected.require_in_range(path);
  return std::move(collected).into_cloud(header.origin, header.orientation);
}

std::string encode_ply(const model::PointCloud& cloud, CloudEncoding encoding) {
  std::string text = "ply\nformat ";
  text += encoding == CloudEncoding::ascii ? "ascii 1.0\n" : "binary_little_endian 1.0\n";
  // PLY has no viewpoint; this comment keeps the sensor pose through a round trip.
  text += "comment written by rigdesign\ncomment viewpoint";
  append_viewpoint_values(text, cloud);
  text += "\nelement vertex " + std::to_string(cloud.size()) +
          "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  append_point_body(text, cloud, encoding);
  return text;
}

}  // namespace rigdesign::io
