#include "rigdesign/deploy/export/export_readme.hpp"

#include <map>
#include <sstream>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::deploy {
namespace {

std::string metres(double value) {
  return model::format_number(value, 3);
}

// What each file is for, by name.
const std::map<std::string, std::string>& file_purposes() {
  static const std::map<std::string, std::string> purposes = {
      {"sensors.urdf.xacro", "the sensors' links and joints, included by the robot's xacro"},
      {"nav2_costmap.yaml", "nav2 local and global costmap parameters (controller and planner)"},
      {"collision_monitor.yaml", "nav2 collision_monitor parameters: stop and slowdown zones"},
      {"self_filters.yaml", "laser_filters and pcl_ros chains that drop the robot's own returns"},
      {"self_filters.launch.py", "launches those chains"},
      {"sensors.gazebo.xacro", "gz sim sensors on the same links, frames and topics"},
      {"bridge.yaml", "ros_gz_bridge: the simulated sensors onto the ROS topics"},
      {"clearpath_sensors.yaml", "the rig as a Clearpath robot.yaml `sensors:` section"},
      {"README.md", "this file"},
  };
  return purposes;
}

std::string layer_of(const deploy::Deployment& deployment, const deploy::SourceConfig& source) {
  if (deployment.stvl && !source.laser_scan) return "stvl_layer";
  return deployment.costmap.costmap.layer == costmap::ObstacleLayerKind::voxel ? "voxel_layer"
                                                                               : "obstacle_layer";
}

std::string clears(const deploy::Deployment& deployment, std::size_t m) {
  const deploy::SourceConfig& source = deployment.costmap.sources[m];
  if (deployment.stvl && !source.laser_scan) {
    for (const deploy::StvlSource& s : deployment.stvl->sources) {
      if (s.source != m) continue;
      if (!(s.vertical_fov > 0.0)) return "no (no vertical FOV to clear with)";
      return std::string(s.model == deploy::StvlModel::depth_camera ? "depth frustum "
                                                                    : "lidar band ") +
             metres(s.min_z) + ".." + metres(s.max_z) + " m";
    }
  }
  const costmap::ObservationSource& s = source.source;
  if (!s.clearing) return "no";
  return "rays " + metres(s.raytrace_min_range) + ".." + metres(s.raytrace_max_range) + " m";
}

std::string feeds(const deploy::Deployment& deployment, std::size_t m) {
  if (!deployment.collision_monitor) return "no monitor (no speed)";
  const deploy::CollisionMonitor& monitor = *deployment.collision_monitor;
  std::string text;
  for (const deploy::ProtectiveZone& zone : monitor.zones) {
    for (const std::size_t s : zone.sources) {
      if (monitor.sources[s].source != m) continue;
      text += (text.empty() ? "" : ", ") + zone.name + " (sees " +
              metres(zone.visibility.seen_boundary[s]) + " of " +
              metres(zone.visibility.checked_boundary) + " m of edge)";
    }
  }
  return text.empty() ? "none: sees no zone" : text;
}

}  // namespace

std::string visibility_table(const deploy::Deployment& deployment) {
  std::ostringstream out;
  out << "| mount | frame | topic | marks in | marks (range, heights above the floor) | clears "
         "| collision monitor | Gazebo |\n"
         "|---|---|---|---|---|---|---|---|\n";
  for (std::size_t m = 0; m < deployment.costmap.sources.size(); ++m) {
    const deploy::SourceConfig& source = deployment.costmap.sources[m];
    const costmap::ObservationSource& s = source.source;
    out << "| " << source.mount_id << " | " << source.sensor_frame << " | " << source.topic << " | "
        << layer_of(deployment, source) << " | "
        << (s.marking
                ? metres(s.obstacle_min_range) + ".." + metres(s.obstacle_max_range) + " m, " +
                      metres(s.min_obstacle_height) + ".." + metres(s.max_obstacle_height) + " m"
                : "no")
        << " | " << clears(deployment, m) << " | " << feeds(deployment, m) << " | ";
    if (m < deployment.gazebo.size()) {
      const deploy::GazeboSensor& g = deployment.gazebo[m];
      if (g.description_sensor) {
        out << "the description's " << g.description_sensor->type << " '"
            << g.description_sensor->name << "'"
            << (g.gz_data_topic.empty() ? std::string() : " on " + g.gz_data_topic)
            << (g.differences.empty() ? "" : " (differs: see below)");
      } else {
        out << deploy::to_string(g.type) << " on " << g.gz_data_topic;
      }
    }
    out << " |\n";
  }
  return out.str();
}

namespace {

// The mounts the description's own sensors simulate, and how those differ from the design.
std::string description_sensor_notes(const deploy::Deployment& deployment) {
  std::ostringstream out;
  for (const deploy::GazeboSensor& g : deployment.gazebo) {
    if (g.differences.empty()) continue;
    out << "\n"
        << g.mount_id << " in Gazebo: the description's sensor '" << g.description_sensor->name
        << "' (" << model::to_string(g.description_sensor->where) << ") differs from the design:";
    for (const std::string& difference : g.differences) out << "\n- " << difference;
    out << "\n";
  }
  return out.str();
}

}  // namespace

std::string export_readme_text(const model::Rig& rig, const deploy::Deployment& deployment,
                               const std::vector<std::string>& file_names,
                               const std::string& header) {
  std::ostringstream out;
  out << "# " << rig.name << ": ROS 2 configuration\n\n" << header << "\n\n## Files\n\n";
  for (const std::string& name : file_names) {
    const auto purpose = file_purposes().find(name);
    out << "- `" << name << "`" << (purpose == file_purposes().end() ? "" : ": " + purpose->second)
        << '\n';
  }
  out << "\n## What each layer does with each sensor\n\n"
      << visibility_table(deployment) << description_sensor_notes(deployment);
  if (deployment.collision_monitor) {
    const deploy::CollisionMonitor& monitor = *deployment.collision_monitor;
    out << "\n## Collision monitor\n\n";
    for (const deploy::ProtectiveZone& zone : monitor.zones) {
      out << "- `" << zone.name << "` (" << zone.action << "): " << zone.sizing << ".";
      if (zone.visibility.unseen.empty()) {
        out << " Every point of its edge outside the robot is seen.\n";
        continue;
      }
      out << " Seen by no source:";
      for (const deploy::BoundaryArc& arc : zone.visibility.unseen) {
        out << " " << metres(arc.length) << " m from (" << metres(arc.from.x()) << ", "
            << metres(arc.from.y()) << ") to (" << metres(arc.to.x()) << ", " << metres(arc.to.y())
            << ");";
      }
      out << '\n';
    }
    out << "\nDeceleration " << metres(monitor.deceleration)
        << " m/s^2: " << monitor.deceleration_from << ".\n";
    out << "Check the deployed file with `rigdesign check " << rig.file
        << " --collision-monitor collision_monitor.yaml`.\n";
  }
  return out.str();
}

}  // namespace rigdesign::deploy
