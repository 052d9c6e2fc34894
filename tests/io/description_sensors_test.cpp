// Issue 52 item 5: the sensors a description declares for Gazebo, read from the expanded
// description. The expected values are the numbers written in the URDF text below.
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

const char* kUrdf = R"(<?xml version="1.0"?>
<robot name="probe">
  <link name="base_link"/>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed">
    <parent link="base_link"/><child link="laser"/><origin xyz="0.2 0 0.3" rpy="0 0 0"/>
  </joint>
  <gazebo reference="laser">
    <sensor name="front" type="gpu_lidar">
      <pose>0.01 0 0.02 0 0 1.5707963267948966</pose>
      <topic>front/scan</topic>
      <gz_frame_id>laser</gz_frame_id>
      <update_rate>15</update_rate>
      <lidar><scan><horizontal><samples>811</samples><min_angle>-2.356</min_angle>
        <max_angle>2.356</max_angle></horizontal></scan><range><min>0.05</min><max>25</max></range>
      </lidar>
    </sensor>
  </gazebo>
  <gazebo reference="base_link">
    <sensor name="bad" type="depth_camera">
      <pose>1 2</pose>
      <update_rate>fast</update_rate>
      <camera><horizontal_fov>1.2</horizontal_fov><image><width>64.5</width><height>48</height>
      </image></camera>
    </sensor>
  </gazebo>
  <gazebo reference="no_such_link"><sensor name="lost" type="camera"/></gazebo>
  <gazebo><plugin name="model_wide" filename="libx.so"/></gazebo>
</robot>
)";

}  // namespace

TEST_CASE("description sensors: every <sensor> of a <gazebo reference>, numbers as written",
          "[io]") {
  test::TempFolder folder;
  io::RobotDescriptionRequest request;
  request.path = folder.write("probe.urdf", kUrdf);
  const model::RobotDescription description = io::load_robot_description(request);
  REQUIRE(description.sensors.size() == 2);  // the one on an unknown link is not a link's
  const model::DescriptionSensor& front = description.sensors[0];
  CHECK(front.name == "front");
  CHECK(front.type == "gpu_lidar");
  CHECK(front.link == "laser");
  CHECK(front.topic == "front/scan");
  CHECK(front.frame_id == "laser");
  CHECK(front.update_rate == Approx(15));
  CHECK(front.horizontal_samples == 811);
  CHECK(front.horizontal_min == Approx(-2.356));
  CHECK(front.horizontal_max == Approx(2.356));
  CHECK(front.range_min == Approx(0.05));
  CHECK(front.range_max == Approx(25));
  CHECK(front.T_link_sensor.translation().isApprox(model::Vec3(0.01, 0, 0.02)));
  // yaw pi/2: the sensor's x is the link's y
  CHECK((front.T_link_sensor.linear() * model::Vec3::UnitX() - model::Vec3::UnitY()).norm() <
        1e-12);
  CHECK(front.where.line == 9);
  const model::DescriptionSensor& bad = description.sensors[1];
  CHECK(bad.T_link_sensor.isApprox(model::Pose3::Identity()));
  CHECK_FALSE(bad.update_rate);
  CHECK_FALSE(bad.width);  // 64.5 pixels
  CHECK(bad.height == 48);
  CHECK(bad.horizontal_fov == Approx(1.2));
  // Each unreadable number is a warning at its line, never an error.
  int warned = 0;
  for (const model::Diagnostic& warning : description.warnings) {
    if (warning.severity != model::Severity::warning) continue;
    if (warning.where.line == 21 && warning.field == "gazebo.sensor.pose") ++warned;
    if (warning.where.line == 22 && warning.field == "gazebo.sensor.update_rate") ++warned;
    if (warning.where.line == 23 && warning.field == "gazebo.sensor.width") ++warned;
  }
  CHECK(warned == 3);
}
