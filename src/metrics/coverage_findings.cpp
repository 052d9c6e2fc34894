#include "rigdesign/metrics/coverage_findings.hpp"

#include <algorithm>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::metrics {
namespace {

bool limits(const Limiting& limiting, const std::string& mount_id) {
  return std::find(limiting.mounts.begin(), limiting.mounts.end(), mount_id) !=
         limiting.mounts.end();
}

}  // namespace

std::vector<model::Diagnostic> coverage_findings(const model::Rig& rig,
                                                 const ResultantMetrics& resultant,
                                                 const RigCoverage& coverage) {
  std::vector<model::Diagnostic> findings;
  for (std::size_t i = 0; i < coverage.mount_ids.size() && i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const bool sees_some = std::any_of(coverage.angles.begin(), coverage.angles.end(),
                                       [i](const AngleCoverage& a) { return a.mount_sees[i]; });
    if (!sees_some) {
      std::vector<std::string> set;
      if (limits(resultant.frequency, mount.id)) set.push_back("F");
      if (limits(resultant.point_spacing, mount.id)) set.push_back("R");
      if (limits(resultant.noise, mount.id)) set.push_back("N");
      findings.emplace_back(
          mount.pose_where, "mounts[" + std::to_string(i) + "]",
          "mount '" + mount.id + "' sees 0 % of the area to perceive (rho in [r, d], z in [0, " +
              model::format_number(coverage.height) + "] m)" +
              (set.empty() ? std::string()
                           : " but sets " + model::join(set) + " for the whole rig"),
          "a pose that looks into the area, or a different area_height", model::Severity::warning);
    }
  }
  return findings;
}

}  // namespace rigdesign::metrics
