#include "rigdesign/metrics/tolerance_verdicts.hpp"

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::metrics {
namespace {

std::string tolerance_percent(double share) {
  return model::format_number(share * 100, 4) + " %";
}

std::string worst_errors_text(const WorstShare& worst) {
  std::vector<std::string> errors;
  for (const MountError& error : worst.errors)
    errors.push_back(error.mount_id + ": " + error_text(error.error));
  return errors.empty() ? "no error lowers it" : model::join(errors, "; ");
}

// The tolerance a reviewer would widen or tighten: that of the first mount in `worst`.
model::SourceLocation tolerance_line(const model::Rig& rig, const WorstShare& worst) {
  for (const MountError& error : worst.errors) {
    const model::Mount* mount = rig.find_mount(error.mount_id);
    const model::PoseTolerance* tolerance = mount ? rig.tolerance_for(*mount) : nullptr;
    if (tolerance != nullptr) return tolerance->where;
  }
  return rig.tolerance ? rig.tolerance->where : rig.where;
}

}  // namespace

std::string error_text(const PoseError& error) {
  std::vector<std::string> parts;
  const char* axes[] = {"x", "y", "z"};
  const char* turns[] = {"roll", "pitch", "yaw"};
  const auto sign = [](double v) { return v > 0 ? "+" : ""; };
  for (int i = 0; i < 3; ++i) {
    if (error.xyz[i] != 0)
      parts.push_back(std::string(axes[i]) + " " + sign(error.xyz[i]) +
                      model::format_number(error.xyz[i] * 1000, 4) + " mm");
  }
  for (int i = 0; i < 3; ++i) {
    if (error.rpy[i] != 0)
      parts.push_back(std::string(turns[i]) + " " + sign(error.rpy[i]) +
                      model::format_number(model::rad_to_deg(error.rpy[i]), 4) + " deg");
  }
  if (error.narrowest_fov) parts.push_back("FOV at its datasheet narrowest");
  return parts.empty() ? "nominal" : model::join(parts);
}

std::vector<RequirementResult> tolerance_verdicts(const model::Rig& rig,
                                                  const std::vector<SectorTolerance>& sectors) {
  std::vector<RequirementResult> results;
  for (const SectorTolerance& sector : sectors) {
    RequirementResult result;
    result.id = "R2";
    result.title = "direction of motion: " + sector.sector.name + ", over mounting tolerance";
    result.field = "sectors." + sector.sector.name;
    result.where = sector.sector.where;
    const bool floor = sector.floor_binds();
    const WorstShare& binding = floor ? sector.floor : sector.complete;
    result.metric = floor ? "SC floor" : "SC";
    result.required =
        floor ? sector.sector.min_floor_coverage : sector.sector.min_complete_coverage;
    result.actual = binding.share;
    result.bound = Bound::at_least;
    result.verdict = sector.pass ? Verdict::pass : Verdict::fail;
    for (const MountError& error : binding.errors) result.limiting_mounts.push_back(error.mount_id);
    result.rig_where = tolerance_line(rig, binding);
    result.explanation =
        "worst over the tolerance boxes: SC complete " +
        tolerance_percent(sector.nominal_complete) + " -> " +
        tolerance_percent(sector.complete.share) + " (" + worst_errors_text(sector.complete) +
        ") >= " + tolerance_percent(sector.sector.min_complete_coverage) + ", SC floor " +
        tolerance_percent(sector.nominal_floor) + " -> " + tolerance_percent(sector.floor.share) +
        " (" + worst_errors_text(sector.floor) +
        ") >= " + tolerance_percent(sector.sector.min_floor_coverage);
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace rigdesign::metrics
