#pragma once
// The three mesh formats behind load_mesh, one implementation file each (mesh_ply.cpp,
// mesh_obj.cpp, mesh_off.cpp), and what they share: located errors and fan triangulation.
// mesh_loader.cpp reads the file and picks the format by extension. Private to io.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::io {

/// Parses a whole PLY file (ascii or binary_little_endian) held in `bytes`.
model::TriangleMesh parse_ply_mesh(const std::string& path, std::string_view bytes);
/// Parses a whole Wavefront OBJ file held in `bytes`.
model::TriangleMesh parse_obj_mesh(const std::string& path, std::string_view bytes);
/// Parses a whole OFF file held in `bytes`.
model::TriangleMesh parse_off_mesh(const std::string& path, std::string_view bytes);

/// Throws InputError at `line`:`column` of `path` (both 0 for a binary body, whose problem
/// text names the byte offset and element index instead).
[[noreturn]] void throw_mesh_error(const std::string& path, int line, int column,
                                   const std::string& field, const std::string& problem,
                                   const std::string& expected);

/// 1-based column of `word` inside `line` (a view into it).
int column_of(std::string_view line, std::string_view word);

/// A whole word as a signed decimal integer; nullopt otherwise.
bool parse_index(std::string_view word, std::int64_t& index);

/// Appends the polygon `corners` (valid vertex indices, at least 3) as a fan of triangles
/// around its first corner: (c0, c1, c2), (c0, c2, c3), ...
void append_fan(model::TriangleMesh& mesh, const std::vector<int>& corners);

}  // namespace rigdesign::io
