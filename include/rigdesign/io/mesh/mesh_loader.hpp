#pragma once
/// Triangle meshes from files, for scenes loaded from disk (DESIGN.md section 6): PLY (ascii
/// and binary_little_endian), Wavefront OBJ and OFF, told apart by the file's extension.
#include <string>

#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::io {

/// Reads the mesh at `path` (`.ply`, `.obj` or `.off`, any letter case). Coordinates are
/// taken as metres, as stored; polygons with more than three corners are split into a fan
/// of triangles around their first corner (so convex polygons keep their area and winding).
/// Vertex properties other than x, y, z and every other element, line or statement are
/// skipped. Throws InputError naming file:line:column (PLY ascii, OBJ, OFF) or the byte
/// offset and element index (PLY binary), the field and the expected form for an unknown
/// extension, an unreadable file, a malformed or truncated file, a non-numeric or non-finite
/// value, an index out of range, a face with fewer than three corners, and a file with no
/// triangle.
model::TriangleMesh load_mesh(const std::string& path);

/// Whether `path` ends in an extension load_mesh reads (.ply, .obj, .off, any case).
bool has_mesh_extension(const std::string& path);

}  // namespace rigdesign::io
