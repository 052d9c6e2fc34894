#include <filesystem>
#include <system_error>

#include "rigdesign/deploy/clearpath/clearpath_sensors.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/deploy/export/export_readme.hpp"
#include "rigdesign/deploy/gazebo/sensors_gazebo_writer.hpp"
#include "rigdesign/deploy/ros/description/sensors_xacro_writer.hpp"
#include "rigdesign/deploy/ros/nav2/collision_monitor_writer.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_launch_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_writer.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::deploy {

std::vector<std::string> write_deployment(const std::string& folder, const model::Rig& rig,
                                          const deploy::Deployment& deployment,
                                          const std::string& header) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw model::InputError(model::Diagnostic{model::SourceLocation{folder}, "output",
                                              "cannot create the folder: " + error.message(),
                                              "a writable folder"});
  }
  // The robot frame's link carries the crop boxes; it differs from the robot frame by its
  // height above the floor only.
  const model::Pose3 T_robot_base =
      deploy::robot_frame_pose(rig, rig.base_link).value_or(model::Pose3::Identity());
  std::vector<std::string> unmapped;
  const std::vector<ClearpathSensor> clearpath =
      clearpath_sensors_of(rig, deployment.frames, unmapped);
  std::vector<std::pair<std::string, std::string>> files = {
      {"sensors.urdf.xacro", sensors_xacro_text(deployment.frames, header)},
      {"nav2_costmap.yaml",
       nav2_costmap_text(
           deployment.costmap, header,
           deployment.stvl && !deployment.stvl->sources.empty() ? &*deployment.stvl : nullptr)},
      {"self_filters.yaml",
       self_filters_text(deployment.self_filters, rig.base_link, T_robot_base, header)},
      {"self_filters.launch.py",
       self_filters_launch_text(deployment.self_filters, deployment.costmap.sources,
                                "self_filters.yaml", header)},
      {"sensors.gazebo.xacro", sensors_gazebo_xacro_text(deployment.gazebo, header)},
      {"bridge.yaml", gz_bridge_yaml_text(deployment.gazebo, header)},
      {"clearpath_sensors.yaml", clearpath_sensors_text(clearpath, unmapped, header)}};
  if (deployment.collision_monitor) {
    files.emplace_back(
        "collision_monitor.yaml",
        collision_monitor_text(*deployment.collision_monitor, deployment.costmap, header));
  }
  std::vector<std::string> names;
  for (const auto& file : files) names.push_back(file.first);
  names.push_back("README.md");
  files.emplace_back("README.md", export_readme_text(rig, deployment, names, header));
  std::vector<std::string> written;
  for (const auto& [name, text] : files) {
    const std::string path = (std::filesystem::path(folder) / name).string();
    io::write_file_atomically(path, text);
    written.push_back(path);
  }
  return written;
}

}  // namespace rigdesign::deploy
