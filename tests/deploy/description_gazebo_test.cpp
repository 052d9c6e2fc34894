// Issue 52 item 5: every bundled robot description, expanded with its accessories as the rig
// enables them, together with the exported sensors.urdf.xacro and sensors.gazebo.xacro, read
// by Gazebo's own parser (Debian's libsdformat 12): no errors, and exactly one sensor in each
// mount's housing. The housing test and the pose arithmetic are written here, apart from the
// export's; the poses are libsdformat's, resolved by it into the model frame.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sdf/Link.hh>
#include <sdf/Model.hh>
#include <sdf/Root.hh>
#include <sdf/Sensor.hh>
#include <sstream>

#include "io/robot/package_locator.hpp"
#include "io/robot/xacro_expander.hpp"
#include "io/robot/xml_tree.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using test::source_path;

namespace {

model::Pose3 to_pose(const ignition::math::Pose3d& p) {
  model::Pose3 T = model::Pose3::Identity();
  T.translation() = model::Vec3(p.Pos().X(), p.Pos().Y(), p.Pos().Z());
  T.linear() = Eigen::Quaterniond(p.Rot().W(), p.Rot().X(), p.Rot().Y(), p.Rot().Z())
                   .normalized()
                   .toRotationMatrix();
  return T;
}

// Whether a point (robot frame) lies in a mount's housing grown by `margin`: the housing's box,
// or its upright cylinder, in the sensor frame (sensors.yaml's `housing`).
bool in_housing(const model::Mount& mount, const model::HousingSolid& housing,
                const model::Vec3& point, double margin) {
  const model::Vec3 local = mount.T_robot_sensor.inverse() * point - housing.center;
  if (housing.shape == model::HousingShape::cylinder) {
    return std::hypot(local.x(), local.y()) <= 0.5 * housing.size.x() + margin &&
           std::abs(local.z()) <= 0.5 * housing.size.z() + margin;
  }
  return (local.cwiseAbs() - 0.5 * housing.size).maxCoeff() <= margin;
}

// The description as the rig loads it, then the exported macros, called as their comments say.
std::string wrapper_xacro(const model::Rig& rig) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<robot name=\"rig\" "
         "xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      << "  <xacro:include filename=\""
      << std::filesystem::absolute(rig.robot->description).string() << "\"/>\n"
      << "  <xacro:include filename=\"sensors.urdf.xacro\"/>\n"
      << "  <xacro:include filename=\"sensors.gazebo.xacro\"/>\n"
      << "  <xacro:rig_sensors/>\n  <xacro:rig_gazebo_sensors/>\n</robot>\n";
  return out.str();
}

}  // namespace

TEST_CASE(
    "export: libsdformat loads each bundled description with its accessories and the "
    "exported Gazebo sensors, one sensor per mount",
    "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  int adopted = 0;
  // The bundled rigs on a robot description. ur_cleaner_from_urdf.yaml's legacy `urdf:` file
  // gives poses only (links without mass or collision, which libsdformat drops: "A model must
  // have at least one link"); it is no simulation model, so it is not tried.
  for (const char* rig_file : {"rigs/jackal.yaml", "rigs/turtlebot4.yaml"}) {
    INFO(rig_file);
    const model::Rig rig = io::load_rig(source_path(rig_file));
    REQUIRE(rig.robot.has_value());
    REQUIRE_FALSE(rig.robot->poses_only);
    deploy::DeployOptions options;
    options.max_speed = 1.0;
    const deploy::Deployment deployment = deploy::plan_deployment(rig, library, nullptr, options);
    test::TempFolder folder;
    deploy::write_deployment(folder.path(), rig, deployment, "test");
    const io::PackageLocator packages(rig.robot->package_paths);
    io::XacroInput input;
    input.path = folder.write("robot.urdf.xacro", wrapper_xacro(rig));
    input.args = rig.robot->args;
    input.environment = rig.robot->environment;
    input.packages = &packages;
    // <gazebo reference> expanded; model-wide <gazebo> plugins and <ros2_control> left out:
    // they name the robot's controller packages (irobot_create_control), not bundled here.
    input.keep_gazebo = true;
    const std::string urdf = io::xml::to_xml(io::expand_xacro(input));
    sdf::Root root;
    const sdf::Errors errors = root.LoadSdfString(urdf);
    std::string messages;
    for (const sdf::Error& e : errors) messages += e.Message() + "\n";
    INFO(messages);
    REQUIRE(errors.empty());
    const sdf::Model* model = root.Model();
    REQUIRE(model != nullptr);
    // The model frame in the robot frame, from the canonical link (a description link).
    const sdf::Link* canonical = model->CanonicalLink();
    REQUIRE(canonical != nullptr);
    REQUIRE(rig.link_poses.count(canonical->Name()) == 1);
    ignition::math::Pose3d canonical_pose;
    REQUIRE(canonical->SemanticPose().Resolve(canonical_pose, "__model__").empty());
    const model::Pose3 T_robot_model =
        rig.link_poses.at(canonical->Name()) * to_pose(canonical_pose).inverse();
    std::vector<model::Vec3> sensor_origins;
    for (uint64_t l = 0; l < model->LinkCount(); ++l) {
      const sdf::Link* link = model->LinkByIndex(l);
      for (uint64_t s = 0; s < link->SensorCount(); ++s) {
        ignition::math::Pose3d pose;
        REQUIRE(link->SensorByIndex(s)->SemanticPose().Resolve(pose, "__model__").empty());
        sensor_origins.push_back(T_robot_model * to_pose(pose).translation());
      }
    }
    for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
      const model::Mount& mount = rig.mounts[m];
      INFO(mount.id);
      const model::Sensor* sensor = library.find(mount.sensor_id);
      REQUIRE((sensor && sensor->housing));
      int in_mount = 0;
      // sensors.yaml lets a data origin lie up to 10 mm outside its housing.
      for (const model::Vec3& origin : sensor_origins)
        in_mount += in_housing(mount, *sensor->housing, origin, 0.01) ? 1 : 0;
      CHECK(in_mount == 1);
      if (deployment.gazebo[m].description_sensor) ++adopted;
    }
  }
  // The Jackal's laser and VLP-16 accessories and the TurtleBot 4's RPLIDAR and OAK-D declare
  // their own sensors: four mounts the export configures rather than doubles.
  CHECK(adopted == 4);
}

TEST_CASE("export: a mount on a description's sensor says what that sensor simulates otherwise",
          "[deploy]") {
  test::TempFolder folder;
  const test::CliResult result = test::run_cli({"export", source_path("rigs/jackal.yaml"), "--to",
                                                folder.path() + "/out", "--max-speed", "1"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  // sick_lms1xx.urdf.xacro line 59 declares <sensor type="ray" name="${frame}">; its macro's
  // defaults (line 32) give 720 samples at 50 Hz. The design's mode: 25 Hz, 270 deg at 0.5 deg,
  // 541 rays (sensors.yaml, sick_lms100 res_0.5deg_25hz).
  CHECK(result.out.find("Gazebo front_laser: the description's sensor 'front_laser' simulates "
                        "it (none added)") != std::string::npos);
  CHECK(result.out.find("its type 'ray' is Gazebo Classic's CPU sensor") != std::string::npos);
  CHECK(result.out.find("50 Hz (design 25)") != std::string::npos);
  CHECK(result.out.find("720 rays a turn of its scan (design 541)") != std::string::npos);
  const std::string readme = test::file_text(folder.path() + "/out/README.md");
  CHECK(readme.find("sick_lms1xx.urdf.xacro:59") != std::string::npos);
}
