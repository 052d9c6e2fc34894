#include "rigdesign/io/config/requirements_loader.hpp"

#include <algorithm>
#include <set>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

using io::MapReader;
using io::Need;

model::SectorRequirement read_sector(MapReader& reader) {
  model::SectorRequirement sector;
  sector.where = reader.location();
  sector.name = reader.text("name", Need::required, "a sector name such as front").value_or("");
  const std::string angle = "an azimuth in degrees, counter-clockwise from forward, in [-360, 360]";
  const auto from = reader.number("from_deg", Need::required, angle);
  const auto to = reader.number("to_deg", Need::required, angle);
  if (from && to) {
    reader.require(*from >= -360 && *from <= 360, "from_deg", "is out of range", angle);
    reader.require(*to > *from && *to - *from <= 360, "to_deg", "does not follow from_deg",
                   "from_deg < to_deg <= from_deg + 360");
    sector.from = model::deg_to_rad(*from);
    sector.to = model::deg_to_rad(*to);
    io::warn_if_radians(reader, "from_deg", {*from, *to});  // a sector of +-0.52
  }
  const std::string share = "a share of the cross-section in [0, 1]";
  sector.min_complete_coverage =
      io::share(reader, "min_complete_coverage", Need::required, share).value_or(0.0);
  sector.min_floor_coverage =
      io::share(reader, "min_floor_coverage", Need::required, share).value_or(0.0);
  reader.reject_unknown_keys();
  return sector;
}

model::MotionBetweenFrames read_motion(MapReader& reader, const std::string& speed_key) {
  model::MotionBetweenFrames motion;
  motion.where = reader.location();
  motion.speed = io::positive(reader, speed_key, Need::required, "metres per second, > 0");
  motion.travel = io::positive(reader, "max_travel_between_frames", Need::required,
                               "metres moved between two frames, > 0");
  reader.reject_unknown_keys();
  return motion;
}

// robot_speed.deceleration [m/s^2], read before read_motion rejects keys it does not know.
void read_deceleration(MapReader& speed, model::Requirements& requirements) {
  if (!speed.has("deceleration")) return;
  const std::string expected = "braking deceleration in m/s^2, > 0 (e.g. 1.0)";
  requirements.deceleration_where = speed.location("deceleration");
  requirements.deceleration = io::positive(speed, "deceleration", Need::required, expected);
  // Above ~1 g a wheeled robot skids: probably g, cm/s^2 or a typo, not m/s^2.
  constexpr double kSkidLimit = 9.81;
  if (requirements.deceleration && *requirements.deceleration > kSkidLimit) {
    speed.diagnostics().warning(
        speed.location("deceleration"), speed.field("deceleration"),
        "is above 1 g (" + model::format_number(*requirements.deceleration, 4) +
            " m/s^2): a wheeled robot's tyres slip before it brakes that hard",
        "m/s^2; a value in g or cm/s^2 must be converted");
  }
}

void read_lighting(MapReader& top, model::Requirements& requirements) {
  const std::string expected =
      "a list of conditions from: " + model::join(model::names_of(model::kLightConditionNames));
  requirements.lighting_where = top.location("lighting");
  const YAML::Node list = top.node("lighting");
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) {
    top.require(false, "lighting", "is not a list", expected);
    return;
  }
  std::set<std::string> seen;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string field = top.field("lighting") + "[" + std::to_string(i) + "]";
    const std::string value = list[i].IsScalar() ? list[i].Scalar() : "";
    const auto condition = model::value_in(model::kLightConditionNames, value);
    if (!condition || !seen.insert(value).second) {
      top.diagnostics().error(io::location_of(list[i], top.file()), field,
                              !condition ? "unknown condition '" + value + "'"
                                         : "condition '" + value + "' given twice",
                              expected);
      continue;
    }
    requirements.lighting.push_back(*condition);
  }
}

// `robustness: {survive: [n-1, sunlight], sectors: [{name, min_complete_coverage,
// min_floor_coverage}]}`; sector names must be the requirements' own.
model::RobustnessRequirement read_robustness(MapReader& reader,
                                             const std::vector<model::SectorRequirement>& sectors) {
  model::RobustnessRequirement robustness;
  robustness.where = reader.location();
  const std::string expected =
      "a list of failures: n-1 (any one sensor), or a lighting condition "
      "in which every sensor not immune to it fails (" +
      model::join(model::names_of(model::kLightConditionNames)) + ")";
  const YAML::Node list = reader.node("survive");
  if (!list.IsSequence() || list.size() == 0) {
    reader.require(false, "survive", list.IsDefined() ? "is not a non-empty list" : "is missing",
                   expected);
  } else {
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string value = list[i].IsScalar() ? list[i].Scalar() : "";
      const std::string field = reader.field("survive") + "[" + std::to_string(i) + "]";
      if (value == "n-1") {
        robustness.single_failure = true;
      } else if (const auto condition = model::value_in(model::kLightConditionNames, value);
                 condition && !robustness.condition) {
        robustness.condition = *condition;
      } else {
        reader.diagnostics().error(
            io::location_of(list[i], reader.file()), field,
            condition ? "names a second condition" : "unknown failure '" + value + "'", expected);
      }
    }
  }
  const std::string share = "a share of the cross-section in [0, 1]";
  for (MapReader& entry : reader.maps("sectors", Need::optional)) {
    model::SectorRequirement relaxed;
    relaxed.where = entry.location();
    relaxed.name =
        entry.text("name", Need::required, "the name of one of the sectors").value_or("");
    const auto named =
        std::find_if(sectors.begin(), sectors.end(),
                     [&](const model::SectorRequirement& s) { return s.name == relaxed.name; });
    std::vector<std::string> names;
    for (const model::SectorRequirement& sector : sectors) names.push_back(sector.name);
    entry.require(named != sectors.end() || relaxed.name.empty(), "name",
                  "names no sector of these requirements", "one of: " + model::join(names));
    if (named != sectors.end()) {
      relaxed.from = named->from;
      relaxed.to = named->to;
    }
    relaxed.min_complete_coverage =
        io::share(entry, "min_complete_coverage", Need::required, share).value_or(0.0);
    relaxed.min_floor_coverage =
        io::share(entry, "min_floor_coverage", Need::required, share).value_or(0.0);
    entry.reject_unknown_keys();
    robustness.sectors.push_back(relaxed);
  }
  reader.reject_unknown_keys();
  return robustness;
}

}  // namespace

model::Requirements load_requirements(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(path, diagnostics,
                                    "requirements: a map with keys R1-R8 (see rigs/README.md)");
  model::Requirements requirements;
  requirements.file = path;
  requirements.name = top.text("name", Need::required, "the application's name").value_or("");
  if (auto body = top.map("body", Need::optional)) {  // R1
    requirements.body_where = body->location();
    requirements.body_radius = io::positive(*body, "radius", Need::required, "metres, > 0");
    requirements.body_height = io::positive(*body, "height", Need::required, "metres, > 0");
    body->reject_unknown_keys();
  }
  if (top.has("area_height")) {
    requirements.area_height_where = top.location("area_height");
    requirements.area_height = io::positive_length(
        top, "area_height", Need::required, "the top of the area to perceive in metres, > 0");
  }
  std::set<std::string> sector_names;
  for (MapReader& reader : top.maps("sectors", Need::optional)) {  // R2
    model::SectorRequirement sector = read_sector(reader);
    if (!sector.name.empty() && !sector_names.insert(sector.name).second) {
      reader.require(false, "name", "duplicate sector '" + sector.name + "'", "unique names");
    }
    requirements.sectors.push_back(std::move(sector));
  }
  if (auto range = top.map("range", Need::required, "a map with distance (R3)")) {  // R3
    requirements.range_where = range->location();
    requirements.distance = io::positive(*range, "distance", Need::required,
                                         "the distance of interest d in metres, > 0");
    if (range->has("min_frequency")) {
      requirements.min_frequency =
          io::positive(*range, "min_frequency", Need::required, "frames per second [Hz], > 0");
    }
    range->reject_unknown_keys();
  }
  if (auto dynamics = top.map("object_dynamics", Need::optional)) {  // R4
    requirements.object_dynamics = read_motion(*dynamics, "max_object_speed");
  }
  if (auto speed = top.map("robot_speed", Need::optional)) {  // R5
    read_deceleration(*speed, requirements);
    requirements.robot_speed = read_motion(*speed, "max_speed");
  }
  if (auto obstacle = top.map("smallest_obstacle", Need::optional)) {  // R6
    requirements.smallest_obstacle_where = obstacle->location();
    requirements.smallest_obstacle =
        io::positive(*obstacle, "size", Need::required, "the obstacle's size in metres, > 0");
    obstacle->reject_unknown_keys();
  }
  if (auto accuracy = top.map("accuracy", Need::optional)) {  // R7
    requirements.accuracy_where = accuracy->location();
    requirements.max_noise = io::positive(*accuracy, "max_noise", Need::required,
                                          "one-sigma range noise at d in metres, > 0");
    accuracy->reject_unknown_keys();
  }
  read_lighting(top, requirements);  // R8
  if (auto robustness = top.map("robustness", Need::optional, "a map with survive (and sectors)")) {
    requirements.robustness = read_robustness(*robustness, requirements.sectors);
  }
  if (auto calibration =
          top.map("calibration", Need::optional, "a map with pairs and min_overlap_m2")) {
    model::CalibrationRequirement needed;
    needed.where = calibration->location();
    needed.all_pairs = calibration->choice("pairs", Need::required, {"connected", "all"}) == 1U;
    needed.min_overlap = io::positive(*calibration, "min_overlap_m2", Need::required,
                                      "the co-visible area a pair needs, in square metres, > 0");
    calibration->reject_unknown_keys();
    requirements.calibration = needed;
  }
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  requirements.load_warnings = diagnostics.items();
  return requirements;
}

}  // namespace rigdesign::io
