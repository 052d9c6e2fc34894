#pragma once
/// Crosstalk between active sensors (issue 38, item 2): for every pair of mounts that both send
/// light (sensors.yaml `emitter`), whether one's lit region lies in the other's view (their
/// co-visible area, metrics/covisibility.hpp, above zero) and what the rig does about it.
/// A pair is looked at when they share a point and their wavelengths are unknown or within
/// kFilterPassband of each other (a receiver's band-pass filter is assumed no wider: light
/// farther off is not demodulated). Vendors' statements are about several units of their own
/// sensor, so two mounts of one model are judged (check's D5): a failure when the vendor says
/// units interfere and the rig states no measure both support (one `sync` group with capture
/// offsets at least `min_delay` apart where the sensor needs one, or different modulation
/// `channel`s); a pass when the vendor says they do not, or the measure holds; a warning when
/// the vendor says nothing. Two different cameras that flood the scene (ToF, structured light,
/// active stereo) get a warning unless a measure is stated: no statement covers the pair.
/// Scanners of different models are not judged (narrow pulses; no vendor statement found).
#include <vector>

#include "rigdesign/metrics/covisibility.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::metrics {

/// [m] Emitters farther apart in wavelength than this are not judged (an assumption about the
/// receivers' optical filters, stated in docs/crosstalk.md; no vendor publishes the widths).
inline constexpr double kFilterPassband = 50e-9;

struct CrosstalkFindings {
  std::vector<RequirementResult> verdicts;  ///< D5, one per judged pair
  std::vector<model::Diagnostic> warnings;  ///< pairs whose vendors say nothing
};

/// `overlap` must be covisibility() of the same rig.
CrosstalkFindings crosstalk_findings(const model::Rig& rig, const model::SensorLibrary& library,
                                     const Covisibility& overlap);

/// The rig's pairs, computed: covisibility out to covisibility_distance(rig).
CrosstalkFindings crosstalk_findings(const model::Rig& rig, const model::SensorLibrary& library);

}  // namespace rigdesign::metrics
