#include "rigdesign/io/config/yaml_writers.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

// Enough digits that a pose read back equals the one written to well under a micrometre.
// Rounding residue (1e-31 deg of roll, -0) is written as 0.
std::string number(double value) {
  return model::format_number(std::abs(value) < 1e-12 ? 0.0 : value, 12);
}

// A cylinder or prism body (a rig without collision geometry).
void write_body(std::ostringstream& out, const model::RobotBody& body) {
  out << "body:\n  height: " << number(body.height) << '\n';
  if (body.footprint.empty()) {
    out << "  radius: " << number(body.radius) << '\n';
  } else {
    out << "  footprint: [";
    for (std::size_t i = 0; i < body.footprint.size(); ++i) {
      out << (i ? ", " : "") << '[' << number(body.footprint[i].x()) << ", "
          << number(body.footprint[i].y()) << ']';
    }
    out << "]\n";
  }
}

// The masts, brackets and plates that hold the sensors (issue 52 item 3), as rig files write
// them.
void write_supports(std::ostringstream& out, const std::vector<model::RigSupport>& supports) {
  if (supports.empty()) return;
  out << "supports:\n";
  for (const model::RigSupport& support : supports) {
    const model::HousingSolid& solid = support.solid;
    out << "  - {id: " << yaml_quoted(support.id)
        << ", shape: " << model::name_in(model::kHousingShapeNames, solid.shape);
    if (solid.shape == model::HousingShape::cylinder) {
      out << ", radius: " << number(solid.radius()) << ", height: " << number(solid.size.z());
    } else {
      out << ", size: [" << number(solid.size.x()) << ", " << number(solid.size.y()) << ", "
          << number(solid.size.z()) << "]";
    }
    const model::Vec3 xyz = support.T_robot_support.translation();
    const model::Vec3 rpy = model::rpy_from_rotation(support.T_robot_support.linear());
    out << ", pose: {xyz: [" << number(xyz.x()) << ", " << number(xyz.y()) << ", "
        << number(xyz.z()) << "], rpy_deg: [" << number(model::rad_to_deg(rpy.x())) << ", "
        << number(model::rad_to_deg(rpy.y())) << ", " << number(model::rad_to_deg(rpy.z())) << "]}";
    if (support.price > 0) out << ", price_usd: " << number(support.price);
    out << "}\n";
  }
}

// `path` as seen from `folder`.

void write_text_map(std::ostringstream& out, const char* key,
                    const std::map<std::string, std::string>& values) {
  if (values.empty()) return;
  out << "  " << key << ": {";
  bool first = true;
  for (const auto& [name, value] : values) {
    out << (first ? "" : ", ") << yaml_scalar(name) << ": " << yaml_quoted(value);
    first = false;
  }
  out << "}\n";
}

// The description as a rig names it: `robot:` (collision geometry) or a legacy `urdf:`.
void write_robot(std::ostringstream& out, const model::RobotSource& robot,
                 const std::string& folder) {
  if (robot.poses_only) {
    out << "urdf:\n  file: " << yaml_quoted(path_seen_from(robot.description, folder)) << '\n';
    if (!robot.base_link.empty()) out << "  base_link: " << yaml_quoted(robot.base_link) << '\n';
    return;
  }
  out << "robot:\n  description: " << yaml_quoted(path_seen_from(robot.description, folder))
      << '\n';
  write_text_map(out, "args", robot.args);
  write_text_map(out, "env", robot.environment);
  if (!robot.package_paths.empty()) {
    out << "  package_paths: [";
    for (std::size_t i = 0; i < robot.package_paths.size(); ++i)
      out << (i ? ", " : "") << yaml_quoted(path_seen_from(robot.package_paths[i], folder));
    out << "]\n";
  }
  if (!robot.base_link.empty()) out << "  base_link: " << yaml_quoted(robot.base_link) << '\n';
  out << "  base_link_height: " << number(robot.base_link_height) << '\n';
  out << "  expander: " << robot.expander << '\n';
}

}  // namespace

std::string path_seen_from(const std::string& path, const std::string& folder) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  const std::filesystem::path inside =
      absolute.lexically_relative(std::filesystem::absolute(folder).lexically_normal());
  if (inside.empty() || *inside.begin() == "..") return absolute.string();
  return inside.string();
}

std::string rig_to_yaml(const model::Rig& rig, const std::string& sensor_library,
                        const std::string& requirements, const std::string& comment,
                        const std::string& folder) {
  std::ostringstream out;
  out << yaml_comment(comment);
  out << "name: " << yaml_quoted(rig.name) << '\n';
  if (!sensor_library.empty()) out << "sensor_library: " << yaml_quoted(sensor_library) << '\n';
  if (!requirements.empty()) out << "requirements: " << yaml_quoted(requirements) << '\n';
  if (rig.robot) write_robot(out, *rig.robot, folder);
  if (rig.body.area_height) out << "area_height: " << number(*rig.body.area_height) << '\n';
  if (!rig.body.has_parts()) write_body(out, rig.body);
  out << "distance_of_interest: " << number(rig.distance_of_interest) << '\n';
  if (rig.tolerance) {
    const model::PoseTolerance& t = *rig.tolerance;
    out << "tolerance: {xyz: [" << number(t.xyz.x()) << ", " << number(t.xyz.y()) << ", "
        << number(t.xyz.z()) << "], rpy_deg: [" << number(model::rad_to_deg(t.rpy.x())) << ", "
        << number(model::rad_to_deg(t.rpy.y())) << ", " << number(model::rad_to_deg(t.rpy.z()))
        << "]}\n";
  }
  write_supports(out, rig.supports);
  out << "mounts:\n";
  for (const model::Mount& mount : rig.mounts) {
    out << "  - id: " << yaml_quoted(mount.id) << "\n    sensor: " << yaml_quoted(mount.sensor_id)
        << "\n    mode: " << yaml_quoted(mount.mode_id) << '\n';
    if (!mount.urdf_link.empty()) {
      out << "    pose: {urdf_link: " << yaml_quoted(mount.urdf_link)
          << ", frame: " << (mount.urdf_link_optical ? "optical" : "body") << "}\n";
    } else {
      const model::Vec3 xyz = mount.T_robot_sensor.translation();
      const model::Vec3 rpy = model::rpy_from_rotation(mount.T_robot_sensor.linear());
      out << "    pose: {xyz: [" << number(xyz.x()) << ", " << number(xyz.y()) << ", "
          << number(xyz.z()) << "], rpy_deg: [" << number(model::rad_to_deg(rpy.x())) << ", "
          << number(model::rad_to_deg(rpy.y())) << ", " << number(model::rad_to_deg(rpy.z())) << "]"
          << (mount.housing_link.empty() ? "" : ", housing: " + yaml_quoted(mount.housing_link))
          << "}\n";
    }
    if (mount.distance_of_interest) {
      out << "    distance_of_interest: " << number(*mount.distance_of_interest) << '\n';
    }
    if (mount.throttle_hz) out << "    throttle_hz: " << number(*mount.throttle_hz) << '\n';
    if (mount.recessed) out << "    recessed: true\n";
    // How the mount's driver runs, where the rig says it (namespace, topic, frame).
    std::string ros;
    for (const auto& [key, value] :
         {std::pair{"namespace", &mount.ros_namespace}, std::pair{"topic", &mount.ros_topic},
          std::pair{"frame", &mount.ros_frame}}) {
      if (!value->empty())
        ros += (ros.empty() ? "" : ", ") + std::string(key) + ": " + yaml_quoted(*value);
    }
    if (!ros.empty()) out << "    ros: {" << ros << "}\n";
  }
  return out.str();
}

std::string requirements_to_yaml(const model::Requirements& requirements,
                                 const std::string& comment) {
  std::ostringstream out;
  out << yaml_comment(comment);
  out << "name: " << yaml_quoted(requirements.name) << '\n';
  if (requirements.body_radius && requirements.body_height) {
    out << "body: {radius: " << number(*requirements.body_radius)
        << ", height: " << number(*requirements.body_height) << "}\n";
  }
  if (requirements.area_height) out << "area_height: " << number(*requirements.area_height) << '\n';
  if (!requirements.sectors.empty()) {
    out << "sectors:\n";
    for (const model::SectorRequirement& sector : requirements.sectors) {
      out << "  - {name: " << yaml_quoted(sector.name)
          << ", from_deg: " << number(model::rad_to_deg(sector.from))
          << ", to_deg: " << number(model::rad_to_deg(sector.to))
          << ", min_complete_coverage: " << number(sector.min_complete_coverage)
          << ", min_floor_coverage: " << number(sector.min_floor_coverage) << "}\n";
    }
  }
  out << "range: {distance: " << number(requirements.distance);
  if (requirements.min_frequency) out << ", min_frequency: " << number(*requirements.min_frequency);
  out << "}\n";
  if (requirements.object_dynamics) {
    out << "object_dynamics: {max_object_speed: " << number(requirements.object_dynamics->speed)
        << ", max_travel_between_frames: " << number(requirements.object_dynamics->travel) << "}\n";
  }
  if (requirements.robot_speed) {
    out << "robot_speed: {max_speed: " << number(requirements.robot_speed->speed)
        << ", max_travel_between_frames: " << number(requirements.robot_speed->travel) << "}\n";
  }
  if (requirements.smallest_obstacle) {
    out << "smallest_obstacle: {size: " << number(*requirements.smallest_obstacle) << "}\n";
  }
  if (requirements.max_noise)
    out << "accuracy: {max_noise: " << number(*requirements.max_noise) << "}\n";
  if (!requirements.lighting.empty()) {
    out << "lighting: [";
    for (std::size_t i = 0; i < requirements.lighting.size(); ++i) {
      out << (i ? ", " : "") << to_string(requirements.lighting[i]);
    }
    out << "]\n";
  }
  if (requirements.robustness && requirements.robustness->any()) {
    const model::RobustnessRequirement& robust = *requirements.robustness;
    std::vector<std::string> survive;
    if (robust.single_failure) survive.push_back("n-1");
    if (robust.condition) survive.push_back(to_string(*robust.condition));
    out << "robustness:\n  survive: [" << model::join(survive) << "]\n";
    if (!robust.sectors.empty()) {
      out << "  sectors:\n";
      for (const model::SectorRequirement& sector : robust.sectors) {
        out << "    - {name: " << yaml_quoted(sector.name)
            << ", min_complete_coverage: " << number(sector.min_complete_coverage)
            << ", min_floor_coverage: " << number(sector.min_floor_coverage) << "}\n";
      }
    }
  }
  return out.str();
}

// Declared in filtering_loads_io.hpp: the loads file is written here with the other YAML.
std::string filtering_loads_to_yaml(const model::FilteringLoads& loads,
                                    const std::string& comment) {
  std::ostringstream out;
  out << yaml_comment(comment);
  out << "machine: " << yaml_quoted(loads.machine) << '\n';
  out << "pipeline: " << yaml_quoted(loads.pipeline) << '\n';
  if (!loads.scene.empty()) out << "scene: " << yaml_quoted(loads.scene) << '\n';
  if (loads.frames > 0) out << "frames: " << loads.frames << '\n';
  out << "sensors:\n";
  for (const model::FilteringLoad& load : loads.sensors) {
    out << "  - sensor: " << yaml_quoted(load.sensor_id) << '\n';
    if (!load.mode_id.empty()) out << "    mode: " << yaml_quoted(load.mode_id) << '\n';
    out << "    seconds_per_point: " << model::format_number(load.seconds_per_point, 6) << '\n';
    out << "    points_per_frame: " << model::format_number(load.points_per_frame, 8) << '\n';
    out << "    median_seconds_per_frame: "
        << model::format_number(load.median_seconds_per_frame, 6) << '\n';
  }
  return out.str();
}

}  // namespace rigdesign::io
