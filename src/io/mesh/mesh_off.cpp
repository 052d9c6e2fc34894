// OFF meshes (Geomview's object file format): an optional `OFF` keyword (or a variant such as
// COFF or NOFF), the counts `vertices faces [edges]` on the keyword's line or the next one,
// then one vertex per line (x y z, further values such as a colour ignored) and one polygon
// per line (n i0 ... i(n-1), 0-based, a colour after the indices ignored). '#' starts a
// comment; blank lines are skipped.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/cloud/cloud_text.hpp"
#include "io/mesh/mesh_formats.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kCountsForm = "OFF, then 'vertices faces [edges]' as integers >= 0";
constexpr const char* kOffVertexForm = "x y z (finite numbers, metres), one vertex per line";
constexpr const char* kOffFaceForm = "n i0 ... i(n-1): n >= 3 corners, 0-based vertex indices";

bool is_off_keyword(std::string_view word) {
  return word.size() >= 3 && word.substr(word.size() - 3) == "OFF";
}

class OffReader {
 public:
  OffReader(const std::string& path, std::string_view bytes) : path_(path), cursor_(bytes) {}

  model::TriangleMesh read() {
    read_counts();
    if (vertex_count_ > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      fail(line_, words_[0], "counts", "too many vertices", "at most 2^31 - 1 vertices");
    }
    for (std::size_t v = 0; v < vertex_count_; ++v) read_vertex(v);
    for (std::size_t f = 0; f < face_count_; ++f) read_face(f);
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(std::string_view line, std::string_view word, const std::string& field,
                         const std::string& problem, const std::string& expected) const {
    throw_mesh_error(path_, cursor_.line_number(), column_of(line, word), field, problem, expected);
  }

  // The next line with words on it, without its comment; false at the end of the file.
  bool next_line() {
    while (const auto raw = cursor_.next()) {
      line_ = *raw;
      if (const std::size_t hash = line_.find('#'); hash != std::string_view::npos) {
        line_ = line_.substr(0, hash);
      }
      split_words(line_, words_);
      if (!words_.empty()) return true;
    }
    return false;
  }

  void need_line(const std::string& field, const std::string& what, const char* expected) {
    if (!next_line()) {
      throw_mesh_error(path_, std::max(cursor_.line_number(), 1), 1, field,
                       "the file ends before " + what, expected);
    }
  }

  void read_counts() {
    need_line("counts", "the vertex and face counts", kCountsForm);
    std::size_t first = 0;
    if (is_off_keyword(words_[0])) {
      first = 1;
      if (words_.size() == 1) {  // the counts are on a line of their own
        need_line("counts", "the vertex and face counts", kCountsForm);
        first = 0;
      }
    }
    const std::size_t given = words_.size() - first;
    if (given < 2 || given > 3) {
      fail(line_, words_[first < words_.size() ? first : 0], "counts",
           "has " + std::to_string(given) + " value(s)", kCountsForm);
    }
    std::size_t* targets[] = {&vertex_count_, &face_count_};
    for (std::size_t i = 0; i < given; ++i) {
      const auto count = parse_count(words_[first + i]);
      if (!count) {
        fail(line_, words_[first + i], "counts", quote_word(words_[first + i]) + " is not a count",
             kCountsForm);
      }
      if (i < 2) *targets[i] = *count;
    }
  }

  void read_vertex(std::size_t index) {
    const std::string field = "vertex[" + std::to_string(index) + "]";
    need_line(field, "vertex " + std::to_string(index) + " of " + std::to_string(vertex_count_),
              kOffVertexForm);
    if (words_.size() < 3) {
      fail(line_, words_[0], field, "has " + std::to_string(words_.size()) + " value(s)",
           kOffVertexForm);
    }
    model::Vec3 vertex;
    for (std::size_t i = 0; i < words_.size(); ++i) {
      const auto value = parse_double(words_[i]);
      if (!value || (i < 3 && !std::isfinite(*value))) {
        fail(line_, words_[i], field, quote_word(words_[i]) + " is not a finite number",
             kOffVertexForm);
      }
      if (i < 3) vertex[static_cast<Eigen::Index>(i)] = *value;
    }
    mesh_.vertices.push_back(vertex);
  }

  void read_face(std::size_t index) {
    const std::string field = "face[" + std::to_string(index) + "]";
    need_line(field, "face " + std::to_string(index) + " of " + std::to_string(face_count_),
              kOffFaceForm);
    const auto corners = parse_count(words_[0]);
    if (!corners || *corners < 3) {
      fail(line_, words_[0], field, "corner count " + quote_word(words_[0]) + " is not 3 or more",
           kOffFaceForm);
    }
    if (words_.size() - 1 < *corners) {
      fail(line_, words_[0], field,
           "lists " + std::to_string(words_.size() - 1) + " of its " + std::to_string(*corners) +
               " corners",
           kOffFaceForm);
    }
    corners_.clear();
    for (std::size_t i = 1; i <= *corners; ++i) {
      std::int64_t vertex = 0;
      if (!parse_index(words_[i], vertex)) {
        fail(line_, words_[i], field, quote_word(words_[i]) + " is not an integer", kOffFaceForm);
      }
      if (vertex < 0 || static_cast<std::uint64_t>(vertex) >= vertex_count_) {
        fail(line_, words_[i], field,
             "refers to vertex " + std::to_string(vertex) + "; the file has " +
                 std::to_string(vertex_count_) + " vertices",
             "indices in [0, " + std::to_string(vertex_count_) + ")");
      }
      corners_.push_back(static_cast<int>(vertex));
    }
    append_fan(mesh_, corners_);
  }

  const std::string& path_;
  LineCursor cursor_;
  std::string_view line_;
  std::vector<std::string_view> words_;
  std::vector<int> corners_;
  std::size_t vertex_count_ = 0;
  std::size_t face_count_ = 0;
  model::TriangleMesh mesh_;
};

}  // namespace

model::TriangleMesh parse_off_mesh(const std::string& path, std::string_view bytes) {
  return OffReader(path, bytes).read();
}

}  // namespace rigdesign::io
