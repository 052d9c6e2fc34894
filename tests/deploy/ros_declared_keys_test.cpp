// Issue 30, item 3: every key the exported nav2_costmap.yaml and self_filters.yaml write is a
// parameter the package declares for what it configures, with the declared type. The
// declarations come from data/ros_parameters/ (read from nav2's, laser_filters' and pcl_ros'
// sources, file:line and commit cited there), not from rigdesign's key tables; the exported
// files are read with yaml-cpp, and a scalar's type is the one rclcpp's parameter YAML gives it.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "deploy/ros/nav2/collision_monitor_keys.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/deploy/ros/nav2/collision_monitor_writer.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_writer.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_writer.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/shared_export.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using rigdesign::test::source_path;

namespace {

// key -> declared type, for the entries present in both releases.
using Declared = std::map<std::string, std::string>;

Declared declared(const YAML::Node& entries) {
  Declared result;
  for (const YAML::Node& entry : entries) {
    if (entry["humble"].as<bool>(false) && entry["jazzy"].as<bool>(false)) {
      result[entry["key"].as<std::string>()] = entry["type"].as<std::string>();
    }
  }
  return result;
}

// A YAML integer: an optional sign and digits.
bool is_integer(const std::string& text) {
  const std::size_t first = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
  return first < text.size() &&
         std::all_of(text.begin() + static_cast<std::ptrdiff_t>(first), text.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

// A YAML float: a number with a point or an exponent (no inf or nan is ever exported).
bool is_real(const std::string& text) {
  if (text.find_first_of(".eE") == std::string::npos) return false;
  if (text.find_first_not_of("+-.0123456789eE") != std::string::npos) return false;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

// The type rclcpp's YAML parser gives a value: a sequence of strings, or a scalar by its form.
std::string yaml_type(const YAML::Node& node) {
  if (node.IsSequence()) return "string array";
  const std::string& text = node.Scalar();
  if (node.Tag() == "!") return "string";  // quoted
  if (text == "true" || text == "false") return "bool";
  if (is_integer(text)) return "int";
  if (is_real(text)) return "double";
  return "string";
}

// STVL's keys in the code its table was read from (data/ros_parameters/
// spatio_temporal_voxel_layer.yaml): newer keys whose releases are unconfirmed are left out.
Declared stvl_declared(const YAML::Node& entries) {
  Declared result;
  for (const YAML::Node& entry : entries) {
    if (entry["in_403d9ed"].as<bool>(false))
      result[entry["key"].as<std::string>()] = entry["type"].as<std::string>();
  }
  return result;
}

struct Tables {
  YAML::Node file = YAML::LoadFile(source_path("data/ros_parameters/nav2_costmap_2d.yaml"));
  YAML::Node stvl_file =
      YAML::LoadFile(source_path("data/ros_parameters/spatio_temporal_voxel_layer.yaml"));
  Declared stvl_layer = stvl_declared(stvl_file["layer"]);
  Declared stvl_source = stvl_declared(stvl_file["observation_source"]);
  Declared costmap = declared(file["costmap"]);
  Declared source = declared(file["observation_source"]);
  Declared common = declared(file["layer_common"]);
  std::map<std::string, std::string> layer_of_class = {
      {"nav2_costmap_2d::ObstacleLayer", "obstacle_layer"},
      {"nav2_costmap_2d::VoxelLayer", "voxel_layer"},
      {"nav2_costmap_2d::InflationLayer", "inflation_layer"},
      {"nav2_costmap_2d::StaticLayer", "static_layer"}};
};

void check_key(const Declared& table, const std::string& key, const YAML::Node& value,
               const std::string& where) {
  INFO(where << key << ": " << (value.IsScalar() ? value.Scalar() : "(list)"));
  const auto it = table.find(key);
  REQUIRE(it != table.end());  // declared by nav2
  CHECK(yaml_type(value) == it->second);
}

// One layer's keys against its class's declarations; its sources against a source's.
void check_layer(const Tables& tables, const std::string& name, const YAML::Node& layer,
                 std::set<std::string>& other_classes) {
  const std::string plugin = layer["plugin"].as<std::string>();
  const auto known = tables.layer_of_class.find(plugin);
  const bool stvl = plugin == tables.stvl_file["plugin_class"].as<std::string>();
  if (known == tables.layer_of_class.end() && !stvl) {
    other_classes.insert(plugin);
    return;
  }
  Declared keys = stvl ? tables.stvl_layer : declared(tables.file["layers"][known->second]);
  keys.insert(tables.common.begin(), tables.common.end());
  const Declared& source_keys = stvl ? tables.stvl_source : tables.source;
  std::set<std::string> sources;
  if (layer["observation_sources"]) {
    std::istringstream names(layer["observation_sources"].as<std::string>());
    for (std::string source; names >> source;) sources.insert(source);
  }
  for (const auto& entry : layer) {
    const std::string key = entry.first.as<std::string>();
    if (sources.count(key)) {
      for (const auto& setting : entry.second) {
        check_key(source_keys, setting.first.as<std::string>(), setting.second,
                  name + "." + key + ".");
      }
      continue;
    }
    check_key(keys, key, entry.second, name + ".");
  }
}

}  // namespace

// The classes of every layer the exported nav2 file loads, after checking each key.
std::set<std::string> checked_classes(const Tables& tables, const std::string& text) {
  const YAML::Node file = YAML::Load(text);
  std::set<std::string> other_classes;
  for (const char* costmap : {"local_costmap", "global_costmap"}) {
    const YAML::Node parameters = file[costmap][costmap]["ros__parameters"];
    REQUIRE(parameters.IsMap());
    std::set<std::string> layers;
    for (const YAML::Node& name : parameters["plugins"]) layers.insert(name.as<std::string>());
    for (const auto& entry : parameters) {
      const std::string key = entry.first.as<std::string>();
      if (layers.count(key)) {
        check_layer(tables, key, entry.second, other_classes);
      } else {
        check_key(tables.costmap, key, entry.second, std::string(costmap) + ".");
      }
    }
  }
  return other_classes;
}

TEST_CASE("export: every nav2 key is declared by nav2 with the type written", "[deploy]") {
  const Tables tables;
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  for (const char* rig_file : {"rigs/turtlebot4.yaml", "rigs/jackal.yaml", "rigs/ur_cleaner.yaml",
                               "rigs/cart_two_scanners.yaml", "rigs/delivery_amr.yaml"}) {
    INFO(rig_file);
    // --max-speed sizes the blind-gap memory: observation_persistence is written. Only nav2's
    // own layers by default (issue 30 item 2).
    CHECK(checked_classes(tables,
                          test::file_text(test::shared_export(rig_file, {"--max-speed", "1"}) +
                                          "/nav2_costmap.yaml"))
              .empty());
    // --layer stvl: the 3D sources in spatio_temporal_voxel_layer, every key declared by STVL.
    CHECK(checked_classes(
              tables, test::file_text(
                          test::shared_export(rig_file, {"--max-speed", "1", "--layer", "stvl"}) +
                          "/nav2_costmap.yaml"))
              .empty());
    const model::Rig rig = io::load_rig(source_path(rig_file));
    deploy::DeployOptions options;
    options.max_speed = 1.0;
    // Paper 1's Hit Layer only when asked for, under the class the user gave.
    options.hit_layer_plugin = "my_layers::HitLayer";
    CHECK(
        checked_classes(tables, deploy::nav2_costmap_text(
                                    deploy::plan_deployment(rig, library, nullptr, options).costmap,
                                    "test")) == std::set<std::string>{"my_layers::HitLayer"});
  }
}

namespace {

Declared params_of(const YAML::Node& entries) {
  Declared result;
  for (const YAML::Node& entry : entries) {
    result[entry["key"].as<std::string>()] = entry["type"].as<std::string>();
  }
  return result;
}

}  // namespace

TEST_CASE("export: every self-filter key is declared by laser_filters or pcl_ros CropBox",
          "[deploy]") {
  const YAML::Node tables =
      YAML::LoadFile(source_path("data/ros_parameters/laser_filters_pcl_ros.yaml"));
  const Declared crop_box = params_of(tables["pcl_ros"]["CropBox"]["params"]);
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  int chains = 0, boxes = 0;
  // A rig with 2D scanners that see its body (bands) and one with 3D sensors that do (boxes).
  for (const char* rig_file :
       {"rigs/cart_two_scanners.yaml", "rigs/delivery_amr.yaml", "rigs/cell.yaml"}) {
    INFO(rig_file);
    const model::Rig rig = io::load_rig(source_path(rig_file));
    const deploy::Deployment deployment = deploy::plan_deployment(rig, library, nullptr, {});
    const YAML::Node file = YAML::Load(deploy::self_filters_text(
        deployment.self_filters, rig.base_link, model::Pose3::Identity(), "test"));
    for (const auto& node : file) {
      const YAML::Node parameters = node.second["ros__parameters"];
      REQUIRE(parameters.IsMap());
      if (parameters["input_frame"]) {  // a CropBox node
        ++boxes;
        for (const auto& entry : parameters) {
          check_key(crop_box, entry.first.as<std::string>(), entry.second, "CropBox.");
        }
        continue;
      }
      ++chains;  // a scan_to_scan_filter_chain: filter1, filter2, ... {name, type, params}
      for (const auto& filter : parameters) {
        const std::string type = filter.second["type"].as<std::string>();
        REQUIRE(type.rfind("laser_filters/", 0) == 0);
        const YAML::Node declared_filter =
            tables["laser_filters"]["filters"][type.substr(std::string("laser_filters/").size())];
        REQUIRE(declared_filter.IsMap());  // a filter class laser_filters ships
        CHECK(yaml_type(filter.second["name"]) == "string");
        const Declared params = params_of(declared_filter["params"]);
        for (const auto& param : filter.second["params"]) {
          check_key(params, param.first.as<std::string>(), param.second, type + ".");
        }
      }
    }
  }
  CHECK(chains > 0);  // both kinds were exercised
  CHECK(boxes > 0);
}

namespace {

// nav2_collision_monitor's keys one release declares (data/ros_parameters/
// nav2_collision_monitor.yaml), types spelt as yaml_type does ("string array").
Declared monitor_declared(const YAML::Node& entries, const std::string& distro) {
  Declared result;
  for (const YAML::Node& entry : entries) {
    if (!entry[distro].as<bool>(false)) continue;
    std::string type = entry["type"].as<std::string>();
    std::replace(type.begin(), type.end(), '_', ' ');
    result[entry["key"].as<std::string>()] = type;
  }
  return result;
}

// yaml_type, telling a list of numbers (a double array) from a list of names.
std::string monitor_yaml_type(const YAML::Node& node) {
  if (!node.IsSequence()) return yaml_type(node);
  const bool numbers =
      node.size() > 0 && std::all_of(node.begin(), node.end(), [](const YAML::Node& n) {
        return n.Tag() != "!" && is_real(n.Scalar());
      });
  return numbers ? "double array" : "string array";
}

void check_monitor_key(const Declared& table, const std::string& key, const YAML::Node& value,
                       const std::string& where) {
  INFO(where << key << ": " << (value.IsScalar() ? value.Scalar() : "(list)"));
  const auto it = table.find(key);
  REQUIRE(it != table.end());  // declared by nav2 for this release
  CHECK(monitor_yaml_type(value) == it->second);
}

}  // namespace

TEST_CASE("export: every collision_monitor key is declared by nav2 for the release written",
          "[deploy]") {
  const YAML::Node table =
      YAML::LoadFile(source_path("data/ros_parameters/nav2_collision_monitor.yaml"));
  int zones = 0, sources = 0;
  for (const char* distro : {"humble", "jazzy"}) {
    const Declared node = monitor_declared(table["node"], distro);
    const Declared polygon = monitor_declared(table["polygon"], distro);
    const Declared source = monitor_declared(table["source"], distro);
    for (const char* rig_file : {"rigs/turtlebot4.yaml", "rigs/jackal.yaml", "rigs/ur_cleaner.yaml",
                                 "rigs/cart_two_scanners.yaml", "rigs/delivery_amr.yaml"}) {
      INFO(distro << " " << rig_file);
      const YAML::Node file = YAML::LoadFile(
          test::shared_export(rig_file, {"--max-speed", "1", "--ros-distro", distro}) +
          "/collision_monitor.yaml");
      const YAML::Node parameters = file["collision_monitor"]["ros__parameters"];
      REQUIRE(parameters.IsMap());
      std::set<std::string> polygons, source_names;
      for (const YAML::Node& name : parameters["polygons"]) polygons.insert(name.as<std::string>());
      for (const YAML::Node& name : parameters["observation_sources"])
        source_names.insert(name.as<std::string>());
      for (const auto& entry : parameters) {
        const std::string key = entry.first.as<std::string>();
        const Declared& keys = polygons.count(key)       ? polygon
                               : source_names.count(key) ? source
                                                         : node;
        if (&keys == &node) {
          check_monitor_key(node, key, entry.second, "");
          continue;
        }
        (&keys == &polygon ? zones : sources) += 1;
        for (const auto& setting : entry.second)
          check_monitor_key(keys, setting.first.as<std::string>(), setting.second, key + ".");
      }
    }
  }
  CHECK(zones == 20);  // two zones per rig and release
  CHECK(sources > 10);
}

TEST_CASE("check --collision-monitor reads only keys nav2 declares", "[deploy]") {
  const YAML::Node table =
      YAML::LoadFile(source_path("data/ros_parameters/nav2_collision_monitor.yaml"));
  const auto either_release = [&](const char* level) {
    Declared keys = monitor_declared(table[level], "humble");
    const Declared jazzy = monitor_declared(table[level], "jazzy");
    keys.insert(jazzy.begin(), jazzy.end());
    return keys;
  };
  const Declared node = either_release("node");
  const Declared polygon = either_release("polygon");
  Declared velocity_keys = either_release("velocity_polygon");
  velocity_keys.insert(polygon.begin(), polygon.end());
  const Declared& velocity = velocity_keys;
  const Declared source = either_release("source");
  for (const auto& [level, declared_keys, keys] :
       {std::tuple{"node", &node, &deploy::nav2::kMonitorNodeKeys},
        std::tuple{"polygon", &velocity, &deploy::nav2::kMonitorPolygonKeys},
        std::tuple{"source", &source, &deploy::nav2::kMonitorSourceKeys}}) {
    for (const std::vector<std::string>* list : {&keys->modelled, &keys->ignored}) {
      for (const std::string& key : *list) {
        INFO(level << "." << key);
        // use_sim_time is rclcpp's own parameter, on every node.
        CHECK((declared_keys->count(key) == 1 || key == "use_sim_time"));
      }
    }
  }
}

TEST_CASE("export: bridge.yaml uses only ros_gz_bridge's keys, directions and type pairs",
          "[deploy]") {
  // data/ros_parameters/ros_gz_bridge.yaml: bridge_config.cpp's keys and mappings.py's pairs.
  const YAML::Node table = YAML::LoadFile(source_path("data/ros_parameters/ros_gz_bridge.yaml"));
  std::set<std::string> keys, directions;
  std::set<std::pair<std::string, std::string>> pairs;
  for (const YAML::Node& entry : table["keys"]) {
    if (entry["humble"].as<bool>(false) && entry["jazzy"].as<bool>(false))
      keys.insert(entry["key"].as<std::string>());
  }
  for (const YAML::Node& entry : table["directions"]) {
    directions.insert(entry.IsMap() ? entry["value"].as<std::string>() : entry.as<std::string>());
  }
  for (const YAML::Node& entry : table["type_mappings"]) {
    if (entry["humble"].as<bool>(false) && entry["jazzy"].as<bool>(false))
      pairs.emplace(entry["ros"].as<std::string>(), entry["gz"].as<std::string>());
  }
  REQUIRE(keys.count("ros_topic_name") == 1);
  REQUIRE(!directions.empty());
  int bridged = 0;
  for (const char* rig_file : {"rigs/turtlebot4.yaml", "rigs/jackal.yaml", "rigs/ur_cleaner.yaml",
                               "rigs/cart_two_scanners.yaml", "rigs/delivery_amr.yaml"}) {
    INFO(rig_file);
    // The bridge does not depend on --max-speed: the export the other key tests read.
    const std::string folder = test::shared_export(rig_file, {"--max-speed", "1"});
    const YAML::Node bridge = YAML::LoadFile(folder + "/bridge.yaml");
    REQUIRE(bridge.IsSequence());  // the bridge reads a list of maps, else nothing
    for (const YAML::Node& item : bridge) {
      for (const auto& entry : item) CHECK(keys.count(entry.first.as<std::string>()) == 1);
      // topic_name excludes ros_topic_name and gz_topic_name (the entry is dropped).
      CHECK_FALSE((item["topic_name"] && (item["ros_topic_name"] || item["gz_topic_name"])));
      if (item["direction"]) CHECK(directions.count(item["direction"].as<std::string>()) == 1);
      const std::string ros = item["ros_type_name"].as<std::string>();
      const std::string gz = item["gz_type_name"].as<std::string>();
      INFO(ros << " <-> " << gz);
      CHECK(pairs.count({ros, gz}) == 1);
      ++bridged;
    }
  }
  CHECK(bridged > 5);
}
