// Issue 30 item 1: `select` on a catalog that names the robot's description designs on its
// collision geometry. The check is a brute force that shares nothing with the search but the
// loaders and the exact coverage: every combination of the catalog's options (each slot empty
// or one sensor mode at one pose) is built into a rig by hand, judged on the exact path, and
// priced from the sensor library; the cheapest passing cost must be the search's.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/select/selection.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

// Transfer and CPU are free and unbounded, so a rig costs its sensors' prices.
const char* const kFreeHardware = R"(
reference_machine: test
filtering_seconds_per_point: 3.5e-7
transfer:
  - {id: onboard, capacity_bps: 1.0e12, price_usd: 0}
cpus:
  - {id: onboard, cores: 1000.0, price_usd: 0}
)";

std::string jackal_catalog() {
  return "name: Jackal candidates\nsensor_library: " + source_path("sensors.yaml") +
         "\nrobot:\n  description: " +
         source_path("rigs/robots/jackal_description/urdf/jackal.urdf.xacro") +
         "\n  env: {JACKAL_LASER: 1}\n  package_paths: [" + source_path("rigs/robots") +
         "]\n  base_link: base_link\n  base_link_height: 0.0655\n" + kFreeHardware + R"(
area_height: 0.25
distance_of_interest: 2.0
sensors:
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
  - {sensor: hokuyo_ust_10lx, modes: [40hz]}
  - {sensor: rplidar_a2m8, modes: [10hz]}
slots:
  - id: front_camera
    pose: {xyz: [0.24, 0, 0.22], rpy_deg: [0, {min: 0, max: 30, step: 15}, 0]}
    allows: [realsense_d435]
  - id: rear_camera
    pose: {xyz: [-0.24, 0, 0.22], rpy_deg: [0, {min: 0, max: 30, step: 15}, 180]}
    allows: [realsense_d435]
  - id: laser
    pose: {urdf_link: front_laser}
    allows: [hokuyo_ust_10lx, rplidar_a2m8]
)";
}

// Issue 52's reproducer, reduced: a scanner slot on the top plate whose height range starts
// inside the chassis. Only the positions above the chassis can be built.
std::string jackal_catalog_with_top_scanner() {
  return jackal_catalog() + R"(  - id: top_scanner
    pose: {xyz: [0.0, 0.0, {min: 0.11, max: 0.35, step: 0.04}], rpy_deg: [0, 0, 0]}
    allows: [rplidar_a2m8]
)";
}

// Outside the Jackal's chassis box, by hand from jackal.urdf.xacro (lines 13-15: 0.420 x 0.310
// x 0.184 m; line 112: centred chassis_height / 2 above chassis_link, which is base_link,
// 0.0655 m above the floor): x in [-0.21, 0.21], y in [-0.155, 0.155], z in [0.0655, 0.2495].
// The top scanner's column (x = y = 0) meets no other collision part.
bool outside_jackal_chassis(const model::Vec3& p) {
  return !(std::abs(p.x()) < 0.21 && std::abs(p.y()) < 0.155 && p.z() > 0.0655 && p.z() < 0.2495);
}

std::string turtlebot_catalog() {
  return "name: TurtleBot 4 candidates\nsensor_library: " + source_path("sensors.yaml") +
         "\nrobot:\n  description: " +
         source_path("rigs/robots/turtlebot4_description/urdf/standard/turtlebot4.urdf.xacro") +
         "\n  args: {gazebo: classic}\n  package_paths: [" + source_path("rigs/robots") +
         "]\n  base_link: base_link\n" + kFreeHardware + R"(
area_height: 0.2
distance_of_interest: 2.0
sensors:
  - {sensor: oakd_pro, modes: [depth_640x400_30]}
  - {sensor: realsense_d435, modes: [z16_848x480_30]}
  - {sensor: rplidar_a1m8, modes: [5_5hz]}
  - {sensor: rplidar_a2m8, modes: [10hz]}
slots:
  - id: lidar
    pose: {urdf_link: rplidar_link}
    allows: [rplidar_a1m8, rplidar_a2m8]
  - id: oakd
    pose: {urdf_link: oakd_rgb_camera_frame}
    allows: [oakd_pro, realsense_d435]
  - id: rear_camera
    pose: {xyz: [-0.17, 0, 0.2], rpy_deg: [0, {min: 10, max: 30, step: 20}, 180]}
    allows: [realsense_d435]
)";
}

model::SectorRequirement robot_sector(const char* name, double from_deg, double to_deg,
                                      double complete, double floor) {
  constexpr double kRad = std::numbers::pi / 180.0;
  return {name, from_deg * kRad, to_deg * kRad, complete, floor, {}};
}

// One slot's choices: nothing, or a (sensor, mode, pose) it allows.
struct Choice {
  const model::Sensor* sensor = nullptr;
  const model::SensorMode* mode = nullptr;
  std::size_t pose = 0;
};

// Whether a pose can be built, by a test that shares no code with the program's; none: all.
using Buildable = std::function<bool(const model::Vec3& origin)>;

std::vector<Choice> choices_of(const model::Catalog& catalog, const model::SensorLibrary& library,
                               const model::MountingSlot& slot, const Buildable& buildable) {
  std::vector<Choice> choices = {Choice{}};
  for (const model::CandidateSensor& candidate : catalog.sensors) {
    const auto& allowed = slot.allowed_sensors;
    if (std::find(allowed.begin(), allowed.end(), candidate.sensor_id) == allowed.end()) continue;
    const model::Sensor* sensor = library.find(candidate.sensor_id);
    for (const std::string& mode : candidate.mode_ids) {
      for (std::size_t p = 0; p < slot.poses.size(); ++p) {
        if (buildable && !buildable(slot.poses[p].T_robot_sensor.translation())) continue;
        choices.push_back({sensor, sensor->find_mode(mode), p});
      }
    }
  }
  return choices;
}

// The cheapest passing price over every combination, on the exact path.
double brute_force_cost(const model::Catalog& catalog, const model::SensorLibrary& library,
                        const std::vector<model::SectorRequirement>& sectors,
                        const metrics::CoverageSettings& settings, const Buildable& buildable) {
  std::vector<std::vector<Choice>> slots;
  for (const model::MountingSlot& slot : catalog.slots)
    slots.push_back(choices_of(catalog, library, slot, buildable));
  std::vector<std::size_t> index(slots.size(), 0);
  double best = std::numeric_limits<double>::infinity();
  while (true) {
    model::Rig rig;
    rig.body = catalog.body;
    rig.distance_of_interest = catalog.distance_of_interest;
    double price = 0.0;
    for (std::size_t k = 0; k < slots.size(); ++k) {
      const Choice& choice = slots[k][index[k]];
      if (!choice.sensor) continue;
      model::Mount mount;
      mount.id = catalog.slots[k].id;
      mount.sensor_id = choice.sensor->id;
      mount.mode_id = choice.mode->id;
      mount.T_robot_sensor = catalog.slots[k].poses[choice.pose].T_robot_sensor;
      mount.housing_link = catalog.slots[k].poses[choice.pose].housing_link;
      rig.mounts.push_back(mount);
      price += choice.sensor->price.usd;
    }
    if (price < best && !rig.mounts.empty()) {
      const metrics::RigCoverage coverage =
          metrics::compute_coverage(rig, library, sectors, settings);
      if (std::all_of(coverage.sectors.begin(), coverage.sectors.end(),
                      [](const metrics::SectorCoverage& s) { return s.pass; })) {
        best = price;
      }
    }
    std::size_t k = 0;
    while (k < slots.size() && ++index[k] == slots[k].size()) index[k++] = 0;
    if (k == slots.size()) break;
  }
  return best;
}

void check_against_brute_force(const std::string& catalog_text,
                               const std::vector<std::vector<model::SectorRequirement>>& cases,
                               const Buildable& buildable = {}) {
  TempFolder folder;
  const model::Catalog catalog = io::load_catalog(folder.write("catalog.yaml", catalog_text));
  // The body is the description's collision geometry, not a cylinder.
  REQUIRE(catalog.body.has_parts());
  REQUIRE(catalog.robot);
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  metrics::CoverageSettings settings;
  settings.step = 10.0 * std::numbers::pi / 180.0;  // 36 azimuths
  const select::SelectionSpace space(catalog, library, settings);
  int feasible = 0;
  for (const std::vector<model::SectorRequirement>& sectors : cases) {
    model::Requirements requirements;
    requirements.sectors = sectors;
    requirements.distance = catalog.distance_of_interest;
    const select::Selection selection =
        select::select_cheapest(space, requirements, {}, /*probe=*/true);
    const double expected = brute_force_cost(catalog, library, sectors, settings, buildable);
    INFO("front " << sectors[0].min_complete_coverage << "/" << sectors[0].min_floor_coverage);
    REQUIRE(selection.found == std::isfinite(expected));
    if (!selection.found) continue;
    ++feasible;
    CHECK(selection.cost.sensors == Approx(expected));
    // The chosen rig stands on the same robot: its description and its links.
    CHECK(selection.rig.robot->description == catalog.robot->description);
    CHECK(selection.rig.body.parts.size() == catalog.body.parts.size());
    if (!buildable) continue;
    for (const model::Mount& mount : selection.rig.mounts) {
      INFO(mount.id);
      CHECK(buildable(mount.T_robot_sensor.translation()));
    }
  }
  CHECK(feasible >= 2);
}

}  // namespace

TEST_CASE("select on the Jackal's description equals a brute force on its collision geometry",
          "[select]") {
  check_against_brute_force(
      jackal_catalog(),
      {{robot_sector("front", -20, 20, 0.1, 0.1), robot_sector("back", 160, 200, 0.05, 0.05)},
       {robot_sector("front", -20, 20, 0.5, 0.6), robot_sector("back", 160, 200, 0.0, 0.0)},
       {robot_sector("front", -20, 20, 0.02, 0.0), robot_sector("back", 160, 200, 0.01, 0.0)},
       {robot_sector("front", -20, 20, 0.99, 0.99), robot_sector("back", 160, 200, 0.0, 0.0)}});
}

TEST_CASE(
    "select never buries a sensor in the Jackal's chassis: a brute force over the poses a "
    "hand-computed box leaves agrees",
    "[select]") {
  check_against_brute_force(
      jackal_catalog_with_top_scanner(),
      {{robot_sector("front", -20, 20, 0.1, 0.1), robot_sector("back", 160, 200, 0.05, 0.05)},
       {robot_sector("front", -20, 20, 0.02, 0.0), robot_sector("back", 160, 200, 0.01, 0.0)}},
      outside_jackal_chassis);
}

TEST_CASE(
    "select on the TurtleBot 4's description equals a brute force on its collision "
    "geometry",
    "[select]") {
  check_against_brute_force(
      turtlebot_catalog(),
      {{robot_sector("front", -20, 20, 0.1, 0.1), robot_sector("back", 160, 200, 0.05, 0.05)},
       {robot_sector("front", -20, 20, 0.3, 0.3), robot_sector("back", 160, 200, 0.0, 0.0)},
       {robot_sector("front", -20, 20, 0.02, 0.0), robot_sector("back", 160, 200, 0.01, 0.0)}});
}
