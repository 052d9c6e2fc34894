#include "io/mesh/mesh_formats.hpp"

#include <charconv>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

void throw_mesh_error(const std::string& path, int line, int column, const std::string& field,
                      const std::string& problem, const std::string& expected) {
  throw model::InputError(model::Diagnostic{{path, line, column}, field, problem, expected});
}

int column_of(std::string_view line, std::string_view word) {
  return static_cast<int>(word.data() - line.data()) + 1;
}

bool parse_index(std::string_view word, std::int64_t& index) {
  if (word.size() > 1 && word[0] == '+') word.remove_prefix(1);
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), index);
  return error == std::errc() && end == word.data() + word.size();
}

void append_fan(model::TriangleMesh& mesh, const std::vector<int>& corners) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    mesh.triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
}

}  // namespace rigdesign::io
