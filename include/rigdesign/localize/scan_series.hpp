#pragma once
/// One emitter's scans in time order, heard or not. A receiver reports nothing below its floor,
/// so a scan that did not hear the emitter says "weaker than the floor here": the range fit
/// treats it as a censored reading rather than as no data (which would bias the estimate away
/// from the path, where the weak readings are missing).
///
/// Where the unheard scans come from, in order of trust:
/// - explicit log lines with an empty rssi (the robot logged the scan and the track);
/// - scans of other emitters at times this one was not heard (the same scan, heard nothing);
/// - gaps in the log's timeline longer than the scan period: the missed scans are placed on
///   the straight line between the scans around the gap, but only where the robot drove
///   straight (the chord is at least `min_straightness` of what the robot's median speed covers
///   in that time). Across a bend the positions are unknown; those scans are counted and left
///   out (a log with empty-rssi lines avoids that).
#include <optional>
#include <vector>

#include "rigdesign/localize/rssi_log.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct Scan {
  double t = 0.0;                              ///< [s]
  model::Vec3 position = model::Vec3::Zero();  ///< robot antenna [m]
  double rssi_dbm = 0.0;                       ///< [dBm]; meaningless when not heard
  bool heard = true;
};

enum class FloorSource { log, option, weakest_reading };

struct ScanSeriesParams {
  std::optional<double> floor_dbm;      ///< overrides the log's `# floor_dbm:` [dBm]
  std::optional<double> scan_period_s;  ///< overrides the log's `# scan_period_s:` [s]
  /// A gap is filled with scans on its chord only when the chord is at least this share of the
  /// distance the robot covers at its median speed in the gap's time.
  double min_straightness = 0.9;
};

struct ScanSeries {
  std::vector<Scan> scans;  ///< in time order
  double floor_dbm = 0.0;   ///< what an unheard scan is below [dBm]
  FloorSource floor_source = FloorSource::weakest_reading;
  double scan_period_s = 0.0;  ///< given, or the median step of the log's timeline [s]
  int heard = 0;
  int unheard_logged = 0;        ///< empty-rssi lines and other emitters' scans
  int unheard_interpolated = 0;  ///< placed in straight gaps of the timeline
  int unheard_unplaced = 0;      ///< in gaps across bends: left out
};

/// The scans of emitter `emitter` of `log`. The floor: the option, else the log's comment,
/// else the weakest reading of any emitter in the log (what the receiver reported at least).
ScanSeries scan_series(const RssiLog& log, int emitter, const ScanSeriesParams& params = {});

std::string to_string(FloorSource source);

}  // namespace rigdesign::localize
