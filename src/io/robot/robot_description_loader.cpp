#include "rigdesign/io/robot/robot_description_loader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include "description_bounds.hpp"
#include "description_sensors.hpp"
#include "joint_tree.hpp"
#include "origin_angles.hpp"
#include "package_locator.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/io/mesh/assimp_mesh_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "xacro_command.hpp"
#include "xacro_expander.hpp"
#include "xml_tree.hpp"

namespace rigdesign::io {
namespace {

namespace fs = std::filesystem;

// urdfdom reports why a description is invalid through console_bridge; this keeps the
// message for our error instead of printing it.
class MessageCollector : public console_bridge::OutputHandler {
 public:
  MessageCollector() {
    console_bridge::useOutputHandler(this);
    console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
  }
  ~MessageCollector() override { console_bridge::restorePreviousOutputHandler(); }
  MessageCollector(const MessageCollector&) = delete;
  MessageCollector& operator=(const MessageCollector&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR)
      messages += (messages.empty() ? "" : "; ") + text;
  }
  std::string messages;
};

model::Pose3 to_pose(const urdf::Pose& pose) {
  model::Pose3 result = model::Pose3::Identity();
  result.translation() = model::Vec3(pose.position.x, pose.position.y, pose.position.z);
  result.linear() =
      Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z)
          .normalized()
          .toRotationMatrix();
  return result;
}

// T_root_link, composing joint origins from the link up to the root (every joint at zero).
model::Pose3 pose_in_root(const urdf::LinkConstSharedPtr& link) {
  model::Pose3 T_root_link = model::Pose3::Identity();
  for (urdf::LinkConstSharedPtr current = link; current && current->parent_joint;
       current = current->getParent()) {
    T_root_link = to_pose(current->parent_joint->parent_to_joint_origin_transform) * T_root_link;
  }
  return T_root_link;
}

xml::Node read_tree(const RobotDescriptionRequest& request, const PackageLocator& packages,
                    std::set<std::string>* environment_read,
                    std::optional<model::Diagnostic>& simulation_skipped) {
  if (!is_xacro_file(request.path))
    return xml::parse_file(request.path, request.named_at, request.field);
  using Expander = RobotDescriptionRequest::Expander;
  if (request.expander != Expander::builtin) {
    if (const auto executable = find_xacro_executable()) {
      return xml::parse_text(
          run_xacro(*executable, request.path, request.args, request.environment, request.named_at),
          request.path);
    }
    if (request.expander == Expander::external) {
      throw model::InputError(model::Diagnostic{
          request.named_at, "robot.expander", "is 'xacro' but no xacro executable is on PATH",
          "ROS's xacro installed (e.g. ros-humble-xacro), or expander: builtin"});
    }
  }
  XacroInput input;
  input.path = request.path;
  input.args = request.args;
  input.environment = request.environment;
  input.packages = &packages;
  input.named_at = request.named_at;
  input.environment_read = environment_read;
  // With its <gazebo> elements, for the sensors the description declares (issue 52 item 5);
  // where a plugin names a package this machine lacks, without them, and a warning says so.
  input.keep_gazebo = true;
  try {
    return expand_xacro(input);
  } catch (const model::InputError& error) {
    input.keep_gazebo = false;
    xml::Node tree = expand_xacro(input);
    const std::string why = error.diagnostics().empty()
                                ? std::string(error.what())
                                : model::to_string(error.diagnostics().front().where) + ": " +
                                      error.diagnostics().front().problem;
    simulation_skipped = model::Diagnostic{
        request.named_at, request.field,
        "its <gazebo> elements do not expand (" + why +
            "): the sensors it declares for Gazebo are unknown, and export may add a second one",
        "the packages those elements name on the package paths", model::Severity::warning};
    return tree;
  }
}

// Where each link's element and its <collision> elements are in the (expanded) text.
struct LinkPlaces {
  model::SourceLocation link;
  std::vector<model::SourceLocation> collisions;
};

std::map<std::string, LinkPlaces> link_places(const xml::Node& robot) {
  std::map<std::string, LinkPlaces> places;
  for (const xml::Node& child : robot.children) {
    if (!child.is_element("link")) continue;
    const std::string* name = child.attribute("name");
    if (!name) continue;
    LinkPlaces& place = places[*name];
    place.link = child.where;
    for (const xml::Node& part : child.children) {
      if (part.is_element("collision")) place.collisions.push_back(part.where);
    }
  }
  return places;
}

// Where each <joint> element is, by name.
std::map<std::string, model::SourceLocation> joint_places(const xml::Node& robot) {
  std::map<std::string, model::SourceLocation> places;
  for (const xml::Node& child : robot.children) {
    if (!child.is_element("joint")) continue;
    if (const std::string* name = child.attribute("name")) places.emplace(*name, child.where);
  }
  return places;
}

model::CollisionShape shape_of(const urdf::Collision& collision, const std::string& link,
                               const model::Pose3& T_root_link, const model::SourceLocation& where,
                               const RobotDescriptionRequest& request,
                               const PackageLocator& packages) {
  model::CollisionShape shape;
  shape.link = link;
  shape.where = where;
  shape.T_root_shape = T_root_link * to_pose(collision.origin);
  const urdf::Geometry& geometry = *collision.geometry;
  switch (geometry.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(geometry);
      shape.kind = model::CollisionShape::Kind::box;
      shape.size = model::Vec3(box.dim.x, box.dim.y, box.dim.z);
      require_positive_size(shape.size, where, "collision.geometry.box.size",
                            "three positive sizes in metres, e.g. \"0.4 0.3 0.2\"");
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
      shape.kind = model::CollisionShape::Kind::cylinder;
      shape.radius = cylinder.radius;
      shape.length = cylinder.length;
      require_positive_size(model::Vec3(shape.radius, shape.length, 1.0), where,
                            "collision.geometry.cylinder (radius, length)",
                            "a positive radius and length in metres");
      break;
    }
    case urdf::Geometry::SPHERE:
      shape.kind = model::CollisionShape::Kind::sphere;
      shape.radius = static_cast<const urdf::Sphere&>(geometry).radius;
      require_positive_size(model::Vec3(shape.radius, 1.0, 1.0), where,
                            "collision.geometry.sphere.radius", "a positive radius in metres");
      break;
    case urdf::Geometry::MESH: {
      const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
      shape.kind = model::CollisionShape::Kind::mesh;
      const auto resolved = packages.resolve_uri(mesh.filename);
      if (!resolved) {
        throw model::InputError(model::Diagnostic{
            where, "collision.geometry.mesh.filename",
            "'" + mesh.filename + "': its package is not found",
            "package://PKG/... with PKG under the rig's robot.package_paths, ROS_PACKAGE_PATH "
            "or AMENT_PREFIX_PATH"});
      }
      shape.mesh_file = *resolved;
      if (fs::path(shape.mesh_file).is_relative()) {
        shape.mesh_file = (fs::path(request.path).parent_path() / shape.mesh_file).string();
      }
      const model::Vec3 scale(mesh.scale.x, mesh.scale.y, mesh.scale.z);
      // A negative component mirrors (Gazebo and RViz accept it); zero flattens the body.
      require_positive_size(scale.cwiseAbs(), where, "collision.geometry.mesh.scale",
                            "three non-zero factors, e.g. \"0.001 0.001 0.001\" for mm");
      if (request.load_meshes) {
        std::error_code error;
        const std::uintmax_t bytes = fs::file_size(shape.mesh_file, error);
        if (!error && bytes > kMaxMeshFileBytes) {
          throw model::InputError(model::Diagnostic{
              where, "collision.geometry.mesh.filename",
              "'" + shape.mesh_file + "' is " + std::to_string(bytes >> 20) + " MiB",
              "a collision mesh of at most 64 MiB (decimate it: collision meshes need few "
              "triangles)"});
        }
        shape.mesh = load_mesh_with_assimp(shape.mesh_file, where);
        for (model::Vec3& v : shape.mesh.vertices) v = v.cwiseProduct(scale);
      }
      break;
    }
  }
  return shape;
}

}  // namespace

bool is_xacro_file(const std::string& path) {
  if (path.size() >= 6 && path.compare(path.size() - 6, 6, ".xacro") == 0) return true;
  if (not_a_regular_file(path)) return false;  // refused by the loader, never opened to wait
  std::ifstream stream(path);
  std::string head(4096, '\0');
  stream.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(stream.gcount()));
  return head.find("xmlns:xacro") != std::string::npos;
}

model::RobotDescription load_robot_description(const RobotDescriptionRequest& request) {
  if (const std::optional<std::string> kind = not_a_regular_file(request.path)) {
    // A FIFO or a device would block the reader forever.
    throw model::InputError(
        model::Diagnostic{request.named_at, request.field,
                          "'" + request.path + "' is not a regular file: it " + *kind,
                          "a .urdf or .urdf.xacro file"});
  }
  const PackageLocator packages(request.package_paths);
  // Only the built-in expander says which variables it read; ROS's xacro is not asked.
  std::set<std::string> environment_read;
  const bool builtin =
      is_xacro_file(request.path) &&
      (request.expander == RobotDescriptionRequest::Expander::builtin || !find_xacro_executable());
  std::optional<model::Diagnostic> simulation_skipped;
  const xml::Node tree = read_tree(request, packages, &environment_read, simulation_skipped);
  if (tree.name != "robot") {
    throw model::InputError(model::Diagnostic{
        tree.where, "robot", "the root element is <" + tree.name + ">", "a URDF <robot> element"});
  }
  require_joint_tree(tree);
  require_radian_origins(tree);
  urdf::ModelInterfaceSharedPtr urdf_model;
  std::string why;
  {
    MessageCollector collector;
    urdf_model = urdf::parseURDF(xml::to_xml(tree));
    why = collector.messages;
  }
  if (!urdf_model) {
    throw model::InputError(model::Diagnostic{
        {request.path, 0, 0},
        "robot",
        "is not a valid URDF" + (why.empty() ? std::string() : ": " + why),
        "links joined by joints into one tree, each joint with a parent, a child and a type"});
  }
  model::RobotDescription description;
  if (builtin) {
    for (const auto& [name, value] : request.environment) {
      if (environment_read.count(name)) continue;
      description.warnings.push_back(
          {request.named_at, "robot.env." + name,
           "is never read: the description has no $(optenv " + name + ") or $(env " + name + ")",
           "a variable the description reads (a typo?)", model::Severity::warning});
    }
  }
  if (simulation_skipped) description.warnings.push_back(*simulation_skipped);
  for (model::DescriptionSensor& sensor : description_sensors(tree, description.warnings)) {
    // A reference to a joint (preserveFixedJoint) or an unknown link holds no sensor of a link.
    if (urdf_model->getLink(sensor.link)) description.sensors.push_back(std::move(sensor));
  }
  description.name = urdf_model->getName();
  description.file = request.path;
  description.root_link = urdf_model->getRoot()->name;
  const std::map<std::string, LinkPlaces> places = link_places(tree);
  description.joint_where = joint_places(tree);
  std::vector<urdf::LinkSharedPtr> links;
  urdf_model->getLinks(links);
  std::size_t triangles = 0;
  for (const urdf::LinkSharedPtr& link : links) {
    const model::Pose3 T_root_link = pose_in_root(link);
    if (link->parent_joint) {
      const auto joint = description.joint_where.find(link->parent_joint->name);
      require_position_in_bounds(T_root_link.translation(),
                                 joint != description.joint_where.end()
                                     ? joint->second
                                     : model::SourceLocation{request.path, 0, 0},
                                 "joint '" + link->parent_joint->name + "' origin");
    }
    description.T_root_link[link->name] = T_root_link;
    const auto place = places.find(link->name);
    if (place != places.end()) description.link_where[link->name] = place->second.link;
    if (link->parent_joint)
      description.parent_link[link->name] = link->parent_joint->parent_link_name;
    for (std::size_t i = 0; i < link->collision_array.size(); ++i) {
      const urdf::CollisionSharedPtr& collision = link->collision_array[i];
      if (!collision || !collision->geometry) continue;
      const model::SourceLocation where =
          place != places.end() && i < place->second.collisions.size()
              ? place->second.collisions[i]
              : model::SourceLocation{request.path, 0, 0};
      description.collisions.push_back(
          shape_of(*collision, link->name, T_root_link, where, request, packages));
      require_position_in_bounds(description.collisions.back().T_root_shape.translation(), where,
                                 "collision origin");
      triangles += description.collisions.back().mesh.triangles.size();
      if (triangles > kMaxDescriptionTriangles) {
        throw model::InputError(
            model::Diagnostic{where, "collision.geometry.mesh",
                              "the description's meshes hold more than " +
                                  std::to_string(kMaxDescriptionTriangles) + " triangles",
                              "at most 2e6 triangles in all (decimate the collision meshes)"});
      }
    }
  }
  // After the meshes, so that their package:// lookups count too.
  for (const PackageLocator::Shadowed& shadowed : packages.shadowed()) {
    std::string hidden;
    for (const std::string& folder : shadowed.hidden)
      hidden += (hidden.empty() ? "" : ", ") + folder;
    description.warnings.push_back({request.named_at, "robot.package_paths",
                                    "package '" + shadowed.package + "' is in " + shadowed.used +
                                        " and in " + hidden + ": the first is used",
                                    "one folder per package (remove or reorder the others)",
                                    model::Severity::warning});
  }
  return description;
}

}  // namespace rigdesign::io
