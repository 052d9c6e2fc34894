// Issue 30 item 5: the exported launch file starts each self-filter with the executable or
// component, node name and topics the packages declare (data/ros_parameters/
// laser_filters_pcl_ros.yaml, read from laser_filters' and pcl_ros' sources), on the driver's
// topic, publishing where the exported nav2 source subscribes; and it is valid Python.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_launch_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_writer.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// The declared topic of `package`'s node with `direction` (subscribe or publish).
std::string declared_topic(const YAML::Node& topics, const std::string& direction) {
  for (const YAML::Node& topic : topics) {
    if (topic["direction"].as<std::string>() == direction && !topic["when"])
      return topic["name"].as<std::string>();
  }
  FAIL("no " << direction << " topic declared");
  return {};
}

struct Exported {
  deploy::Deployment deployment;
  std::string launch;
  YAML::Node parameters;
  YAML::Node nav2;
};

Exported exported(const std::string& rig_file) {
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path(rig_file));
  Exported e{deploy::plan_deployment(rig, library, nullptr, {}), {}, {}, {}};
  e.launch = deploy::self_filters_launch_text(
      e.deployment.self_filters, e.deployment.costmap.sources, "self_filters.yaml", "test");
  e.parameters = YAML::Load(deploy::self_filters_text(e.deployment.self_filters, rig.base_link,
                                                      model::Pose3::Identity(), "test"));
  e.nav2 = YAML::Load(deploy::nav2_costmap_text(e.deployment.costmap, "test"));
  return e;
}

// The nav2 local costmap's source `mount`: its topic.
std::string nav2_topic(const YAML::Node& nav2, const std::string& mount) {
  const YAML::Node parameters = nav2["local_costmap"]["local_costmap"]["ros__parameters"];
  for (const char* layer : {"obstacle_layer", "voxel_layer"}) {
    if (parameters[layer] && parameters[layer][mount])
      return parameters[layer][mount]["topic"].as<std::string>();
  }
  FAIL("no nav2 source " << mount);
  return {};
}

bool python_compiles(const std::string& text) {
  if (std::system("command -v python3 > /dev/null 2>&1") != 0) return true;  // nothing to run
  TempFolder folder;
  const std::string file = folder.write("self_filters.launch.py", text);
  return std::system(("python3 -m py_compile '" + file + "'").c_str()) == 0;
}

}  // namespace

TEST_CASE(
    "export: the self-filter launch file starts laser_filters chains as the package "
    "declares them",
    "[deploy]") {
  const YAML::Node table =
      YAML::LoadFile(source_path("data/ros_parameters/laser_filters_pcl_ros.yaml"));
  const YAML::Node chain = table["laser_filters"]["scan_to_scan_filter_chain"]["launch"];
  const std::string in = declared_topic(chain["topics"], "subscribe");
  const std::string out = declared_topic(chain["topics"], "publish");
  const Exported e = exported("rigs/cart_two_scanners.yaml");
  CHECK(python_compiles(e.launch));
  CHECK(e.launch.find("package='" + chain["package"].as<std::string>() + "'") != std::string::npos);
  CHECK(e.launch.find("executable='" + chain["executable"].as<std::string>() + "'") !=
        std::string::npos);
  for (const char* mount : {"front_lidar", "rear_lidar"}) {
    INFO(mount);
    // The node's name is the parameter file's key, or it would run an empty chain.
    const std::string node = std::string(mount) + "_self_filter";
    REQUIRE(e.parameters[node]);
    CHECK(e.launch.find("name='" + node + "'") != std::string::npos);
    // Driver topic in, the nav2 source's topic out.
    const std::string raw = "/" + std::string(mount) + "/scan";
    const std::string filtered = nav2_topic(e.nav2, mount);
    CHECK(filtered != raw);
    CHECK(e.launch.find("remappings=[('" + in + "', '" + raw + "'), ('" + out + "', '" + filtered +
                        "')]") != std::string::npos);
  }
}

TEST_CASE("export: the self-filter launch file chains pcl_ros CropBox components", "[deploy]") {
  const YAML::Node table =
      YAML::LoadFile(source_path("data/ros_parameters/laser_filters_pcl_ros.yaml"));
  const YAML::Node crop = table["pcl_ros"]["CropBox"]["launch"];
  const std::string in = declared_topic(crop["topics"], "subscribe");
  const std::string out = declared_topic(crop["topics"], "publish");
  const Exported e = exported("rigs/cell.yaml");
  CHECK(python_compiles(e.launch));
  CHECK(e.launch.find("plugin='" + crop["component_plugin"].as<std::string>() + "'") !=
        std::string::npos);
  int boxes = 0;
  for (std::size_t m = 0; m < e.deployment.self_filters.size(); ++m) {
    const deploy::SelfFilter& filter = e.deployment.self_filters[m];
    if (filter.scanner || filter.boxes.empty()) continue;
    INFO(filter.mount_id);
    // Box k reads box k-1's output; the first the driver's topic, the last writes the topic
    // the nav2 source reads.
    std::string input = e.deployment.costmap.sources[m].raw_topic;
    for (std::size_t k = 1; k <= filter.boxes.size(); ++k, ++boxes) {
      const std::string node = filter.mount_id + "_self_filter_" + std::to_string(k);
      REQUIRE(e.parameters[node]);
      const std::size_t named = e.launch.find("name='" + node + "'");
      REQUIRE(named != std::string::npos);
      const std::size_t remap =
          e.launch.find("remappings=[('" + in + "', '" + input + "'), ('" + out + "', '", named);
      REQUIRE(remap != std::string::npos);
      const std::size_t start = e.launch.find("('" + out + "', '", remap) + out.size() + 6;
      const std::string written = e.launch.substr(start, e.launch.find('\'', start) - start);
      if (k == filter.boxes.size()) CHECK(written == nav2_topic(e.nav2, filter.mount_id));
      input = written;
    }
  }
  CHECK(boxes >= 3);
}

TEST_CASE("export: Python strings in the launch file hold any topic exactly", "[deploy]") {
  deploy::SelfFilter filter;
  filter.mount_id = "front";
  filter.scanner = true;
  filter.bands = {{0.1, 0.2}};
  deploy::SourceConfig source;
  source.raw_topic = "/a'b\\c\nimport os";
  source.topic = "/out";
  const std::string launch =
      deploy::self_filters_launch_text({filter}, {source}, "self_filters.yaml", "header\nline two");
  CHECK(launch.find("'/a\\'b\\\\c\\x0aimport os'") != std::string::npos);
  CHECK(launch.find("\nimport os'") == std::string::npos);
  CHECK(python_compiles(launch));
}
