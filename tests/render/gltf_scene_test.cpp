// Issue 37 (export --gltf): the rig's glTF 2.0 scene read back by assimp's glTF 2 importer, an
// independent reader (not ours), with every expected coordinate worked out by hand.
#include "rigdesign/render/gltf_scene.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <catch2/catch.hpp>
#include <set>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

TEST_CASE("glTF scene: a triangle stands upright on its frame, read by assimp", "[render][gltf]") {
  render::GltfPart triangle;
  triangle.name = "tri";
  triangle.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 2, 3}};
  triangle.mesh.triangles = {{0, 1, 2}};
  triangle.colour = {1, 0, 0};
  render::GltfPart empty;  // no triangles: left out
  empty.name = "nothing";
  const std::string text = render::gltf_scene("test", "base_link", 0.5, {triangle, empty});
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFileFromMemory(text.data(), text.size(), aiProcess_PreTransformVertices, "gltf");
  INFO(importer.GetErrorString());
  REQUIRE(scene != nullptr);
  REQUIRE(scene->mNumMeshes == 1);
  const aiMesh& mesh = *scene->mMeshes[0];
  REQUIRE(mesh.mNumVertices == 3);
  REQUIRE(mesh.mNumFaces == 1);
  // glTF's world = rotation -90 deg about x, then down 0.5 m: (x, y, z) -> (x, z - 0.5, -y).
  // (0, 2, 3) -> (0, 2.5, -2).
  std::set<std::array<float, 3>> points;
  for (unsigned i = 0; i < mesh.mNumVertices; ++i)
    points.insert({mesh.mVertices[i].x, mesh.mVertices[i].y, mesh.mVertices[i].z});
  const auto has = [&](float x, float y, float z) {
    return std::any_of(points.begin(), points.end(), [&](const std::array<float, 3>& p) {
      return std::abs(p[0] - x) < 1e-5f && std::abs(p[1] - y) < 1e-5f && std::abs(p[2] - z) < 1e-5f;
    });
  };
  CHECK(has(0, -0.5f, 0));
  CHECK(has(1, -0.5f, 0));
  CHECK(has(0, 2.5f, -2));
}

TEST_CASE(
    "export --gltf: the body, its supports, each mount's volume and housing, as assimp reads them",
    "[render][gltf]") {
  test::TempFolder folder;
  const std::string out = folder.path() + "/export";
  const test::CliResult result = test::run_cli(
      {"export", test::source_path("rigs/cart_two_scanners.yaml"), "--to", out, "--gltf"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  CHECK(result.out.find("rig_fov.gltf") != std::string::npos);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(out + "/rig_fov.gltf", aiProcess_PreTransformVertices);
  INFO(importer.GetErrorString());
  REQUIRE(scene != nullptr);
  // rigs/cart_two_scanners.yaml: a body, its two brackets, and two mounts, front_lidar and
  // rear_lidar, each with its volume and its datasheet housing (issue 52 item 2).
  REQUIRE(scene->mNumMeshes == 7);
  std::set<std::string> names;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) names.insert(scene->mMeshes[i]->mName.C_Str());
  CHECK(names == std::set<std::string>{"body", "support 'front_bracket'", "support 'rear_bracket'",
                                       "front_lidar", "front_lidar housing", "rear_lidar",
                                       "rear_lidar housing"});
  // The front housing: sensors.yaml's RPLIDAR A1 box (read here with yaml-cpp) about the scanner
  // at (0.5, 0, 0.2) m, unturned: glTF x = robot x, y = robot z.
  YAML::Node housing;
  for (const YAML::Node& sensor : YAML::LoadFile(test::source_path("sensors.yaml"))["sensors"])
    if (sensor["id"].as<std::string>() == "rplidar_a1m8") housing = sensor["housing"];
  REQUIRE(housing["shape"].as<std::string>() == "box");
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh& mesh = *scene->mMeshes[i];
    if (std::string(mesh.mName.C_Str()) != "front_lidar housing") continue;
    float low[2] = {1e9f, 1e9f}, high[2] = {-1e9f, -1e9f};
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const float p[2] = {mesh.mVertices[v].x, mesh.mVertices[v].y};
      for (int k = 0; k < 2; ++k)
        low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
    }
    const double cx = 0.5 + housing["center"][0].as<double>();
    const double cz = 0.2 + housing["center"][2].as<double>();
    CHECK(low[0] == Approx(cx - housing["size"][0].as<double>() / 2).margin(1e-5));
    CHECK(high[0] == Approx(cx + housing["size"][0].as<double>() / 2).margin(1e-5));
    CHECK(low[1] == Approx(cz - housing["size"][2].as<double>() / 2).margin(1e-5));
    CHECK(high[1] == Approx(cz + housing["size"][2].as<double>() / 2).margin(1e-5));
  }
  // The body: footprint 0.6 x 0.4 m, 0.4 m high, robot frame on the floor (no description, so
  // the frame is base_footprint at height 0): glTF y (up) spans 0..0.4, x -0.3..0.3, and glTF
  // z = -robot y spans -0.2..0.2.
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh& mesh = *scene->mMeshes[i];
    if (std::string(mesh.mName.C_Str()) != "body") continue;
    float low[3] = {1e9f, 1e9f, 1e9f}, high[3] = {-1e9f, -1e9f, -1e9f};
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const float p[3] = {mesh.mVertices[v].x, mesh.mVertices[v].y, mesh.mVertices[v].z};
      for (int k = 0; k < 3; ++k)
        low[k] = std::min(low[k], p[k]), high[k] = std::max(high[k], p[k]);
    }
    CHECK(low[0] == Approx(-0.3).margin(1e-5));
    CHECK(high[0] == Approx(0.3).margin(1e-5));
    CHECK(low[1] == Approx(0.0).margin(1e-5));
    CHECK(high[1] == Approx(0.4).margin(1e-5));
    CHECK(low[2] == Approx(-0.2).margin(1e-5));
    CHECK(high[2] == Approx(0.2).margin(1e-5));
  }
}
