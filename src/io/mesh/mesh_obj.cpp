// Wavefront OBJ meshes: `v` lines give vertices, `f` lines polygons whose corners are
// `i`, `i/j`, `i/j/k` or `i//k` (only the vertex index i counts; 1-based, or negative to count
// back from the latest vertex). Every other statement (vt, vn, g, o, s, usemtl, l, ...) is
// ignored, as are comments from '#'.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/cloud/cloud_text.hpp"
#include "io/mesh/mesh_formats.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kObjVertexForm = "v x y z [w] (finite numbers, metres)";
constexpr const char* kObjFaceForm = "f v1 v2 v3 ... with corners i, i/j, i/j/k or i//k";
// x, y, z plus an optional w or an r g b colour some exporters append.
constexpr std::size_t kMostVertexValues = 6;

// A positive index past the vertices read so far: OBJ lets it name a later vertex, so it
// is checked once the whole file is read.
struct ForwardReference {
  std::int64_t index = 0;  // 0-based
  int line = 0;
  int column = 0;
};

class ObjReader {
 public:
  ObjReader(const std::string& path, std::string_view bytes) : path_(path), cursor_(bytes) {}

  model::TriangleMesh read() {
    while (const auto raw = cursor_.next()) {
      std::string_view line = *raw;
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
        line = line.substr(0, hash);
      }
      split_words(line, words_);
      if (words_.empty()) continue;
      if (words_[0] == "v") {
        read_vertex(line);
      } else if (words_[0] == "f") {
        read_face(line);
      }
    }
    check_forward_references();
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(std::string_view line, std::string_view word, const std::string& field,
                         const std::string& problem, const std::string& expected) const {
    throw_mesh_error(path_, cursor_.line_number(), column_of(line, word), field, problem, expected);
  }

  void read_vertex(std::string_view line) {
    if (words_.size() < 4 || words_.size() > 1 + kMostVertexValues) {
      fail(line, words_[0], "v", "has " + std::to_string(words_.size() - 1) + " value(s)",
           kObjVertexForm);
    }
    model::Vec3 vertex;
    for (std::size_t i = 1; i < words_.size(); ++i) {
      const auto value = parse_double(words_[i]);
      if (!value || !std::isfinite(*value)) {
        fail(line, words_[i], "v", quote_word(words_[i]) + " is not a finite number",
             kObjVertexForm);
      }
      if (i <= 3) vertex[static_cast<Eigen::Index>(i - 1)] = *value;
    }
    if (mesh_.vertices.size() >= static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      fail(line, words_[0], "v", "one vertex too many", "at most 2^31 - 1 vertices");
    }
    mesh_.vertices.push_back(vertex);
  }

  void read_face(std::string_view line) {
    if (words_.size() < 4) {
      fail(line, words_[0], "f", "has " + std::to_string(words_.size() - 1) + " corner(s)",
           kObjFaceForm + std::string(" (at least 3 corners)"));
    }
    corners_.clear();
    for (std::size_t i = 1; i < words_.size(); ++i)
      corners_.push_back(vertex_index(line, words_[i]));
    append_fan(mesh_, corners_);
  }

  int vertex_index(std::string_view line, std::string_view corner) {
    const std::string_view text = corner.substr(0, corner.find('/'));
    std::int64_t index = 0;
    if (!parse_index(text, index) || index == 0) {
      fail(line, corner, "f", "corner " + quote_word(corner) + " has no vertex index",
           kObjFaceForm + std::string(" (i a non-zero integer)"));
    }
    const auto count = static_cast<std::int64_t>(mesh_.vertices.size());
    if (index < 0) {
      if (-index > count) {
        fail(line, corner, "f",
             "relative index " + std::to_string(index) + " reaches before the first vertex (" +
                 std::to_string(count) + " read so far)",
             "-1 ... -" + std::to_string(count) + " (counting back from the latest vertex)");
      }
      return static_cast<int>(count + index);
    }
    if (index > count) {
      // An absolute index, so it can be stored now; only its range waits for the file's end.
      forward_.push_back({index - 1, cursor_.line_number(), column_of(line, corner)});
    }
    return static_cast<int>(std::min<std::int64_t>(index - 1, std::numeric_limits<int>::max()));
  }

  void check_forward_references() {
    const auto count = static_cast<std::int64_t>(mesh_.vertices.size());
    for (const ForwardReference& reference : forward_) {
      if (reference.index >= count) {
        throw_mesh_error(
            path_, reference.line, reference.column, "f",
            "refers to vertex " + std::to_string(reference.index + 1) + "; the file has " +
                std::to_string(count) + " vertices",
            "indices 1 ... " + std::to_string(count) + " or -1 ... -" + std::to_string(count));
      }
    }
  }

  const std::string& path_;
  LineCursor cursor_;
  std::vector<std::string_view> words_;
  std::vector<int> corners_;
  std::vector<ForwardReference> forward_;
  model::TriangleMesh mesh_;
};

}  // namespace

model::TriangleMesh parse_obj_mesh(const std::string& path, std::string_view bytes) {
  return ObjReader(path, bytes).read();
}

}  // namespace rigdesign::io
