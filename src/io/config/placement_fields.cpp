#include "io/config/placement_fields.hpp"

#include <algorithm>
#include <cmath>

#include "io/config/field_checks.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/rotation.hpp"
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
  const double area = model::signed_area(footprint);
  body.require(std::abs(area) > 1e-9, "footprint", "encloses no area",
               "vertices of a simple polygon around the robot's vertical axis");
  if (area < 0) std::reverse(footprint.begin(), footprint.end());
  return footprint;
}

}  // namespace

model::RobotBody read_body(MapReader& body) {
  model::RobotBody result;
  result.height = io::positive(body, "height", Need::required, "the body height h in metres, > 0");
  const bool has_radius = body.has("radius");
  const bool has_footprint = body.has("footprint");
  body.require(has_radius != has_footprint, "radius",
               has_radius ? "given together with footprint" : "missing",
               "either radius (a cylinder) or footprint (a prism), in metres");
  if (has_radius) {
    result.radius =
        io::positive(body, "radius", Need::required, "the body radius r in metres, > 0");
  } else if (has_footprint) {
    result.footprint = read_footprint(body);
    for (const model::Vec2& vertex : result.footprint)
      result.radius = std::max(result.radius, vertex.norm());
  }
  body.text("note", Need::optional);
  body.reject_unknown_keys();
  return result;
}

model::Pose3 read_pose(MapReader& pose, const std::optional<UrdfPoses>& urdf) {
  if (pose.has("urdf_link")) {
    const std::string link =
        pose.text("urdf_link", Need::required, "a URDF link name").value_or("");
    pose.require(!pose.has("xyz") && !pose.has("rpy_deg"), "urdf_link", "given together with xyz",
                 "either urdf_link or xyz/rpy_deg");
    pose.reject_unknown_keys();
    if (!urdf) {
      pose.require(false, "urdf_link", "needs the rig's top-level `urdf` (file, base_link)",
                   "a rig with `urdf: {file: robot.urdf}`");
      return model::Pose3::Identity();
    }
    if (const auto T_base_link = urdf->T_base(link)) return *T_base_link;
    std::string names;
    for (const std::string& name : urdf->link_names()) names += (names.empty() ? "" : ", ") + name;
    pose.require(false, "urdf_link", "no link '" + link + "' in the URDF", "one of: " + names);
    return model::Pose3::Identity();
  }
  const auto xyz = pose.numbers("xyz", Need::required, 3, 3, "[x, y, z] in metres, finite");
  const auto rpy = pose.numbers("rpy_deg", Need::optional, 3, 3,
                                "[roll, pitch, yaw] in degrees, finite (default [0, 0, 0])");
  pose.reject_unknown_keys();
  const model::Vec3 position =
      xyz ? model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]) : model::Vec3::Zero();
  model::Vec3 angles = model::Vec3::Zero();
  if (rpy)
    angles = model::Vec3(model::deg_to_rad((*rpy)[0]), model::deg_to_rad((*rpy)[1]),
                         model::deg_to_rad((*rpy)[2]));
  return model::pose_from_xyz_rpy(position, angles);
}

std::optional<UrdfPoses> read_urdf(MapReader& top, const std::string& file) {
  auto urdf = top.map("urdf", Need::optional, "a map with file and base_link");
  if (!urdf) return std::nullopt;
  const auto urdf_file = urdf->text("file", Need::required, "a URDF path relative to this file");
  const std::string base = urdf->text("base_link", Need::optional).value_or("");
  const model::SourceLocation file_at = urdf->location("file");
  const model::SourceLocation base_at = urdf->location("base_link");
  urdf->reject_unknown_keys();
  if (!urdf_file) return std::nullopt;
  try {
    return UrdfPoses::load(resolve_beside(file, *urdf_file), base, file_at, base_at);
  } catch (const model::InputError& error) {
    for (const model::Diagnostic& diagnostic : error.diagnostics())
      top.diagnostics().add(diagnostic);
    return std::nullopt;
  }
}

}  // namespace rigdesign::io
