#pragma once
/// The rig as Gazebo (gz sim) simulates it (issue 34): one `<sensor>` per mount with the
/// numbers of its mode, on the link the export gives the sensor, stamping the frame and
/// publishing the topic the nav2 source of the same mount names, so one name means one thing
/// in the URDF, nav2 and the simulator. Facts about SDFormat, gz-sensors and ros_gz_bridge
/// (element names, published topics, the frame id element) are cited in docs/gazebo.md.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/deploy/costmap_config.hpp"
#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/model/description_sensor.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

enum class GazeboSensorType { gpu_lidar, depth_camera };

struct GazeboSensor {
  std::string mount_id, sensor_id, mode_id;
  GazeboSensorType type = GazeboSensorType::gpu_lidar;
  /// The `<gazebo reference>`: the sensor's link (body axes: x forward, the way gz sensors
  /// look), and the sensor's pose in it (a rotation when that link is a camera's optical frame).
  std::string link;
  bool link_added =
      false;  ///< sensors.urdf.xacro adds `link` (prefixed), else the description has it
  model::Pose3 T_link_sensor = model::Pose3::Identity();
  /// simulated_frame's pose in the link: where the driver would broadcast it.
  model::Pose3 T_link_simulated = model::Pose3::Identity();
  /// gz-sensors' `gz_frame_id`: the frame the nav2 source's data is stamped with.
  std::string frame_id;
  bool frame_added = false;  ///< the export adds frame_id (prefixed), else the description has it
  /// A frame the sensor's driver broadcasts on the robot (so the URDF must not have it) that the
  /// simulation must supply: an optical frame at `link`'s origin. Empty: the URDF has frame_id.
  std::string simulated_frame;
  /// The ROS topic the driver publishes (the nav2 source's raw topic), which the bridge feeds.
  std::string ros_topic;
  /// gz `<topic>`. A gpu_lidar publishes LaserScan on it and its cloud on `<topic>/points`; a
  /// depth camera its depth image on it and its cloud on `<topic>/points`. A scan's topic is
  /// the ROS topic; a cloud's is the ROS topic without its `/points` ending where it has one,
  /// so the cloud keeps the ROS name in gz too.
  std::string topic;
  std::string gz_data_topic;  ///< what the bridge reads: the scan's topic or `<topic>/points`
  bool laser_scan = false;    ///< the ROS side wants LaserScan (2D scanners), else PointCloud2
  double update_rate = 0.0;   ///< [Hz] the mode's frequency
  // gpu_lidar: scan angles in the sensor frame [rad] and ray counts.
  int horizontal_samples = 0, vertical_samples = 1;
  double horizontal_min = 0.0, horizontal_max = 0.0;
  double vertical_min = 0.0, vertical_max = 0.0;
  // depth_camera: a pinhole camera; its vertical FOV follows from the image's aspect ratio.
  double horizontal_fov = 0.0;  ///< [rad]
  int width = 0, height = 0;
  double pinhole_vertical_fov = 0.0;  ///< [rad] what Gazebo will see (the datasheet's may differ)
  double range_min = 0.0, range_max = 0.0;  ///< [m] rays or clip planes
  /// Gaussian range noise: the mode's sigma(d) at the mount's distance of interest d (where the
  /// rig's resolution and noise are judged, paper 1), at most the mode's maximum range.
  double noise_stddev = 0.0;
  double noise_distance = 0.0;          ///< [m] the d above
  double datasheet_vertical_fov = 0.0;  ///< [rad] the mode's, for the file's comment
  /// The description's own sensor of this mount (gazebo_description_sensors.hpp): the export
  /// writes no second one and bridges this one's topic; the fields above stay the design's, and
  /// `differences` says what the description's sensor simulates otherwise.
  std::optional<model::DescriptionSensor> description_sensor;
  std::vector<std::string> differences;
};

/// One GazeboSensor per mount, in the rig's order; a mount the description already simulates
/// carries that sensor (`frames` and `costmap` hold one entry per
/// mount each, as plan_deployment makes them).
std::vector<GazeboSensor> gazebo_sensors(const model::Rig& rig, const SensorFrames& frames,
                                         const CostmapConfig& costmap,
                                         const model::SensorLibrary& library);

std::string to_string(GazeboSensorType type);

}  // namespace rigdesign::deploy
