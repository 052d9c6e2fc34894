#include "rigdesign/localize/log_generator.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::localize {
namespace {

constexpr const char* kPhoneBssid = "02:00:00:00:00:01";  // a locally administered address

struct Layout {
  std::string description;
  std::vector<model::Vec2> waypoints;
  model::Vec2 phone;
  std::vector<WallSegment> walls;
};

// Paper 4's outdoor test: circle the phone at about 12 m, then approach it to 5 m.
Layout loop_layout() {
  Layout layout;
  layout.description = "circle the phone at 12 m outdoors, then approach it to 5 m";
  const model::Vec2 centre(0, 0);
  layout.phone = {1.0, -0.8};
  constexpr double kRadius = 12.0;
  constexpr int kSegments = 120;
  for (int i = 0; i <= kSegments; ++i) {
    const double angle = 2 * std::numbers::pi * i / kSegments;
    layout.waypoints.push_back(centre + kRadius * model::Vec2(std::cos(angle), std::sin(angle)));
  }
  const model::Vec2 start = layout.waypoints.back();
  const model::Vec2 towards = (layout.phone - start).normalized();
  layout.waypoints.push_back(layout.phone - 5.0 * towards);
  return layout;
}

// Around a corner: an L-shaped corridor 3 m wide; the phone lies in the second leg, hidden
// from the first by the inner corner's walls.
Layout corner_layout(const ScenarioParams& p) {
  Layout layout;
  layout.description = "an L-shaped corridor; the phone is around the corner";
  layout.waypoints = {{-20, 0}, {0, 0}, {0, 20}};
  layout.phone = {-0.8, 10.0};
  layout.walls = {{{-30, 1.5}, {-1.5, 1.5}, p.wall_attenuation_db},
                  {{-1.5, 1.5}, {-1.5, 30}, p.wall_attenuation_db}};
  return layout;
}

// A room behind a closed door: the robot drives along the corridor past the door and turns
// along the room's far side.
Layout room_layout(const ScenarioParams& p) {
  Layout layout;
  layout.description =
      "a closed room beside the corridor; the robot passes its door and turns along its side";
  layout.waypoints = {{-15, 0}, {10, 0}, {10, 12}};
  layout.phone = {1.0, 5.0};
  const double wall = p.wall_attenuation_db;
  layout.walls = {{{-3, 2}, {-0.5, 2}, wall}, {{-0.5, 2}, {0.5, 2}, p.door_attenuation_db},
                  {{0.5, 2}, {3, 2}, wall},   {{3, 2}, {3, 8}, wall},
                  {{3, 8}, {-3, 8}, wall},    {{-3, 8}, {-3, 2}, wall}};
  return layout;
}

// A straight hallway past the phone: the collinear case.
Layout hallway_layout() {
  Layout layout;
  layout.description = "a straight hallway past the phone (collinear positions)";
  layout.waypoints = {{-20, 0}, {20, 0}};
  layout.phone = {2.0, 3.0};
  return layout;
}

}  // namespace

const std::vector<std::string>& scenario_names() {
  static const std::vector<std::string> names = {"loop", "corner", "room", "hallway"};
  return names;
}

Scenario make_scenario(const std::string& name, const ScenarioParams& params) {
  Layout layout;
  if (name == "loop") {
    layout = loop_layout();
  } else if (name == "corner") {
    layout = corner_layout(params);
  } else if (name == "room") {
    layout = room_layout(params);
  } else if (name == "hallway") {
    layout = hallway_layout();
  } else {
    throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                              "--scenario",
                                              "unknown scenario '" + name + "'",
                                              model::join(scenario_names(), ", ")});
  }
  Scenario scenario;
  scenario.name = name;
  scenario.description = layout.description;
  if (params.wall_attenuation_db > 0) scenario.walls = layout.walls;
  const model::Vec3 phone(layout.phone.x(), layout.phone.y(), params.emitter_height);
  scenario.truth.push_back({kPhoneBssid, phone});
  scenario.log.source = "scenario " + name + " seed " + std::to_string(params.seed);
  scenario.log.emitters.push_back(kPhoneBssid);
  scenario.log.floor_dbm = params.sensitivity_dbm;
  scenario.log.scan_period_s = 1.0 / params.scan_rate;
  for (const model::Vec2& w : layout.waypoints)
    scenario.path.emplace_back(w.x(), w.y(), params.antenna_height);

  std::mt19937_64 random(params.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  PathLossParams truth_model = params.path_loss;
  truth_model.rssi_at_1m_dbm += params.tx_offset_db;
  const double spacing = params.speed / params.scan_rate;
  double shadowing = params.shadowing_db * normal(random);
  const double rho = std::exp(-spacing / params.decorrelation_distance);
  double t = 0.0;
  for (std::size_t leg = 0; leg + 1 < scenario.path.size(); ++leg) {
    const model::Vec3 from = scenario.path[leg], to = scenario.path[leg + 1];
    const double length = (to - from).norm();
    for (double s = 0.0; s < length; s += spacing) {
      const model::Vec3 robot = from + (to - from) * (s / length);
      // Gudmundson's model: AR(1) along the travelled distance keeps the marginal sigma.
      shadowing = rho * shadowing + std::sqrt(1 - rho * rho) * params.shadowing_db * normal(random);
      const double rssi = rssi_at_range((phone - robot).norm(), truth_model) -
                          wall_loss_db(scenario.walls, robot, phone) + shadowing;
      model::Vec3 logged = robot;
      logged.x() += params.position_noise * normal(random);
      logged.y() += params.position_noise * normal(random);
      // Radios report whole dBm; a scan below the floor is logged without a value.
      const bool heard = rssi >= params.sensitivity_dbm;
      scenario.log.readings.push_back(
          {t, logged, 0, heard ? std::min(std::round(rssi), 0.0) : 0.0, heard});
      t += 1.0 / params.scan_rate;
    }
  }
  return scenario;
}

}  // namespace rigdesign::localize
