#pragma once
/// nav2 costmap parameters derived from a rig (issue 14): the footprint from the body, one
/// observation source per mount with its marking and clearing ranges and height band from the
/// sensor's mode, the area to perceive and the sensor's floor noise, the voxel column from the
/// area's height, the inflation from the body, and the memory of the rig's blind
/// sectors (deploy/blind_memory.hpp). Every value says where it came from (`why`), so the
/// exported file can explain itself.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/costmap/costmap.hpp"
#include "rigdesign/costmap/observation.hpp"
#include "rigdesign/deploy/blind_memory.hpp"
#include "rigdesign/model/requirements.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::deploy {

struct DeployOptions {
  std::string parent;  ///< sensor frames' parent link; empty: the base link
  /// Topic templates of 2D scanners and of 3D sensors ({mount}: the mount id); empty: each
  /// driver's topic (sensors.yaml `ros2`, under the mount's namespace when two mounts' drivers
  /// would share it), else /{mount}/scan and /{mount}/points. A mount's `ros` wins over both.
  std::string scan_topic;
  std::string cloud_topic;
  double update_rate = 5.0;  ///< [Hz] the local costmap's update_frequency (nav2's default)
  double max_speed = 0.0;    ///< [m/s] for the blind-gap memory rule; 0: the requirements' R5
  /// [m/s] the slowest the robot drives: nav2 Regulated Pure Pursuit's default
  /// regulated_linear_scaling_min_speed (0.25 m/s), or max_speed when that is lower.
  double min_speed = 0.25;
  double floor_flatness = 0.02;   ///< [m] steps and tiles a flat floor may have
  double floor_noise_sigmas = 6;  ///< floor returns this many sigma high still do not mark
  /// The class of a costmap layer implementing paper 1's Hit Layer, for a team that built one
  /// (`export --hit-layer-plugin`). Empty: no Hit Layer; the blind gaps are remembered by
  /// nav2's observation_persistence instead (deploy/blind_memory.hpp).
  std::string hit_layer_plugin;
  /// [m] how high the costmap's global frame (odom) stands above the floor: Clearpath's 2D
  /// EKF puts odom at base_link height. The file's height bands are written in that frame.
  double global_frame_height = 0.0;
  /// The 3D sensors' layer: nav2's voxel layer, or spatio_temporal_voxel_layer (`export
  /// --layer stvl`; 2D scanners stay in nav2's obstacle layer).
  bool stvl = false;
  /// The nav2 release the collision monitor's file is written for (humble or jazzy: they
  /// spell polygons differently), and the driver and filter time per frame [s] that sizes its
  /// zones (nothing: one frame period).
  std::string ros_distro = "jazzy";
  std::optional<double> processing_latency;
};

/// One observation source as nav2's obstacle and voxel layers read it.
struct SourceConfig {
  std::string mount_id;
  bool laser_scan = false;  ///< data_type LaserScan (2D scanners), else PointCloud2
  /// What the costmap subscribes to: the self-filter chain's output where the sensor sees
  /// its robot (plan_deployment), else the driver's topic `raw_topic`.
  std::string topic;
  std::string raw_topic;
  std::string topic_note;    ///< how the driver must run to publish raw_topic, if it differs
  std::string sensor_frame;  ///< the frame the driver stamps its data with
  costmap::ObservationSource source;
  /// [m] the largest height error of a floor return within the marking range (0: the sensor
  /// sees no floor there), from which min_obstacle_height follows.
  double floor_height_error = 0.0;
};

struct CostmapConfig {
  std::string robot_base_frame;        ///< the rig's base link
  std::vector<model::Vec2> footprint;  ///< counter-clockwise; empty: a round robot
  double robot_radius = 0.0;           ///< [m] circumscribed radius (nav2's robot_radius)
  double inscribed_radius = 0.0;       ///< [m]
  costmap::CostmapParams costmap;      ///< the local costmap (window, layers, Hit Layer, ...)
  std::vector<SourceConfig> sources;
  BlindMemory memory;              ///< how the memory's values were chosen
  std::string hit_layer_class;     ///< the Hit Layer's plugin class; empty: no Hit Layer
  std::vector<std::string> notes;  ///< derivations and warnings for the file's comments
  double update_rate = 5.0;        ///< [Hz] the local costmap's update_frequency
  /// What the derivations used, so the file's comments say it: sigma of a floor return's
  /// height above the floor flatness in min_obstacle_height, and the inflation margin [m]
  /// beyond the circumscribed radius.
  double floor_noise_sigmas = 0.0;
  double inflation_margin = 0.0;
  /// [m] the global frame's height above the floor: heights in `costmap` and `sources` are
  /// above the floor; the file says them in the global frame (minus this).
  double global_frame_height = 0.0;
};

/// Precondition: every mount's sensor and mode are in `library`. `requirements` may be null
/// (no R5 speed and no R6 check then).
CostmapConfig costmap_config(const model::Rig& rig, const model::SensorLibrary& library,
                             const model::Requirements* requirements, const DeployOptions& options);

/// `text` with every `{mount}` replaced by `mount_id`.
std::string expand_topic(const std::string& text, const std::string& mount_id);

}  // namespace rigdesign::deploy
