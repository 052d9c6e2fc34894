#include "rigdesign/metrics/mount_placement_verdicts.hpp"

#include "rigdesign/geometry/mount_placement.hpp"

namespace rigdesign::metrics {

std::vector<RequirementResult> placement_verdicts(const model::Rig& rig) {
  std::vector<RequirementResult> results;
  for (const model::Mount& mount : rig.mounts) {
    RequirementResult result;
    result.id = "B1";
    result.title = "mounted outside the body: " + mount.id;
    result.field = "pose";
    result.metric = "placement";
    result.where = mount.pose_where;
    result.rig_where = mount.pose_where;
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
    results.push_back(std::move(result));
  }
  return results;
}

std::vector<model::Diagnostic> placement_warnings(const model::Rig& rig) {
  std::vector<model::Diagnostic> warnings;
  for (const RequirementResult& result : placement_verdicts(rig)) {
    if (result.verdict != Verdict::fail) continue;
    warnings.emplace_back(result.where, "pose", result.explanation + " (check: B1)",
                          "a sensor origin outside the robot body", model::Severity::warning);
  }
  return warnings;
}

}  // namespace rigdesign::metrics
