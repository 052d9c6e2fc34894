#pragma once
/// A `<sensor>` a robot description already declares for the simulator, inside a
/// `<gazebo reference="link">` element (issue 52 item 5). Where it sits inside a mount's
/// housing it is that mount's sensor: the Gazebo export configures the simulation around it
/// instead of adding a second sensor, which libsdformat would refuse by name or Gazebo would
/// run twice. Only what the export compares with the design is kept.
#include <optional>
#include <string>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

struct DescriptionSensor {
  std::string name;
  std::string type;  ///< as written: ray, gpu_ray, gpu_lidar, lidar, depth_camera, rgbd_camera...
  std::string link;  ///< its `<gazebo reference>`
  Pose3 T_link_sensor = Pose3::Identity();  ///< its `<pose>` (x y z roll pitch yaw) in the link
  std::string topic;     ///< its gz `<topic>`; empty: gz sim names one after the world and model
  std::string frame_id;  ///< gz_frame_id, ignition_frame_id or a camera's optical_frame_id
  std::optional<double> update_rate;  ///< [Hz]
  std::optional<int> horizontal_samples;
  std::optional<double> horizontal_min, horizontal_max;  ///< [rad] a lidar's scan
  std::optional<double> horizontal_fov;                  ///< [rad] a camera's
  std::optional<int> width, height;                      ///< a camera's image [px]
  std::optional<double> range_min, range_max;            ///< [m] rays, or clip planes
  SourceLocation where;                                  ///< the `<sensor>` element
};

}  // namespace rigdesign::model
