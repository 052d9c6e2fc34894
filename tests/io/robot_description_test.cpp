// The bundled real robot descriptions (rigs/robots/), expanded by the built-in xacro
// expander: link poses and collision shapes against values worked out by hand from the
// xacro text (file and line of each number in the comments).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/model/optical_frame.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double kDescriptionPi = std::numbers::pi;

model::RobotDescription load(const std::string& description,
                             std::map<std::string, std::string> environment = {}) {
  io::RobotDescriptionRequest request;
  request.path = source_path("rigs/robots/" + description);
  request.package_paths = {source_path("rigs/robots")};
  request.environment = std::move(environment);
  request.expander = io::RobotDescriptionRequest::Expander::builtin;
  return io::load_robot_description(request);
}

void check_translation(const model::RobotDescription& robot, const std::string& base,
                       const std::string& link, const model::Vec3& expected) {
  INFO(link);
  const auto T = robot.T_base(base, link);
  REQUIRE(T);
  CHECK((T->translation() - expected).norm() < 1e-12);
}

}  // namespace

TEST_CASE("TurtleBot 4: link poses from the xacro text") {
  const model::RobotDescription robot =
      load("turtlebot4_description/urdf/standard/turtlebot4.urdf.xacro");
  // shell_link: z = shell_z_offset + base_link_z_offset (turtlebot4.urdf.xacro:46) with
  // shell_z_offset = 3 cm (:13) and base_link_z_offset = 6.42 cm (create3.urdf.xacro:53).
  const double shell_z = 0.03 + 0.0642;
  check_translation(robot, "base_link", "shell_link", {0, 0, shell_z});
  // rplidar_link on shell_link (:114-116): xyz (-4 cm, 0, 9.8715 cm) (:31-33), yaw pi/2.
  check_translation(robot, "base_link", "rplidar_link", {-0.04, 0, shell_z + 0.098715});
  const model::Mat3 yaw =
      Eigen::AngleAxisd(kDescriptionPi / 2, model::Vec3::UnitZ()).toRotationMatrix();
  CHECK(robot.T_base("base_link", "rplidar_link")->linear().isApprox(yaw, 1e-12));
  // oakd_camera_bracket on shell_link (:119-121, camera_bracket's default parent): (-11.8 cm,
  // 0, 5.257 cm) (:35-37); oakd_link on it (:123-125): (5.84 cm, 0, 9.676 cm) (:39-41); the
  // rgb frame at oakd_link (oakd.urdf.xacro, rgb_camera_joint origin 0).
  check_translation(robot, "base_link", "oakd_rgb_camera_frame",
                    {-0.118 + 0.0584, 0, shell_z + 0.05257 + 0.09676});
  // The optical frame: rpy (-pi/2, 0, -pi/2) under the rgb frame, REP-103's optical convention.
  const model::Pose3 T_rgb_optical =
      robot.T_base("oakd_rgb_camera_frame", "oakd_rgb_camera_optical_frame").value();
  CHECK(T_rgb_optical.linear().isApprox(model::T_sensor_optical().linear(), 1e-12));
  // front_left_tower_standoff on shell_link (:92-94): (3.063, 11.431, 14.757) cm (:23-24, :28);
  // its collision: a vertical cylinder r = 0.006 m, length 0.205 m (tower_standoff.urdf.xacro).
  check_translation(robot, "base_link", "front_left_tower_standoff",
                    {0.03063, 0.11431, shell_z + 0.14757});
  bool found = false;
  for (const model::CollisionShape& shape : robot.collisions) {
    if (shape.link != "front_left_tower_standoff") continue;
    found = true;
    CHECK(shape.kind == model::CollisionShape::Kind::cylinder);
    CHECK(shape.radius == 0.006);
    CHECK(shape.length == 0.205);
  }
  CHECK(found);
}

TEST_CASE("Jackal: default arguments and accessories chosen by environment variables") {
  const model::RobotDescription plain = load("jackal_description/urdf/jackal.urdf.xacro");
  // mid_mount at chassis_height = 0.184 (jackal.urdf.xacro:15, :229); front_mount
  // mount_spacing = 0.120 ahead of it (:19, :243); chassis_link at base_link (:97).
  check_translation(plain, "base_link", "front_mount", {0.12, 0, 0.184});
  check_translation(plain, "base_link", "rear_mount", {-0.12, 0, 0.184});
  CHECK(plain.T_root_link.count("front_laser") == 0);  // no accessory by default
  const model::RobotDescription equipped = load("jackal_description/urdf/jackal.urdf.xacro",
                                                {{"JACKAL_LASER", "1"}, {"JACKAL_LASER_3D", "1"}});
  CHECK(equipped.T_root_link.count("front_laser") == 1);
  CHECK(equipped.T_root_link.count("velodyne") == 1);
  // The LMS1xx on the upright bracket: front_laser_mount at front_mount, the scan frame
  // 0.149 m up (accessories/sick_lms1xx_upright_mount.urdf.xacro:57, the lms1xx macro names the
  // link "front_laser").
  check_translation(equipped, "base_link", "front_laser", {0.12, 0, 0.184 + 0.149});
  // The VLP-16 on its tower: the plate height:=0.1 above mid_mount
  // (accessories/vlp16_mount.urdf.xacro:91), the scan frame 0.0377 m above its base
  // (velodyne_description/urdf/VLP-16.urdf.xacro:38-39, name:=velodyne).
  check_translation(equipped, "base_link", "mid_vlp16_plate", {0, 0, 0.184 + 0.1});
  check_translation(equipped, "base_link", "velodyne", {0, 0, 0.184 + 0.1 + 0.0377});
}

TEST_CASE("a camera mounted by its optical frame looks where the x-forward frame looks") {
  TempFolder folder;
  const std::string head =
      "name: tb4\nrobot:\n  description: " +
      source_path("rigs/robots/turtlebot4_description/urdf/standard/turtlebot4.urdf.xacro") +
      "\n  package_paths: [" + source_path("rigs/robots") +
      "]\n  base_link: base_link\ndistance_of_interest: 2.0\nmounts:\n";
  const model::Rig rig = io::load_rig(
      folder.write("rig.yaml", head + "  - {id: body, sensor: oakd_pro, mode: depth_640x400_30, "
                                      "pose: {urdf_link: oakd_rgb_camera_frame}}\n"
                                      "  - {id: optical, sensor: oakd_pro, mode: depth_640x400_30, "
                                      "pose: {urdf_link: oakd_rgb_camera_optical_frame}}\n"));
  CHECK(rig.mounts[0].T_robot_sensor.isApprox(rig.mounts[1].T_robot_sensor, 1e-9));
  CHECK(rig.load_warnings.empty());
  SECTION("the optical link used as a body frame is flagged, naming the mount's field") {
    const CliResult result = run_cli(
        {"metrics",
         folder.write("wrong.yaml",
                      head + "  - {id: cam, sensor: oakd_pro, mode: depth_640x400_30, "
                             "pose: {urdf_link: oakd_rgb_camera_optical_frame, frame: body}}\n")});
    CHECK(result.exit_code == 0);
    CHECK(
        result.out.find(
            "mounts[0].pose.urdf_link: 'oakd_rgb_camera_optical_frame' is used as a body frame") !=
        std::string::npos);
  }
}

TEST_CASE("the requirements state the top of the area to perceive, over the rig's") {
  TempFolder folder;
  const std::string requirements =
      folder.write("needs.yaml", "name: low\narea_height: 0.15\nrange: {distance: 2.0}\n");
  const CliResult result =
      run_cli({"metrics", source_path("rigs/turtlebot4.yaml"), "--requirements", requirements});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 0);
  CHECK(result.out.find("z in [0, 0.15] m") != std::string::npos);
  // The rig says 0.2: the requirements win, and the report says so.
  CHECK(result.out.find("area_height: overrides the rig's area_height 0.2 m") != std::string::npos);
}
