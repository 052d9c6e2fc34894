#include "rigdesign/deploy/gazebo/sensors_gazebo_writer.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "rigdesign/deploy/gazebo_description_sensors.hpp"
#include "rigdesign/io/emit/xml_emit.hpp"
#include "rigdesign/io/emit/yaml_emit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "rigdesign/model/rotation.hpp"

namespace rigdesign::deploy {
namespace {

// Exact, except that rounding residue below 1e-15 (and -0) is written as 0 for the reader.
std::string sdf_number(double value) {
  return model::exact_number(std::abs(value) < 1e-15 ? 0.0 : value);
}

std::string degrees_text(double radians) {
  return model::format_number(radians * 180.0 / std::numbers::pi, 4);
}

// A name the export adds carries the macro's prefix; a description's name is written as it is.
std::string name_in_macro(const std::string& name, bool added) {
  return added ? "${prefix}" + io::xacro_literal(name) : io::xacro_literal(name);
}

void write_gazebo_noise(const deploy::GazeboSensor& s, const std::string& indent,
                        std::ostream& out) {
  out << indent << "<noise>\n"
      << indent << "  <type>gaussian</type>\n"
      << indent << "  <mean>0</mean>\n"
      << indent << "  <stddev>" << sdf_number(s.noise_stddev) << "</stddev>\n"
      << indent << "</noise>\n";
}

void write_gazebo_lidar(const deploy::GazeboSensor& s, std::ostream& out) {
  out << "        <lidar>\n          <scan>\n"
      << "            <horizontal>\n"
      << "              <samples>" << s.horizontal_samples << "</samples>\n"
      << "              <resolution>1</resolution>\n"
      << "              <min_angle>" << sdf_number(s.horizontal_min) << "</min_angle>\n"
      << "              <max_angle>" << sdf_number(s.horizontal_max) << "</max_angle>\n"
      << "            </horizontal>\n";
  if (s.vertical_samples > 1) {
    out << "            <vertical>\n"
        << "              <samples>" << s.vertical_samples << "</samples>\n"
        << "              <resolution>1</resolution>\n"
        << "              <min_angle>" << sdf_number(s.vertical_min) << "</min_angle>\n"
        << "              <max_angle>" << sdf_number(s.vertical_max) << "</max_angle>\n"
        << "            </vertical>\n";
  }
  out << "          </scan>\n"
      << "          <range>\n"
      << "            <min>" << sdf_number(s.range_min) << "</min>\n"
      << "            <max>" << sdf_number(s.range_max) << "</max>\n"
      << "          </range>\n";
  write_gazebo_noise(s, "          ", out);
  out << "        </lidar>\n";
}

void write_gazebo_camera(const deploy::GazeboSensor& s, std::ostream& out) {
  out << "        <camera>\n"
      << "          <horizontal_fov>" << sdf_number(s.horizontal_fov) << "</horizontal_fov>\n"
      << "          <image>\n"
      << "            <width>" << s.width << "</width>\n"
      << "            <height>" << s.height << "</height>\n"
      << "            <format>R_FLOAT32</format>\n"
      << "          </image>\n"
      << "          <clip>\n"
      << "            <near>" << sdf_number(s.range_min) << "</near>\n"
      << "            <far>" << sdf_number(s.range_max) << "</far>\n"
      << "          </clip>\n";
  write_gazebo_noise(s, "          ", out);
  out << "        </camera>\n";
}

// The frame a driver broadcasts on the robot, which the simulation has to supply: an optical
// frame at the sensor link's origin.
void write_simulated_frame(const deploy::GazeboSensor& s, std::ostream& out) {
  const model::Vec3 rpy = model::rpy_from_rotation(s.T_link_simulated.linear());
  const model::Vec3 xyz = s.T_link_simulated.translation();
  const std::string frame = "${prefix}" + io::xacro_literal(s.simulated_frame);
  out << "    <link name=\"" << frame << "\"/>\n"
      << "    <joint name=\"" << frame << "_sim_joint\" type=\"fixed\">\n"
      << "      <parent link=\"" << name_in_macro(s.link, s.link_added) << "\"/>\n"
      << "      <child link=\"" << frame << "\"/>\n"
      << "      <origin xyz=\"" << sdf_number(xyz.x()) << " " << sdf_number(xyz.y()) << " "
      << sdf_number(xyz.z()) << "\" rpy=\"" << sdf_number(rpy.x()) << " " << sdf_number(rpy.y())
      << " " << sdf_number(rpy.z()) << "\"/>\n"
      << "    </joint>\n";
}

// A mount the description already simulates: no second sensor, a comment saying whose it is.
void write_description_sensor(const deploy::GazeboSensor& s, std::ostream& out) {
  const model::DescriptionSensor& own = *s.description_sensor;
  std::string what = s.mount_id + ": the description's own sensor '" + own.name + "' (" + own.type +
                     ", " + model::to_string(own.where) + ") simulates it; none is added beside it";
  what += s.differences.empty() ? "; it simulates the design" : "; it differs:";
  out << "    <!-- " << io::xml_comment_line(what) << " -->\n";
  for (const std::string& difference : s.differences)
    out << "    <!--   " << io::xml_comment_line(difference) << " -->\n";
}

void write_gazebo_sensor(const deploy::GazeboSensor& s, std::ostream& out) {
  if (s.description_sensor) return write_description_sensor(s, out);
  const bool lidar = s.type == deploy::GazeboSensorType::gpu_lidar;
  std::ostringstream what;
  what << s.mount_id << ": " << s.sensor_id << ", mode " << s.mode_id << "; noise sigma("
       << sdf_number(s.noise_distance) << " m) = " << sdf_number(s.noise_stddev)
       << " m at the distance of interest";
  if (!lidar) {
    what << "; pinhole vertical FOV " << degrees_text(s.pinhole_vertical_fov) << " deg (datasheet "
         << degrees_text(s.datasheet_vertical_fov) << " deg)";
  }
  out << "    <!-- " << io::xml_comment_line(what.str()) << " -->\n";
  if (!s.simulated_frame.empty()) {
    out << "    <!-- "
        << io::xml_comment_line(s.simulated_frame +
                                ": the driver broadcasts it on the robot; the simulation adds it")
        << " -->\n";
    write_simulated_frame(s, out);
  }
  out << "    <gazebo reference=\"" << name_in_macro(s.link, s.link_added) << "\">\n"
      << "      <sensor name=\"" << io::xacro_literal(s.mount_id) << "\" type=\""
      << to_string(s.type) << "\">\n";
  if (!s.T_link_sensor.isApprox(model::Pose3::Identity())) {
    const model::Vec3 rpy = model::rpy_from_rotation(s.T_link_sensor.linear());
    const model::Vec3 xyz = s.T_link_sensor.translation();
    out << "        <pose>" << sdf_number(xyz.x()) << " " << sdf_number(xyz.y()) << " "
        << sdf_number(xyz.z()) << " " << sdf_number(rpy.x()) << " " << sdf_number(rpy.y()) << " "
        << sdf_number(rpy.z()) << "</pose>\n";
  }
  out << "        <always_on>true</always_on>\n"
      << "        <update_rate>" << sdf_number(s.update_rate) << "</update_rate>\n"
      << "        <topic>" << io::xacro_literal(s.topic) << "</topic>\n"
      << "        <gz_frame_id>" << name_in_macro(s.frame_id, s.frame_added) << "</gz_frame_id>\n";
  if (lidar) {
    write_gazebo_lidar(s, out);
  } else {
    write_gazebo_camera(s, out);
  }
  out << "      </sensor>\n    </gazebo>\n";
}

}  // namespace

std::string sensors_gazebo_xacro_text(const std::vector<deploy::GazeboSensor>& sensors,
                                      const std::string& header) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<!--\n";
  out << io::xml_comment_lines(header, "  ");
  out << "  Simulation only: <xacro:include filename=\"sensors.gazebo.xacro\"/>\n"
         "  <xacro:rig_gazebo_sensors/> beside sensors.urdf.xacro's <xacro:rig_sensors/> (same\n"
         "  prefix). gz sim renders the sensors with its Sensors system (gz-sim-sensors-system,\n"
         "  render_engine ogre2). A scan is published on <topic>, the ROS topic nav2 reads; a\n"
         "  cloud on <topic>/points (the ROS topic, where that ends in /points); bridge.yaml\n"
         "  brings each to the ROS topic of its driver. gz_frame_id stamps the\n"
         "  frame nav2 and TF know (gz-sensors 8 / Harmonic, 7.1+ / Garden, 6.8+ / Fortress;\n"
         "  without it the data is stamped model/link/sensor). A sensor on a link the URDF\n"
         "  joins by a fixed joint is moved to the parent link by the URDF-to-SDF conversion,\n"
         "  its pose kept.\n"
         "-->\n";
  out << "<robot xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n";
  out << "  <xacro:macro name=\"rig_gazebo_sensors\" params=\"prefix:=${''}\">\n";
  for (const deploy::GazeboSensor& sensor : sensors) write_gazebo_sensor(sensor, out);
  out << "  </xacro:macro>\n</robot>\n";
  return out.str();
}

std::string gz_bridge_yaml_text(const std::vector<deploy::GazeboSensor>& sensors,
                                const std::string& header) {
  std::ostringstream out;
  out << io::yaml_comment(header);
  out << io::yaml_comment(
      "ros_gz_bridge: ros2 run ros_gz_bridge parameter_bridge --ros-args -p "
      "config_file:=bridge.yaml. One entry per sensor of sensors.gazebo.xacro, from gz sim to "
      "the topic nav2's source reads (scans as gz publishes them, clouds from <topic>/points), "
      "then the simulation clock, which nodes with use_sim_time:=true wait for.");
  for (const deploy::GazeboSensor& s : sensors) {
    if (s.gz_data_topic.empty()) {
      out << io::yaml_comment(
          s.mount_id + ": the description's sensor '" + s.description_sensor->name +
          "' sets no <topic>; gz sim names it after the world and the model (" +
          deploy::gz_scoped_topic(s.description_sensor->name) + "): add its entry for your world");
      continue;
    }
    const bool scan = s.type == deploy::GazeboSensorType::gpu_lidar && s.laser_scan;
    out << "- ros_topic_name: " << io::yaml_quoted(s.ros_topic) << "\n"
        << "  gz_topic_name: " << io::yaml_quoted(s.gz_data_topic) << "\n"
        << "  ros_type_name: "
        << (scan ? "sensor_msgs/msg/LaserScan" : "sensor_msgs/msg/PointCloud2") << "\n"
        << "  gz_type_name: " << (scan ? "gz.msgs.LaserScan" : "gz.msgs.PointCloudPacked") << "\n"
        << "  direction: GZ_TO_ROS\n";
  }
  out << "- ros_topic_name: \"/clock\"\n"
      << "  gz_topic_name: \"/clock\"\n"
      << "  ros_type_name: rosgraph_msgs/msg/Clock\n"
      << "  gz_type_name: gz.msgs.Clock\n"
      << "  direction: GZ_TO_ROS\n";
  return out.str();
}

}  // namespace rigdesign::deploy
