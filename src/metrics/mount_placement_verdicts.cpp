#include "rigdesign/metrics/mount_placement_verdicts.hpp"

#include <cmath>

#include "rigdesign/geometry/housing_clearance.hpp"
#include "rigdesign/geometry/mount_placement.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::metrics {
namespace {

RequirementResult placement_result(const model::Mount& mount, const std::string& id,
                                   const std::string& title) {
  RequirementResult result;
  result.id = id;
  result.title = title + mount.id;
  result.field = "pose";
  result.metric = "placement";
  result.where = mount.pose_where;
  result.rig_where = mount.pose_where;
  return result;
}

RequirementResult burial_verdict(const model::Rig& rig, const model::Mount& mount) {
  RequirementResult result = placement_result(mount, "B1", "mounted outside the body: ");
  const std::optional<geometry::Burial> buried =
      geometry::burial(rig, mount.housing_link, mount.T_robot_sensor.translation());
  if (buried) {
    result.verdict = Verdict::fail;
    result.limiting_mounts = {mount.id};
    result.explanation = "the sensor's data origin is " + buried->describe() +
                         ": it sees nothing through it, and no sensor can be bolted there";
  } else {
    result.explanation = mount.housing_link.empty()
                             ? "the data origin is on or outside the body"
                             : "the data origin is outside the body but for its housing '" +
                                   mount.housing_link + "'";
  }
  return result;
}

RequirementResult clearance_verdict(const model::Rig& rig, const model::SensorLibrary& library,
                                    std::size_t index) {
  const model::Mount& mount = rig.mounts[index];
  RequirementResult result = placement_result(mount, "B2", "housing clear of body and sensors: ");
  const std::vector<geometry::HousingClash> clashes =
      geometry::housing_clashes(rig, library, index);
  if (clashes.empty()) {
    result.explanation =
        "its housing (sensors.yaml) cuts into neither the body nor another "
        "sensor's housing";
    return result;
  }
  result.verdict = Verdict::fail;
  result.limiting_mounts = {mount.id};
  result.explanation = "its housing (sensors.yaml)";
  for (std::size_t c = 0; c < clashes.size(); ++c) {
    result.explanation += (c == 0 ? " " : "; ") + clashes[c].describe();
    if (!clashes[c].mount_id.empty()) result.limiting_mounts.push_back(clashes[c].mount_id);
  }
  result.explanation += ": no sensor can be bolted there (move it out until the solids only touch)";
  return result;
}

}  // namespace

std::vector<RequirementResult> placement_verdicts(const model::Rig& rig,
                                                  const model::SensorLibrary& library) {
  std::vector<RequirementResult> results;
  for (const model::Mount& mount : rig.mounts) results.push_back(burial_verdict(rig, mount));
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const model::Sensor* sensor = library.find(rig.mounts[m].sensor_id);
    if (sensor != nullptr && sensor->housing) results.push_back(clearance_verdict(rig, library, m));
  }
  return results;
}

std::vector<model::Diagnostic> floating_warnings(const model::Rig& rig,
                                                 const model::SensorLibrary& library) {
  std::vector<model::Diagnostic> warnings;
  for (std::size_t m = 0; m < rig.mounts.size(); ++m) {
    const std::optional<double> gap = geometry::housing_gap(rig, library, m);
    if (!gap) continue;
    const model::Mount& mount = rig.mounts[m];
    // Millimetres as a technician measures them; 0.5 m means nothing near at all.
    const std::string distance =
        *gap >= 0.5 ? "more than 500 mm"
                    : "about " + model::format_number(std::round(1000 * *gap)) + " mm";
    warnings.emplace_back(
        mount.pose_where.file.empty() ? mount.where : mount.pose_where, "pose",
        mount.id + "'s housing (sensors.yaml) floats " + distance +
            " from the body, every description link, every other housing and every support: "
            "nothing holds it",
        "a housing that touches what holds it, or a bracket or mast built to "
        "the gap",
        model::Severity::warning);
  }
  return warnings;
}

std::vector<model::Diagnostic> placement_warnings(const model::Rig& rig,
                                                  const model::SensorLibrary& library) {
  std::vector<model::Diagnostic> warnings = floating_warnings(rig, library);
  for (const RequirementResult& result : placement_verdicts(rig, library)) {
    if (result.verdict != Verdict::fail) continue;
    warnings.emplace_back(result.where, "pose", result.explanation + " (check: " + result.id + ")",
                          result.id == "B1" ? "a sensor origin outside the robot body"
                                            : "housings clear of the body and of each other",
                          model::Severity::warning);
  }
  return warnings;
}

}  // namespace rigdesign::metrics
