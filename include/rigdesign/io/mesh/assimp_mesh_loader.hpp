#pragma once
/// Robot collision meshes through Debian's assimp: STL (ascii and binary), COLLADA (.dae),
/// OBJ, PLY and whatever else assimp reads. COLLADA's <unit> scale is applied and its
/// up_axis is not (URDF tools take mesh coordinates as the link frame's, Z up); the node
/// hierarchy's transforms are baked into the vertices.
#include <string>

#include "rigdesign/model/source_location.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::io {

/// Reads every triangle of the file at `path`. Throws InputError at `named_at` (the
/// description's <mesh filename> line) when the file is missing, unreadable by assimp, or
/// holds no triangle.
model::TriangleMesh load_mesh_with_assimp(const std::string& path,
                                          const model::SourceLocation& named_at);

}  // namespace rigdesign::io
