#include "rigdesign/metrics/pair_findings.hpp"

#include <algorithm>

#include "rigdesign/metrics/calibration_overlap.hpp"
#include "rigdesign/metrics/covisibility.hpp"
#include "rigdesign/metrics/crosstalk.hpp"

namespace rigdesign::metrics {

PairFindings pair_findings(const model::Rig& rig, const model::SensorLibrary& library,
                           const model::Requirements* requirements) {
  const bool calibration = requirements != nullptr && requirements->calibration.has_value();
  const auto active =
      std::count_if(rig.mounts.begin(), rig.mounts.end(), [&](const model::Mount& m) {
        return library.resolved_mode(m.sensor_id, m.mode_id).emitter.has_value();
      });
  PairFindings findings;
  if (rig.mounts.size() < 2 || (active < 2 && !calibration)) {
    if (calibration && rig.mounts.size() < 2) {
      // One sensor has nothing to be calibrated to: connected by definition.
      findings.verdicts.push_back(calibration_verdict(rig, *requirements->calibration,
                                                      Covisibility{rig.mount_ids(), {}, 0, 0}));
    }
    return findings;
  }
  const Covisibility overlap = covisibility(rig, library, covisibility_distance(rig));
  CrosstalkFindings crosstalk = crosstalk_findings(rig, library, overlap);
  findings.verdicts = std::move(crosstalk.verdicts);
  findings.warnings = std::move(crosstalk.warnings);
  if (calibration)
    findings.verdicts.push_back(calibration_verdict(rig, *requirements->calibration, overlap));
  return findings;
}

}  // namespace rigdesign::metrics
