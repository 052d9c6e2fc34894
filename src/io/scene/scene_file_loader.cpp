#include "rigdesign/io/scene/scene_file_loader.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <system_error>

#include "io/scene/trajectory.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/io/mesh/mesh_loader.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

// Triangles a scene may hold: the ray caster's tree takes on the order of 100 bytes per
// triangle (estimate), so 1e7 is about a gigabyte; the bundled lab has under a hundred.
constexpr double kMaxSceneTriangles = 1e7;

using io::MapReader;
using io::Need;

constexpr const char* kMeshForm = "a .ply, .obj or .off file, relative to the scene file";

// Loads each mesh file once (a crowd of people can share one body) and files its problems
// under the scene file's findings.
class MeshFiles {
 public:
  explicit MeshFiles(std::string scene_file) : scene_file_(std::move(scene_file)) {}

  std::optional<model::TriangleMesh> read(MapReader& object) {
    const auto name = object.text("mesh", Need::required, kMeshForm);
    if (!name) return std::nullopt;
    const std::string path = resolve_beside(scene_file_, *name);
    if (!has_mesh_extension(path)) {
      object.require(false, "mesh", "'" + *name + "' is not a mesh file by its extension",
                     kMeshForm);
      return std::nullopt;
    }
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(path, ignored)) {
      object.require(false, "mesh", "file '" + path + "' does not exist", kMeshForm);
      return std::nullopt;
    }
    if (const auto found = meshes_.find(path); found != meshes_.end()) return found->second;
    try {
      return meshes_[path] = load_mesh(path);
    } catch (const model::InputError& error) {
      for (const model::Diagnostic& diagnostic : error.diagnostics())
        object.diagnostics().add(diagnostic);
      meshes_[path] = std::nullopt;  // reported once, however many objects use it
      return std::nullopt;
    }
  }

 private:
  std::string scene_file_;
  std::map<std::string, std::optional<model::TriangleMesh>> meshes_;
};

// `pose` (xyz, rpy_deg) and `scale` as one transform: scale about the mesh's origin first.
Eigen::Affine3d read_placement(MapReader& object) {
  const double scale =
      object.has("scale") ? io::positive(object, "scale", Need::required, "a factor > 0") : 1.0;
  model::Pose3 T_parent_mesh = model::Pose3::Identity();
  if (auto pose = object.map("pose", Need::optional, "a map with xyz and rpy_deg")) {
    T_parent_mesh = io::xyz_rpy_deg_pose(*pose, Need::optional);
    pose->reject_unknown_keys();
  }
  return T_parent_mesh * Eigen::Scaling(scale > 0 ? scale : 1.0);
}

model::TriangleMesh placed(const model::TriangleMesh& mesh, const Eigen::Affine3d& T_parent_mesh) {
  model::TriangleMesh result = mesh;
  for (model::Vec3& vertex : result.vertices) vertex = T_parent_mesh * vertex;
  return result;
}

model::Pose3 read_robot_start(MapReader& start) {
  const auto xyz = start.numbers("xyz", Need::required, 3, 3, "[x, y, z] in metres, finite");
  const double yaw = start.number("yaw_deg", Need::optional, "degrees, finite").value_or(0.0);
  start.reject_unknown_keys();
  const model::Vec3 position =
      xyz ? model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]) : model::Vec3::Zero();
  return model::pose_from_xyz_rpy(position, model::Vec3(0.0, 0.0, model::deg_to_rad(yaw)));
}

io::WaypointPath read_waypoint_path(MapReader& trajectory) {
  io::WaypointPath path;
  path.loop = trajectory.boolean("loop", Need::optional).value_or(false);
  const YAML::Node list = trajectory.node("waypoints");
  trajectory.require(!list.IsSequence() || list.size() > 0, "waypoints", "is empty",
                     "at least one waypoint");
  for (MapReader& waypoint :
       trajectory.maps("waypoints", Need::required, "a list of {t, xyz, yaw_deg}")) {
    const auto t = waypoint.number("t", Need::required, "seconds, finite");
    const auto xyz = waypoint.numbers("xyz", Need::required, 3, 3, "[x, y, z] in metres, finite");
    const double yaw =
        waypoint.number("yaw_deg", Need::optional, "degrees, finite (default 0)").value_or(0.0);
    waypoint.reject_unknown_keys();
    if (!t || !xyz) continue;
    if (!path.waypoints.empty()) {
      waypoint.require(*t > path.waypoints.back().t, "t",
                       "is not after the previous waypoint's time", "times strictly increasing");
    }
    path.waypoints.push_back(
        {*t, model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]), model::deg_to_rad(yaw)});
  }
  trajectory.reject_unknown_keys();
  return path;
}

io::EllipsePath read_ellipse_path(MapReader& ellipse) {
  io::EllipsePath path;
  const auto centre =
      ellipse.numbers("centre", Need::optional, 2, 2, "[x, y] in metres, finite (default [0, 0])");
  if (centre) path.centre = model::Vec2((*centre)[0], (*centre)[1]);
  if (const auto axes =
          ellipse.numbers("semi_axes", Need::required, 2, 2, "[a, b] in metres, both > 0")) {
    ellipse.require((*axes)[0] > 0 && (*axes)[1] > 0, "semi_axes", "has a semi-axis <= 0",
                    "[a, b] in metres, both > 0");
    path.semi_axes = model::Vec2((*axes)[0], (*axes)[1]);
  }
  path.period = io::positive(ellipse, "period", Need::required, "seconds per lap, > 0");
  path.face_travel = ellipse.boolean("face_travel", Need::optional).value_or(true);
  ellipse.reject_unknown_keys();
  return path;
}

std::function<model::Pose3(double)> read_motion(MapReader& object) {
  const bool has_trajectory = object.has("trajectory");
  const bool has_ellipse = object.has("ellipse");
  object.require(has_trajectory != has_ellipse, "trajectory",
                 has_trajectory ? "given together with ellipse" : "missing",
                 "either trajectory (waypoints) or ellipse");
  if (auto trajectory = object.map("trajectory", Need::optional, "a map with loop, waypoints")) {
    io::WaypointPath path = read_waypoint_path(*trajectory);
    if (!path.waypoints.empty()) return path;
  }
  if (auto ellipse = object.map("ellipse", Need::optional,
                                "a map with centre, semi_axes, period, face_travel")) {
    return read_ellipse_path(*ellipse);
  }
  return [](double) { return model::Pose3::Identity(); };
}

// Names identify objects in reports; two alike would make them ambiguous.
std::string read_name(MapReader& object, std::set<std::string>& names) {
  const std::string name = object.text("name", Need::required, "the object's name").value_or("");
  if (!name.empty() && !names.insert(name).second) {
    object.require(false, "name", "duplicate object name '" + name + "'", "unique names");
  }
  return name;
}

}  // namespace

model::Scene load_scene_file(const std::string& yaml_path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(yaml_path, diagnostics,
                                    "a scene: a map with name, robot_start, static, moving");
  model::Scene scene;
  scene.name = top.text("name", Need::required, "the scene's name").value_or("");
  if (auto start = top.map("robot_start", Need::optional, "a map with xyz and yaw_deg")) {
    scene.T_world_robot = read_robot_start(*start);
  }
  MeshFiles meshes(yaml_path);
  std::set<std::string> names;
  std::size_t declared = 0;
  for (MapReader& object : top.maps("static", Need::optional, "a list of static objects")) {
    ++declared;
    std::string name = read_name(object, names);
    const auto mesh = meshes.read(object);
    const Eigen::Affine3d T_world_mesh = read_placement(object);
    object.reject_unknown_keys();
    if (mesh) scene.objects.push_back({std::move(name), placed(*mesh, T_world_mesh)});
  }
  for (MapReader& object : top.maps("moving", Need::optional, "a list of moving objects")) {
    ++declared;
    std::string name = read_name(object, names);
    const auto mesh = meshes.read(object);
    const Eigen::Affine3d T_object_mesh = read_placement(object);
    std::function<model::Pose3(double)> T_world_object = read_motion(object);
    const double gives_way =
        object.has("gives_way_within")
            ? io::non_negative(object, "gives_way_within", Need::required, "metres, >= 0")
            : 0.0;
    object.reject_unknown_keys();
    if (mesh) {
      scene.moving.push_back(
          {std::move(name), placed(*mesh, T_object_mesh), T_world_object, gives_way});
    }
  }
  if (declared == 0 && !diagnostics.has_errors()) {
    top.require(false, "static", "the scene has no objects",
                "at least one object under static or moving");
  }
  // Every frame ray-casts against every triangle's tree node: bounded before any simulation.
  std::size_t triangles = 0;
  for (const auto& object : scene.objects) triangles += object.mesh.triangles.size();
  for (const auto& object : scene.moving) triangles += object.mesh.triangles.size();
  if (static_cast<double>(triangles) > kMaxSceneTriangles) {
    top.require(false, "static",
                "the scene's meshes hold " + std::to_string(triangles) + " triangles",
                "at most 1e7 triangles in all (decimate the meshes)");
  }
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return scene;
}

}  // namespace rigdesign::io
