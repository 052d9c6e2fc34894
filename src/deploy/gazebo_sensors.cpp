#include "rigdesign/deploy/gazebo_sensors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "rigdesign/deploy/gazebo_description_sensors.hpp"
#include "rigdesign/model/optical_frame.hpp"

namespace rigdesign::deploy {
namespace {

// gz-sensors publishes a gpu_lidar's or depth camera's cloud on `<topic>` + this.
constexpr std::string_view kCloudSuffix = "/points";

// What the bridge reads from a sensor publishing on gz `topic`: gz-sensors publishes a lidar's
// scan on it, and a lidar's or camera's cloud on `topic`/points (docs/gazebo.md).
std::string gz_data_topic(const std::string& topic, bool laser_scan) {
  return laser_scan ? topic : topic + std::string(kCloudSuffix);
}

int ray_count(double fov, double spacing, bool wraps) {
  const int gaps = static_cast<int>(std::lround(fov / spacing));
  return wraps ? gaps : gaps + 1;
}

void plan_lidar(const model::SensorMode& mode, GazeboSensor& sensor) {
  sensor.type = GazeboSensorType::gpu_lidar;
  const double horizontal = mode.fov.horizontal();
  const bool wraps = mode.fov.full_turn();
  sensor.horizontal_samples = ray_count(horizontal, mode.angular_resolution_h, wraps);
  // A full turn of N rays spans N - 1 spacings, so its last ray stops one spacing short.
  const double span = wraps ? horizontal - mode.angular_resolution_h : horizontal;
  sensor.horizontal_min = -0.5 * horizontal;
  sensor.horizontal_max = sensor.horizontal_min + span;
  if (mode.angular_resolution_v) {
    sensor.vertical_samples = ray_count(mode.fov.vertical(), *mode.angular_resolution_v, false);
    sensor.vertical_min = mode.fov.elevation_min();
    sensor.vertical_max = mode.fov.elevation_max();
  }
}

void plan_camera(const model::SensorMode& mode, GazeboSensor& sensor) {
  sensor.type = GazeboSensorType::depth_camera;
  sensor.horizontal_fov = mode.fov.horizontal();
  sensor.width = static_cast<int>(std::lround(mode.fov.horizontal() / mode.angular_resolution_h));
  const double vertical_spacing = mode.angular_resolution_v.value_or(mode.angular_resolution_h);
  sensor.height = static_cast<int>(std::lround(mode.fov.vertical() / vertical_spacing));
  sensor.pinhole_vertical_fov =
      2.0 * std::atan(std::tan(0.5 * sensor.horizontal_fov) * sensor.height / sensor.width);
}

}  // namespace

std::string to_string(GazeboSensorType type) {
  return type == GazeboSensorType::gpu_lidar ? "gpu_lidar" : "depth_camera";
}

std::vector<GazeboSensor> gazebo_sensors(const model::Rig& rig, const SensorFrames& frames,
                                         const CostmapConfig& costmap,
                                         const model::SensorLibrary& library) {
  std::vector<GazeboSensor> sensors;
  for (std::size_t m = 0; m < frames.frames.size(); ++m) {
    const SensorFrame& frame = frames.frames[m];
    const SourceConfig& source = costmap.sources[m];
    const model::SensorMode& mode = library.resolved_mode(frame.sensor_id, frame.mode_id);
    GazeboSensor sensor;
    sensor.mount_id = frame.mount_id;
    sensor.sensor_id = frame.sensor_id;
    sensor.mode_id = frame.mode_id;
    sensor.link = frame.link;
    sensor.link_added = !frame.joint.empty();
    // gz sensors look along their frame's +x: on a link that is itself an optical frame (z
    // forward) the sensor is turned back to body axes.
    if (frame.optical_frame && *frame.optical_frame == frame.link)
      sensor.T_link_sensor.linear() = model::T_sensor_optical().linear().transpose();
    // A driver's root stands off the sensor (issue 52 item 4): the sensor keeps its pose.
    if (frame.data_frame_from_driver) sensor.T_link_sensor = frame.T_link_sensor;
    sensor.frame_id = source.sensor_frame;
    // Added by the export: the mount's optical frame, its new link, or (simulation only) the
    // frame its driver would broadcast.
    sensor.frame_added = frame.data_frame_from_driver ||
                         (frame.optical_frame && frame.data_frame == *frame.optical_frame
                              ? !frame.optical_joint.empty()
                              : sensor.link_added);
    if (frame.data_frame_from_driver) {
      sensor.simulated_frame = frame.data_frame;
      sensor.T_link_simulated = frame.T_link_data;
    }
    sensor.ros_topic = source.raw_topic;
    sensor.laser_scan = source.laser_scan;
    sensor.topic = source.raw_topic;
    if (!sensor.laser_scan && sensor.topic.ends_with(kCloudSuffix) &&
        sensor.topic.size() > kCloudSuffix.size())
      sensor.topic.resize(sensor.topic.size() - kCloudSuffix.size());
    sensor.gz_data_topic = gz_data_topic(sensor.topic, sensor.laser_scan);
    sensor.update_rate = mode.frequency;
    sensor.range_min = mode.min_range;
    sensor.range_max = mode.max_range;
    sensor.noise_distance = std::min(rig.distance_for(rig.mounts[m]), mode.max_range);
    sensor.noise_stddev = mode.noise.sigma(sensor.noise_distance);
    sensor.datasheet_vertical_fov = mode.fov.vertical();
    if (mode.is_camera()) {
      plan_camera(mode, sensor);
    } else {
      plan_lidar(mode, sensor);
    }
    sensor.description_sensor = description_sensor_of(rig, rig.mounts[m], library);
    if (sensor.description_sensor) {
      sensor.differences = description_sensor_differences(*sensor.description_sensor, sensor);
      // Without a <topic> gz names one after the world: the bridge cannot (empty).
      const std::string& topic = sensor.description_sensor->topic;
      sensor.gz_data_topic =
          topic.empty() ? std::string() : gz_data_topic(topic, sensor.laser_scan);
    }
    sensors.push_back(sensor);
  }
  return sensors;
}

}  // namespace rigdesign::deploy
