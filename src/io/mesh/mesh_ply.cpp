// PLY meshes: the cloud reader's header parser (it already checks the vertex element's x, y
// and z), then the records of an ascii or binary_little_endian body. The vertex and face
// elements are kept; every other element, and every other property of those two, is read
// past and dropped.
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/cloud/cloud_text.hpp"
#include "io/cloud/ply_header.hpp"
#include "io/mesh/mesh_formats.hpp"
#include "io/mesh/mesh_ply_records.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kFaceForm =
    "element face <count> with property list uchar int vertex_indices";

bool is_integer(PlyScalar type) {
  return type != PlyScalar::float32 && type != PlyScalar::float64;
}

// Where the face corners are: the face element and its vertex_indices property.
struct FaceLayout {
  const PlyElement* element = nullptr;
  std::size_t indices = 0;
};

FaceLayout face_layout(const std::string& path, const PlyHeader& header) {
  for (const PlyElement& element : header.elements) {
    if (element.name != "face") continue;
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      if (property.name != "vertex_indices" && property.name != "vertex_index") continue;
      if (!property.is_list || !is_integer(property.type)) {
        throw_mesh_error(
            path, property.line, 1, "property",
            "face property " + quote_word(property.name) + " is not a list of integers",
            "property list uchar int vertex_indices (or uint items)");
      }
      return {&element, p};
    }
    throw_mesh_error(path, element.line, 1, "element face", "has no property vertex_indices",
                     kFaceForm);
  }
  throw_mesh_error(path, header.end_header_line, 1, "element face",
                   "the header declares no face element (a point cloud, not a mesh)", kFaceForm);
}

template <typename Body>
void add_vertex(const Body& body, const PlyElement& element, const PlyHeader& header,
                const PlyRecord& record, model::TriangleMesh& mesh) {
  model::Vec3 vertex;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t p = header.xyz_properties[axis];
    vertex[static_cast<Eigen::Index>(axis)] = record.scalars[p];
    if (!std::isfinite(record.scalars[p])) {
      body.fail(record, record.scalar_at[p],
                ply_field(element, record.index, element.properties[p].name),
                "is not a finite number", "finite coordinates in metres");
    }
  }
  mesh.vertices.push_back(vertex);
}

template <typename Body>
void add_face(const Body& body, const FaceLayout& faces, std::size_t vertex_count,
              const PlyRecord& record, std::vector<int>& corners, model::TriangleMesh& mesh) {
  const std::string field =
      ply_field(*faces.element, record.index, faces.element->properties[faces.indices].name);
  if (record.items.size() < 3) {
    body.fail(record, record.list_at, field,
              "has " + std::to_string(record.items.size()) + " corner(s)",
              "a polygon: at least 3 vertex indices");
  }
  corners.clear();
  for (std::size_t i = 0; i < record.items.size(); ++i) {
    const std::int64_t index = record.items[i];
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count) {
      body.fail(record, record.item_at[i], field,
                "refers to vertex " + std::to_string(index) + "; the file has " +
                    std::to_string(vertex_count) + " vertices",
                "indices in [0, " + std::to_string(vertex_count) + ")");
    }
    corners.push_back(static_cast<int>(index));
  }
  append_fan(mesh, corners);
}

template <typename Body>
model::TriangleMesh read_body(Body body, const std::string& path, const PlyHeader& header,
                              std::size_t body_size) {
  const FaceLayout faces = face_layout(path, header);
  const PlyElement& vertex_element = header.elements[header.vertex_element];
  if (vertex_element.count > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw_mesh_error(path, vertex_element.line, 1, "element vertex", "has too many vertices",
                     "at most 2^31 - 1 vertices");
  }
  model::TriangleMesh mesh;
  // A vertex takes at least 6 bytes of text or 12 of binary: never reserve past the file.
  mesh.vertices.reserve(std::min(vertex_element.count, body_size / 6));
  PlyRecord record;
  std::vector<int> corners;
  for (const PlyElement& element : header.elements) {
    const bool is_face = &element == faces.element;
    for (std::size_t r = 0; r < element.count; ++r) {
      body.read(element, r, is_face ? faces.indices : kNoPlyList, record);
      if (&element == &vertex_element) {
        add_vertex(body, element, header, record, mesh);
      } else if (is_face) {
        add_face(body, faces, vertex_element.count, record, corners, mesh);
      }
    }
  }
  return mesh;
}

}  // namespace

model::TriangleMesh parse_ply_mesh(const std::string& path, std::string_view bytes) {
  const PlyHeader header = parse_ply_header(path, bytes);
  const std::size_t body_size = bytes.size() - header.body_offset;
  if (header.encoding == PlyEncoding::ascii) {
    return read_body(AsciiPlyRecords(path, bytes, header), path, header, body_size);
  }
  return read_body(BinaryPlyRecords(path, bytes, header), path, header, body_size);
}

}  // namespace rigdesign::io
