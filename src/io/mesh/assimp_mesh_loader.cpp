#include "rigdesign/io/mesh/assimp_mesh_loader.hpp"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>
#include <new>

#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {

model::TriangleMesh load_mesh_with_assimp(const std::string& path,
                                          const model::SourceLocation& named_at) {
  const auto fail = [&](const std::string& problem) {
    throw model::InputError(
        model::Diagnostic{named_at, "mesh.filename", problem,
                          "a mesh file with triangles (STL, COLLADA .dae, OBJ, PLY)"});
  };
  std::error_code error;
  if (!std::filesystem::exists(path, error)) fail("'" + path + "' does not exist");
  // A FIFO or a device (/dev/zero) would block or never end.
  if (!std::filesystem::is_regular_file(path, error)) {
    fail("'" + path + "' is not a regular file (a folder, FIFO or device)");
  }
  Assimp::Importer importer;
  // URDF consumers (robot_state_publisher, Gazebo, RViz) read COLLADA vertices in the link
  // frame as written; assimp would otherwise turn Z_UP files to its own Y-up convention.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Only triangles matter: drop points and lines, so they never reach the occluder.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                        aiProcess_PreTransformVertices | aiProcess_SortByPType);
  } catch (const std::bad_alloc&) {
    // Some corrupt COLLADA files make assimp 5.2 reserve for counts the file cannot hold.
    fail("'" + path + "' cannot be read: assimp ran out of memory on it (a corrupt file?)");
  }
  if (!scene) fail("'" + path + "' cannot be read: " + importer.GetErrorString());
  model::TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& part = *scene->mMeshes[m];
    const int offset = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < part.mNumVertices; ++v) {
      const aiVector3D& p = part.mVertices[v];
      mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < part.mNumFaces; ++f) {
      const aiFace& face = part.mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({offset + static_cast<int>(face.mIndices[0]),
                                offset + static_cast<int>(face.mIndices[1]),
                                offset + static_cast<int>(face.mIndices[2])});
    }
  }
  if (mesh.triangles.empty()) fail("'" + path + "' holds no triangle");
  for (const model::Vec3& v : mesh.vertices) {
    if (!v.allFinite()) fail("'" + path + "' has a vertex that is not a finite number");
  }
  return mesh;
}

}  // namespace rigdesign::io
