#include "rigdesign/io/mesh/mesh_loader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/mesh/mesh_formats.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

enum class MeshFormat { ply, obj, off, unknown };

constexpr const char* kReadable = "a readable .ply, .obj or .off mesh file";

MeshFormat mesh_format_of(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".ply") return MeshFormat::ply;
  if (extension == ".obj") return MeshFormat::obj;
  if (extension == ".off") return MeshFormat::off;
  return MeshFormat::unknown;
}

}  // namespace

bool has_mesh_extension(const std::string& path) {
  return mesh_format_of(path) != MeshFormat::unknown;
}

model::TriangleMesh load_mesh(const std::string& path) {
  const MeshFormat format = mesh_format_of(path);
  if (format == MeshFormat::unknown) {
    throw model::InputError(model::Diagnostic{
        {path, 0, 0},
        "file",
        "unknown mesh format '" + std::filesystem::path(path).extension().string() + "'",
        "a path ending in .ply, .obj or .off"});
  }
  const std::string bytes = io::read_file_bytes(path, kReadable);
  model::TriangleMesh mesh = format == MeshFormat::ply   ? io::parse_ply_mesh(path, bytes)
                             : format == MeshFormat::obj ? io::parse_obj_mesh(path, bytes)
                                                         : io::parse_off_mesh(path, bytes);
  if (mesh.triangles.empty()) {
    throw model::InputError(model::Diagnostic{{path, 0, 0},
                                              "faces",
                                              "the mesh has no faces",
                                              "at least one polygon of 3 or more vertices"});
  }
  return mesh;
}

}  // namespace rigdesign::io
