#include "rigdesign/io/scene/scenario_file_loader.hpp"

#include <cmath>
#include <filesystem>
#include <set>
#include <system_error>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/io/scene/scene_file_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

// [m] coordinates a scenario may use: a building, with room to spare; beyond it a typo.
constexpr double kMaxCoordinate = 1e4;
// [s] a run's limit: a day of driving, far beyond any scenario worth simulating.
constexpr double kMaxDuration = 86400.0;
constexpr int kMaxDecimation = 64;

constexpr const char* kXyForm = "[x, y] in metres, finite, within +-1e4";

std::optional<model::Vec2> read_xy(MapReader& reader, const std::string& key, Need need) {
  const auto xy = reader.numbers(key, need, 2, 2, kXyForm);
  if (!xy) return std::nullopt;
  const bool inside = std::abs((*xy)[0]) <= kMaxCoordinate && std::abs((*xy)[1]) <= kMaxCoordinate;
  reader.require(inside, key, "lies beyond 1e4 m", kXyForm);
  if (!inside) return std::nullopt;
  return model::Vec2((*xy)[0], (*xy)[1]);
}

void read_start(MapReader& start, costmap::Pose2& pose) {
  if (const auto xy = read_xy(start, "xy", Need::required)) pose.position = *xy;
  pose.yaw = model::deg_to_rad(
      start.number("yaw_deg", Need::optional, "degrees, finite (default 0)").value_or(0.0));
  start.reject_unknown_keys();
}

void read_route(MapReader& top, scenarios::ScenarioDefinition& scenario) {
  for (MapReader& stop : top.maps("route", Need::required, "a list of {name, xy, wait}")) {
    scenarios::RouteStop route_stop;
    route_stop.name = stop.text("name", Need::optional, "the goal's name").value_or("");
    if (const auto xy = read_xy(stop, "xy", Need::required)) route_stop.position = *xy;
    if (stop.has("wait")) {
      // A wait is part of the run: no longer than the longest run (1e300 s used to pass).
      constexpr const char* kWaitForm = "seconds to wait there, >= 0 and at most 86400";
      route_stop.wait = non_negative(stop, "wait", Need::required, kWaitForm);
      stop.require(route_stop.wait <= kMaxDuration, "wait", "exceeds a day", kWaitForm);
    }
    stop.reject_unknown_keys();
    scenario.route.push_back(route_stop);
  }
  top.require(!top.has("route") || !scenario.route.empty() || top.diagnostics().has_errors(),
              "route", "is empty", "at least one {xy} goal");
}

void read_drops(MapReader& top, scenarios::ScenarioDefinition& scenario) {
  std::set<std::string> names;
  for (MapReader& drop : top.maps("drops", Need::optional, "a list of {name, low, high}")) {
    scenarios::FloorDrop floor_drop;
    floor_drop.name = drop.text("name", Need::required, "the opening's name").value_or("");
    if (!floor_drop.name.empty() && !names.insert(floor_drop.name).second)
      drop.require(false, "name", "duplicate drop name '" + floor_drop.name + "'", "unique names");
    const auto low = read_xy(drop, "low", Need::required);
    const auto high = read_xy(drop, "high", Need::required);
    if (low && high) {
      drop.require(high->x() > low->x() && high->y() > low->y(), "high",
                   "is not above low in both x and y", "[x, y] with x and y above low's");
      floor_drop.low = *low;
      floor_drop.high = *high;
    }
    drop.reject_unknown_keys();
    scenario.drops.push_back(floor_drop);
  }
}

void read_sensing(MapReader& sensing, scenarios::ScenarioDefinition& scenario) {
  if (sensing.has("min_obstacle_height")) {
    scenario.min_obstacle_height = non_negative(sensing, "min_obstacle_height", Need::required,
                                                "metres above the floor, >= 0");
  }
  const auto decimation = [&](const std::string& key) -> std::optional<int> {
    const auto value = sensing.integer(key, Need::optional, "an integer stride from 1 to 64");
    if (!value) return std::nullopt;
    const bool ok = *value >= 1 && *value <= kMaxDecimation;
    sensing.require(ok, key, "is " + std::to_string(*value), "an integer stride from 1 to 64");
    return ok ? value : std::nullopt;
  };
  scenario.camera_decimation = decimation("camera_decimation");
  scenario.lidar_decimation = decimation("lidar_decimation");
  scenario.negative_obstacles = sensing.boolean("negative_obstacles", Need::optional);
  sensing.reject_unknown_keys();
}

}  // namespace

bool is_scenario_file(const std::string& name) {
  const std::string extension = std::filesystem::path(name).extension().string();
  return extension == ".yaml" || extension == ".yml";
}

scenarios::ScenarioDefinition load_scenario_file(const std::string& yaml_path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(yaml_path, diagnostics,
                                    "a scenario: a map with name, scene, start, route, drops");
  scenarios::ScenarioDefinition scenario;
  scenario.name = top.text("name", Need::required, "the scenario's name").value_or("");
  scenario.description = top.text("description", Need::optional, "one line").value_or("");
  const auto scene_name = top.text("scene", Need::required, "a scene file, relative to this one");
  bool scene_found = false;
  if (scene_name) {
    const std::string scene_path = resolve_beside(yaml_path, *scene_name);
    std::error_code ignored;
    scene_found = std::filesystem::is_regular_file(scene_path, ignored);
    top.require(scene_found, "scene", "file '" + scene_path + "' does not exist",
                "a scene file (docs/scene_files.md), relative to this one");
    if (scene_found) {
      try {
        scenario.scene = load_scene_file(scene_path);
      } catch (const model::InputError& error) {
        for (const model::Diagnostic& diagnostic : error.diagnostics()) diagnostics.add(diagnostic);
      }
    }
  }
  // The start: the scene's robot_start unless the scenario gives its own.
  const model::Vec3 forward = scenario.scene.T_world_robot.linear().col(0);
  scenario.start.position = scenario.scene.T_world_robot.translation().head<2>();
  scenario.start.yaw = std::atan2(forward.y(), forward.x());
  if (auto start = top.map("start", Need::optional, "a map with xy and yaw_deg"))
    read_start(*start, scenario.start);
  read_route(top, scenario);
  read_drops(top, scenario);
  scenario.skip_unreachable = top.boolean("skip_unreachable", Need::optional).value_or(false);
  if (top.has("max_duration")) {
    scenario.max_duration =
        positive(top, "max_duration", Need::required, "seconds, > 0 and at most 86400");
    top.require(scenario.max_duration <= kMaxDuration, "max_duration", "exceeds a day",
                "seconds, > 0 and at most 86400");
  }
  if (auto sensing = top.map("sensing", Need::optional,
                             "a map with min_obstacle_height, negative_obstacles, "
                             "camera_decimation, lidar_decimation")) {
    read_sensing(*sensing, scenario);
  }
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return scenario;
}

}  // namespace rigdesign::io
