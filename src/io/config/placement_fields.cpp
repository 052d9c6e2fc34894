#include "io/config/placement_fields.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/io/robot/xacro_environment.hpp"
#include "rigdesign/model/closest_name.hpp"
#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/polygon_checks.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/sensor_housing.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

std::vector<model::Vec2> read_footprint(MapReader& body) {
  const std::string expected = "a list of at least 3 [x, y] vertices in metres";
  std::vector<model::Vec2> footprint;
  const YAML::Node list = body.node("footprint");
  if (!list.IsSequence() || list.size() < 3) {
    body.require(false, "footprint", "is not a list of 3 or more vertices", expected);
    return footprint;
  }
  bool all_valid = true;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string field = body.field("footprint") + "[" + std::to_string(i) + "]";
    const YAML::Node vertex = list[i];
    if (!vertex.IsSequence() || vertex.size() != 2) {
      body.diagnostics().error(io::location_of(vertex, body.file()), field, "is not an [x, y] pair",
                               expected);
      all_valid = false;
      continue;
    }
    const auto x =
        io::sequence_number(vertex[0], field + "[0]", body.file(), expected, body.diagnostics());
    const auto y =
        io::sequence_number(vertex[1], field + "[1]", body.file(), expected, body.diagnostics());
    all_valid = all_valid && x && y;
    footprint.emplace_back(x.value_or(0.0), y.value_or(0.0));
  }
  if (!all_valid) return {};
  for (const model::Vec2& vertex : footprint) {
    if (vertex.cwiseAbs().maxCoeff() > model::kMaxCoordinate) {
      body.require(false, "footprint", "has a vertex beyond +-1e8 m", expected);
      return {};
    }
  }
  const std::optional<std::string> problem = model::polygon_problem(footprint);
  body.require(!problem, "footprint", problem.value_or(""),
               "vertices of a simple polygon around the robot's vertical axis");
  if (problem) return {};
  if (model::signed_area(footprint) < 0) std::reverse(footprint.begin(), footprint.end());
  return footprint;
}

}  // namespace

model::RobotBody read_body(MapReader& body) {
  model::RobotBody result;
  result.height =
      io::positive_length(body, "height", Need::required, "the body height h in metres, > 0");
  const bool has_radius = body.has("radius");
  const bool has_footprint = body.has("footprint");
  body.require(has_radius != has_footprint, "radius",
               has_radius ? "given together with footprint" : "missing",
               "either radius (a cylinder) or footprint (a prism), in metres");
  if (has_radius) {
    result.radius =
        io::positive_length(body, "radius", Need::required, "the body radius r in metres, > 0");
  } else if (has_footprint) {
    result.footprint = read_footprint(body);
    for (const model::Vec2& vertex : result.footprint)
      result.radius = std::max(result.radius, vertex.norm());
  }
  body.text("note", Need::optional);
  body.reject_unknown_keys();
  return result;
}

namespace {

// Frames a pose may be given in (REP-103): a body frame (x forward along the optical axis)
// or a camera optical frame (z forward, x right, y down).
enum class PoseFrame { automatic, body, optical };

PoseFrame read_frame(MapReader& pose) {
  const auto frame = pose.choice("frame", Need::optional, {"body", "optical"});
  if (!frame) return PoseFrame::automatic;
  return *frame == 0 ? PoseFrame::body : PoseFrame::optical;
}

// The links of a pose map, comma-separated, for "one of: ..." messages.
std::string link_names(const std::map<std::string, model::Pose3>& poses) {
  std::vector<std::string> names;
  for (const auto& [name, T] : poses) names.push_back(name);
  return model::join(names);
}

// "up", "down" or "level at azimuth A deg" for a unit vector in the robot frame.
std::string describe_direction(const model::Vec3& v) {
  if (v.z() > 0.7) return "up";
  if (v.z() < -0.7) return "down";
  return "level at azimuth " +
         model::format_number(std::round(model::rad_to_deg(std::atan2(v.y(), v.x()))) + 0.0) +
         " deg";
}

// Flags a link used in the other convention than its axes suggest: an optical frame's z
// (its optical axis) is near horizontal and its y points down; a body frame's x is the axis.
void check_link_convention(MapReader& pose, const std::string& link, const model::Pose3& T,
                           bool as_optical, bool named_optical) {
  constexpr double kNearly = 0.9;  // cosine: within about 25 degrees
  const model::Vec3 x = T.linear().col(0);
  const model::Vec3 y = T.linear().col(1);
  const model::Vec3 z = T.linear().col(2);
  if (as_optical && named_optical && std::abs(z.z()) > kNearly && std::abs(x.z()) < 1 - kNearly) {
    pose.diagnostics().warning(
        pose.location("urdf_link"), pose.field("urdf_link"),
        "'" + link +
            "' is named as an optical frame, but its z axis (the optical axis there) "
            "points " +
            (z.z() > 0 ? "up" : "down") +
            " while its x axis is level: it looks like a "
            "body frame (x forward)",
        "frame: body if the link is x-forward, or the camera's *_optical_frame link");
  }
  if (!as_optical && y.z() < -kNearly && std::abs(z.z()) < 1 - kNearly) {
    pose.diagnostics().warning(
        pose.location("urdf_link"), pose.field("urdf_link"),
        "'" + link +
            "' is used as a body frame (x forward), but its axes look like a camera "
            "optical frame (z level, y down): the sensor would look along its x axis, " +
            describe_direction(x) + " instead of along z, " + describe_direction(z),
        "frame: optical, or the camera's x-forward link");
  }
}

}  // namespace

std::string read_housing(MapReader& pose, const MountLink& link, const model::DescribedRobot& robot,
                         bool robot_loaded) {
  if (link.housing.empty()) return model::housing_link(robot, link.name);
  if (!robot_loaded) return "";
  const std::string refusal = model::housing_refusal(robot, link.housing);
  pose.require(refusal.empty(), "housing", "'" + link.housing + "' " + refusal,
               "a description link with collision geometry that is one sensor's own housing");
  return link.housing;
}

model::Pose3 read_pose(MapReader& pose, const std::optional<RobotLinks>& robot, MountLink* used) {
  // The sensor frame rigdesign mounts by is x-forward; an optical-frame pose is turned into it.
  const model::Pose3 T_optical_sensor = model::T_sensor_optical().inverse();
  if (pose.has("urdf_link")) {
    const std::string link =
        pose.text("urdf_link", Need::required, "a link name of the robot description").value_or("");
    pose.require(!pose.has("xyz") && !pose.has("rpy_deg"), "urdf_link", "given together with xyz",
                 "either urdf_link or xyz/rpy_deg");
    const PoseFrame frame = read_frame(pose);
    pose.reject_unknown_keys();
    if (robot && robot->failed) return model::Pose3::Identity();
    if (!robot) {
      pose.require(false, "urdf_link", "needs the rig's `robot` (or `urdf`) description",
                   "a rig with `robot: {description: robot.urdf.xacro}`");
      return model::Pose3::Identity();
    }
    if (const auto it = robot->T_base_link.find(link); it != robot->T_base_link.end()) {
      // REP-103 names a camera's z-forward frame *_optical_frame; such a link is optical
      // unless the rig says otherwise.
      const bool named_optical = link.find("optical") != std::string::npos;
      const bool as_optical =
          frame == PoseFrame::optical || (frame == PoseFrame::automatic && named_optical);
      check_link_convention(pose, link, it->second, as_optical, named_optical);
      if (used) *used = {link, as_optical, ""};
      return as_optical ? it->second * T_optical_sensor : it->second;
    }
    std::vector<std::string> names;
    for (const auto& [name, T] : robot->T_base_link) names.push_back(name);
    const std::string closest = model::closest_name(link, names);
    pose.require(false, "urdf_link",
                 "no link '" + link + "' in the URDF" +
                     (closest.empty() ? std::string() : " (did you mean '" + closest + "'?)"),
                 "one of: " + link_names(robot->T_base_link));
    return model::Pose3::Identity();
  }
  const PoseFrame frame = read_frame(pose);
  const model::Pose3 T = xyz_rpy_deg_pose(pose, Need::required);
  if (pose.has("housing") && used) {
    used->housing =
        pose.text("housing", Need::required, "a link of the robot description").value_or("");
    pose.require(robot.has_value(), "housing", "needs the rig's `robot` description",
                 "a rig with `robot: {description: robot.urdf.xacro}`");
  }
  pose.reject_unknown_keys();
  return frame == PoseFrame::optical ? T * T_optical_sensor : T;
}

namespace {

RobotLinks failed_links() {
  RobotLinks links;
  links.failed = true;
  return links;
}

std::map<std::string, std::string> read_text_map(
    MapReader& reader, const std::string& key, const std::string& expected,
    const std::function<std::optional<std::string>(const std::string&)>& refused_key = {}) {
  std::map<std::string, std::string> values;
  const YAML::Node node = reader.node(key);
  if (!node.IsDefined() || node.IsNull()) return values;
  if (!node.IsMap()) {
    reader.require(false, key, "is not a map", expected);
    return values;
  }
  for (const auto& entry : node) {
    if (!entry.first.IsScalar()) {  // a map or list used as a key (`{a: 1}: x`)
      reader.diagnostics().error(location_of(entry.first, reader.file()), reader.field(key),
                                 "has a key that is not a single value", expected);
      continue;
    }
    if (!entry.second.IsScalar()) {
      reader.diagnostics().error(location_of(entry.second, reader.file()),
                                 reader.field(key) + "." + entry.first.as<std::string>(),
                                 "is not a single value", expected);
      continue;
    }
    const std::string name = entry.first.as<std::string>();
    if (refused_key) {
      if (const auto why = refused_key(name)) {
        reader.diagnostics().error(location_of(entry.first, reader.file()),
                                   reader.field(key) + "." + name, *why, expected);
        continue;
      }
    }
    values[name] = entry.second.as<std::string>();
  }
  return values;
}

std::vector<std::string> read_folders(MapReader& reader, const std::string& key,
                                      const std::string& file) {
  std::vector<std::string> folders;
  const YAML::Node node = reader.node(key);
  if (!node.IsDefined() || node.IsNull()) return folders;
  const std::string expected = "a list of folders, relative to the rig file";
  if (!node.IsSequence()) {
    reader.require(false, key, "is not a list", expected);
    return folders;
  }
  for (std::size_t i = 0; i < node.size(); ++i) {
    if (!node[i].IsScalar()) {
      reader.diagnostics().error(location_of(node[i], reader.file()),
                                 reader.field(key) + "[" + std::to_string(i) + "]",
                                 "is not a folder name", expected);
      continue;
    }
    folders.push_back(resolve_beside(file, node[i].as<std::string>()));
  }
  return folders;
}

// Poses of every link in the frame of `base` (checked to be a link, reported at `base_at`).
std::optional<RobotLinks> links_of(model::RobotDescription description, std::string base,
                                   double base_height, const std::string& field, MapReader& reader,
                                   const std::string& base_key) {
  if (base.empty()) {
    base =
        description.T_root_link.count("base_footprint") ? "base_footprint" : description.root_link;
  }
  if (!description.T_root_link.count(base)) {
    const std::string names = link_names(description.T_root_link);
    reader.require(false, base_key, "no link '" + base + "' in " + description.file,
                   "one of: " + names);
    return failed_links();
  }
  for (const model::Diagnostic& warning : description.warnings) reader.diagnostics().add(warning);
  RobotLinks links;
  links.base_link = base;
  links.base_height = base_height;
  links.field = field;
  const model::Vec3 up(0.0, 0.0, base_height);
  for (const auto& [name, T] : description.T_root_link) {
    model::Pose3 T_robot_link = *description.T_base(base, name);
    T_robot_link.translation() += up;
    links.T_base_link[name] = T_robot_link;
  }
  links.link_where = description.link_where;
  links.joint_where = description.joint_where;
  links.parent_link = description.parent_link;
  links.description = std::move(description);
  return links;
}

std::optional<RobotLinks> read_legacy_urdf(MapReader& urdf, const std::string& file,
                                           const DescriptionReader& read_description) {
  const auto urdf_file = urdf.text("file", Need::required, "a URDF path relative to this file");
  const std::string base = urdf.text("base_link", Need::optional).value_or("");
  urdf.reject_unknown_keys();
  if (!urdf_file) return failed_links();
  RobotDescriptionRequest request;
  request.path = resolve_beside(file, *urdf_file);
  request.load_meshes = false;  // `urdf:` gives poses only; the body stays the rig's `body`
  request.expander = RobotDescriptionRequest::Expander::builtin;
  request.named_at = urdf.location("file");
  request.field = "urdf.file";
  std::optional<RobotLinks> links =
      links_of(read_description ? read_description(request) : load_robot_description(request), base,
               0.0, "urdf", urdf, "base_link");
  if (links) {
    links->description.reset();
    links->source = model::RobotSource{request.path, {}, {}, {}, base, 0.0, "builtin", true};
  }
  return links;
}

}  // namespace

std::optional<RobotLinks> read_robot_links(MapReader& top, const std::string& file,
                                           const DescriptionReader& read_description) {
  const bool has_robot = top.has("robot");
  top.require(!(has_robot && top.has("urdf")), "urdf", "given together with robot",
              "either robot (a description with its collision geometry) or urdf (poses only)");
  try {
    if (!has_robot) {
      auto urdf = top.map("urdf", Need::optional, "a map with file and base_link");
      return urdf ? read_legacy_urdf(*urdf, file, read_description) : std::nullopt;
    }
    auto robot = top.map("robot", Need::required,
                         "a map with description, and optionally args, env, package_paths, "
                         "base_link, expander");
    if (!robot) return failed_links();
    const auto description = robot->text("description", Need::required,
                                         "a .urdf or .urdf.xacro path relative to this file");
    RobotDescriptionRequest request;
    request.named_at = robot->location("description");
    request.args = read_text_map(*robot, "args", "a map of xacro argument names to values",
                                 refused_argument_name);
    request.environment = read_text_map(
        *robot, "env",
        "a map of the variables the description reads with $(optenv)/$(env) to values",
        refused_environment_name);
    request.package_paths = read_folders(*robot, "package_paths", file);
    const std::string base = robot->text("base_link", Need::optional).value_or("");
    const double base_height =
        robot->has("base_link_height")
            ? robot
                  ->number("base_link_height", Need::required,
                           "the base link's height above the floor in metres (default 0)")
                  .value_or(0.0)
            : 0.0;
    // Beyond +-100 m the height is another unit or a typo (and 1e300 + 0.4 m is 1e300 m:
    // every exported frame would lose its own height).
    robot->require(std::abs(base_height) <= 100.0, "base_link_height",
                   "is " + model::format_number(base_height) + " m",
                   "the base link's height above the floor in metres, within +-100 m");
    const auto expander = robot->choice("expander", Need::optional, {"auto", "builtin", "xacro"});
    if (expander) request.expander = static_cast<RobotDescriptionRequest::Expander>(*expander);
    robot->reject_unknown_keys();
    if (!description) return failed_links();
    request.path = resolve_beside(file, *description);
    std::optional<RobotLinks> links =
        links_of(read_description ? read_description(request) : load_robot_description(request),
                 base, base_height, "robot", *robot, "base_link");
    if (links && !links->failed) {
      static const char* const kExpanders[] = {"auto", "builtin", "xacro"};
      links->source = model::RobotSource{request.path,
                                         request.args,
                                         request.environment,
                                         request.package_paths,
                                         base,
                                         base_height,
                                         kExpanders[static_cast<int>(request.expander)],
                                         false};
    }
    return links;
  } catch (const model::InputError& error) {
    for (const model::Diagnostic& diagnostic : error.diagnostics())
      top.diagnostics().add(diagnostic);
    return failed_links();
  }
}

}  // namespace rigdesign::io
