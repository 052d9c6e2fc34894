// Issue 34: the exported Gazebo sensors read by Gazebo's own parser (Debian's libsdformat 12):
// the URDF with sensors.urdf.xacro and sensors.gazebo.xacro expanded is converted to SDF by
// libsdformat, and every sensor's type, pose, rate, FOV, samples, ranges, noise, topic and frame
// id is checked against the datasheet (sensors.yaml) and the other exported files.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sdf/Camera.hh>
#include <sdf/Geometry.hh>
#include <sdf/Lidar.hh>
#include <sdf/Link.hh>
#include <sdf/Mesh.hh>
#include <sdf/Model.hh>
#include <sdf/Noise.hh>
#include <sdf/Root.hh>
#include <sdf/Sensor.hh>
#include <sdf/Visual.hh>
#include <sdf/World.hh>
#include <set>
#include <sstream>

#include "io/robot/xacro_expander.hpp"
#include "io/robot/xml_tree.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/mesh/assimp_mesh_loader.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/sim/scene_library.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using test::source_path;

namespace {

// The camera modes' image sizes as sensors.yaml writes them (`pixels: [w, h]`), read here with
// yaml-cpp rather than through the library's loader.
std::map<std::string, std::pair<int, int>> pixels_in_sensors_yaml() {
  std::map<std::string, std::pair<int, int>> pixels;
  const YAML::Node file = YAML::LoadFile(source_path("sensors.yaml"));
  for (const YAML::Node& sensor : file["sensors"]) {
    const std::string id = sensor["id"].as<std::string>();
    for (const YAML::Node& mode : sensor["modes"]) {
      if (mode["pixels"])
        pixels[id + "/" + mode["id"].as<std::string>()] = {mode["pixels"][0].as<int>(),
                                                           mode["pixels"][1].as<int>()};
    }
  }
  return pixels;
}

std::string triple(const model::Vec3& v) {
  std::ostringstream out;
  out.precision(17);
  out << v.x() << " " << v.y() << " " << v.z();
  return out.str();
}

// A robot for the macros: the parent link with mass (libsdformat drops massless links that are
// not lumped), and a stand-in at its place for every description link a mount sits on.
std::string wrapper_xacro(const model::Rig& rig, const deploy::Deployment& deployment) {
  const std::string parent = deployment.frames.parent;
  const model::Pose3 T_robot_parent =
      deploy::robot_frame_pose(rig, parent).value_or(model::Pose3::Identity());
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<robot name=\"rig\" "
         "xmlns:xacro=\"http://www.ros.org/wiki/xacro\">\n"
      << "  <link name=\"" << parent << "\"><inertial><mass value=\"20\"/>"
      << "<inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" "
         "izz=\"1\"/></inertial></link>\n";
  std::set<std::string> written = {parent};
  for (const deploy::SensorFrame& frame : deployment.frames.frames) {
    std::vector<std::string> links;
    if (frame.joint.empty()) links.push_back(frame.link);
    if (frame.optical_frame && frame.optical_joint.empty() && !frame.data_frame_from_driver)
      links.push_back(*frame.optical_frame);
    for (const std::string& link : links) {
      if (!written.insert(link).second) continue;
      const model::Pose3 T = T_robot_parent.inverse() * rig.link_poses.at(link);
      out << "  <link name=\"" << link << "\"/>\n"
          << "  <joint name=\"" << link << "_stand_in\" type=\"fixed\"><parent link=\"" << parent
          << "\"/><child link=\"" << link << "\"/><origin xyz=\"" << triple(T.translation())
          << "\" rpy=\"" << triple(model::rpy_from_rotation(T.linear())) << "\"/></joint>\n";
    }
  }
  out << "  <xacro:include filename=\"sensors.urdf.xacro\"/>\n"
      << "  <xacro:include filename=\"sensors.gazebo.xacro\"/>\n"
      << "  <xacro:rig_sensors/>\n  <xacro:rig_gazebo_sensors/>\n</robot>\n";
  return out.str();
}

const sdf::Sensor* find_sensor(const sdf::Model& model, const std::string& name,
                               std::string* link_name) {
  for (uint64_t l = 0; l < model.LinkCount(); ++l) {
    const sdf::Link* link = model.LinkByIndex(l);
    if (const sdf::Sensor* sensor = link->SensorByName(name)) {
      *link_name = link->Name();
      return sensor;
    }
  }
  return nullptr;
}

}  // namespace

TEST_CASE("export: libsdformat reads every bundled rig's Gazebo sensors as the datasheet says",
          "[deploy]") {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const auto pixels = pixels_in_sensors_yaml();
  int lidars = 0, cameras = 0;
  for (const char* rig_file : {"rigs/turtlebot4.yaml", "rigs/jackal.yaml", "rigs/ur_cleaner.yaml",
                               "rigs/cart_two_scanners.yaml", "rigs/delivery_amr.yaml",
                               "rigs/cell.yaml", "rigs/elektron.yaml"}) {
    INFO(rig_file);
    const model::Rig rig = io::load_rig(source_path(rig_file));
    deploy::DeployOptions options;
    options.max_speed = 1.0;
    const deploy::Deployment deployment = deploy::plan_deployment(rig, library, nullptr, options);
    test::TempFolder folder;
    deploy::write_deployment(folder.path(), rig, deployment, "test");
    const std::string wrapper = folder.write("robot.urdf.xacro", wrapper_xacro(rig, deployment));
    io::XacroInput input;
    input.path = wrapper;
    input.keep_simulation = true;
    const std::string urdf = io::xml::to_xml(io::expand_xacro(input));
    sdf::Root root;
    const sdf::Errors errors = root.LoadSdfString(urdf);
    for (const sdf::Error& e : errors) INFO(e.Message());
    REQUIRE(errors.empty());
    REQUIRE(root.Model() != nullptr);
    const YAML::Node nav2 = YAML::LoadFile(folder.path() + "/nav2_costmap.yaml");
    const YAML::Node bridge = YAML::LoadFile(folder.path() + "/bridge.yaml");
    // One entry per mount the export simulates, then gz sim's clock for use_sim_time. A mount
    // the description already simulates (description_gazebo_test.cpp) is left to it here.
    std::size_t simulated = 0;
    for (const deploy::GazeboSensor& g : deployment.gazebo)
      simulated += g.description_sensor ? 0 : 1;
    REQUIRE(bridge.size() == simulated + 1);
    const YAML::Node clock = bridge[simulated];
    CHECK(clock["ros_topic_name"].as<std::string>() == "/clock");
    CHECK(clock["ros_type_name"].as<std::string>() == "rosgraph_msgs/msg/Clock");
    CHECK(clock["direction"].as<std::string>() == "GZ_TO_ROS");
    std::size_t entry_index = 0;
    for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
      const model::Mount& mount = rig.mounts[m];
      INFO(mount.id);
      if (deployment.gazebo[m].description_sensor) continue;
      const model::SensorMode& mode = library.resolved_mode(mount.sensor_id, mount.mode_id);
      const deploy::SourceConfig& source = deployment.costmap.sources[m];
      std::string link_name;
      const sdf::Sensor* sensor = find_sensor(*root.Model(), mount.id, &link_name);
      REQUIRE(sensor != nullptr);
      CHECK(sensor->UpdateRate() == Approx(mode.frequency));
      // The topic and frame nav2's source of this mount reads (from nav2_costmap.yaml's text).
      // gz-sensors publishes a scan on <topic> and a cloud on <topic>/points (docs/gazebo.md).
      const std::string gz_data = source.laser_scan ? sensor->Topic() : sensor->Topic() + "/points";
      if (source.laser_scan || source.raw_topic.ends_with("/points")) {
        CHECK(gz_data == source.raw_topic);  // one name in gz and ROS
      }
      const std::string frame_id = sensor->Element()->Get<std::string>("gz_frame_id");
      CHECK(frame_id == source.sensor_frame);
      CHECK(urdf.find("<link name=\"" + frame_id + "\"") != std::string::npos);
      // Noise: sigma(d) at the mount's distance of interest (the rig file's d).
      const double d =
          std::min(mount.distance_of_interest.value_or(rig.distance_of_interest), mode.max_range);
      const double sigma = mode.noise.a + mode.noise.b * d + mode.noise.c * d * d;
      // The URDF-to-SDF conversion lumps every fixed joint into the parent link: the sensor's
      // pose there is the mount's pose in the rig (x forward: gz sensors look along +x).
      CHECK(link_name == deployment.frames.parent);
      const model::Pose3 expected = deploy::robot_frame_pose(rig, deployment.frames.parent)
                                        .value_or(model::Pose3::Identity())
                                        .inverse() *
                                    mount.T_robot_sensor;
      // libsdformat 12 writes the lumped pose as text with 6 significant digits: 1e-5.
      const auto& pose = sensor->RawPose();
      CHECK((model::Vec3(pose.Pos().X(), pose.Pos().Y(), pose.Pos().Z()) - expected.translation())
                .norm() < 1e-5);
      const Eigen::Quaterniond q(pose.Rot().W(), pose.Rot().X(), pose.Rot().Y(), pose.Rot().Z());
      CHECK(Eigen::Quaterniond(expected.linear()).angularDistance(q) < 1e-5);
      const bool camera = mode.is_camera();
      if (camera) {
        ++cameras;
        REQUIRE(sensor->Type() == sdf::SensorType::DEPTH_CAMERA);
        const sdf::Camera* c = sensor->CameraSensor();
        REQUIRE(c != nullptr);
        CHECK(c->HorizontalFov().Radian() == Approx(mode.fov.horizontal()).epsilon(1e-9));
        const auto size = pixels.find(mount.sensor_id + "/" + mount.mode_id);
        if (size != pixels.end()) {
          CHECK(static_cast<int>(c->ImageWidth()) == size->second.first);
          CHECK(static_cast<int>(c->ImageHeight()) == size->second.second);
        }
        CHECK(c->NearClip() == Approx(mode.min_range));
        CHECK(c->FarClip() == Approx(mode.max_range));
        CHECK(c->ImageNoise().Type() == sdf::NoiseType::GAUSSIAN);
        CHECK(c->ImageNoise().StdDev() == Approx(sigma).epsilon(1e-9));
      } else {
        ++lidars;
        REQUIRE(sensor->Type() == sdf::SensorType::GPU_LIDAR);
        const sdf::Lidar* l = sensor->LidarSensor();
        REQUIRE(l != nullptr);
        // Rays every angular_resolution over the FOV (a full turn does not repeat its first).
        const double fov = mode.fov.horizontal();
        const double spacing = mode.angular_resolution_h;
        const bool full = std::abs(fov - 2 * std::numbers::pi) < 1e-6;
        CHECK(l->HorizontalScanSamples() ==
              static_cast<unsigned>(std::lround(fov / spacing) + (full ? 0 : 1)));
        CHECK(l->HorizontalScanMinAngle().Radian() == Approx(-fov / 2));
        CHECK(l->HorizontalScanMaxAngle().Radian() == Approx(full ? fov / 2 - spacing : fov / 2));
        if (mode.angular_resolution_v) {
          CHECK(l->VerticalScanSamples() ==
                static_cast<unsigned>(
                    std::lround(mode.fov.vertical() / *mode.angular_resolution_v) + 1));
          CHECK(l->VerticalScanMinAngle().Radian() == Approx(mode.fov.elevation_min()));
          CHECK(l->VerticalScanMaxAngle().Radian() == Approx(mode.fov.elevation_max()));
        } else {
          CHECK(l->VerticalScanSamples() == 1u);
        }
        CHECK(l->RangeMin() == Approx(mode.min_range));
        CHECK(l->RangeMax() == Approx(mode.max_range));
        CHECK(l->LidarNoise().Type() == sdf::NoiseType::GAUSSIAN);
        CHECK(l->LidarNoise().StdDev() == Approx(sigma).epsilon(1e-9));
      }
      // bridge.yaml: this sensor's data reaches the ROS topic the costmap (or its self-filter)
      // reads, as the type nav2 declares for the source.
      const YAML::Node entry = bridge[entry_index++];
      CHECK(entry["ros_topic_name"].as<std::string>() == source.raw_topic);
      CHECK(entry["direction"].as<std::string>() == "GZ_TO_ROS");
      CHECK(entry["ros_type_name"].as<std::string>() ==
            (source.laser_scan ? "sensor_msgs/msg/LaserScan" : "sensor_msgs/msg/PointCloud2"));
      CHECK(entry["gz_topic_name"].as<std::string>() == gz_data);
    }
  }
  CHECK(lidars > 0);
  CHECK(cameras > 0);
}

TEST_CASE("simulate --gazebo: libsdformat loads the office world, assimp its mesh", "[deploy]") {
  test::TempFolder folder;
  const std::string out = folder.path() + "/sim";
  const test::CliResult result =
      test::run_cli({"simulate", source_path("rigs/delivery_amr.yaml"), "--scene", "office",
                     "--seed", "3", "--out", out, "--gazebo"});
  INFO(result.out << result.err);
  REQUIRE(result.exit_code == 0);
  sdf::Root root;
  const sdf::Errors errors = root.Load(out + "/gazebo/world.sdf");
  for (const sdf::Error& e : errors) INFO(e.Message());
  REQUIRE(errors.empty());
  REQUIRE(root.WorldCount() == 1u);
  const sdf::World* world = root.WorldByIndex(0);
  REQUIRE(world->ModelCount() == 1u);
  const sdf::Model* scene_model = world->ModelByIndex(0);
  CHECK(scene_model->Static());
  const sdf::Link* link = scene_model->LinkByIndex(0);
  REQUIRE(link != nullptr);
  REQUIRE(link->VisualCount() == 1u);
  REQUIRE(link->CollisionCount() == 1u);
  const sdf::Mesh* mesh = link->VisualByIndex(0)->Geom()->MeshShape();
  REQUIRE(mesh != nullptr);
  CHECK(mesh->Uri() == "scene.obj");
  // assimp reads the OBJ beside the world: the scene's triangles at t = 0, all of them.
  const model::TriangleMesh read =
      io::load_mesh_with_assimp(out + "/gazebo/scene.obj", model::SourceLocation{"test"});
  const model::TriangleMesh scene = sim::make_scene("office", 3).at(0.0);
  CHECK(read.triangles.size() == scene.triangles.size());
  double area_read = 0.0, area_scene = 0.0;
  for (const auto& [mesh_of, area] :
       {std::pair<const model::TriangleMesh*, double*>{&read, &area_read}, {&scene, &area_scene}}) {
    for (const std::array<int, 3>& t : mesh_of->triangles) {
      const model::Vec3 a = mesh_of->vertices[t[0]], b = mesh_of->vertices[t[1]],
                        c = mesh_of->vertices[t[2]];
      *area += 0.5 * (b - a).cross(c - a).norm();
    }
  }
  CHECK(area_read == Approx(area_scene).epsilon(1e-6));  // assimp keeps single-precision floats
}
