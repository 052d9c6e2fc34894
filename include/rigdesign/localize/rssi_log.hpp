#pragma once
/// A robot's Wi-Fi log: where the robot was and how strongly it heard each emitter (BSSID).
///
/// File form (CSV, UTF-8, one reading per line), header first:
///     t,x,y,z,bssid,rssi
///     0.0,1.25,-3.0,0.4,aa:bb:cc:dd:ee:ff,-61
/// t [s], x y z [m] (the robot's antenna in the map frame), rssi [dBm, <= 0]. Columns may
/// come in any order and extra columns are ignored; blank lines and lines starting with '#'
/// are skipped. Errors name file:line:column, where column is the 1-based character column
/// at which the offending field starts, and the field is the column's header name.
///
/// Scans that did not hear an emitter: a line with an empty rssi field (`12,3.1,-0.2,0.4,
/// aa:bb:cc:dd:ee:ff,`) says the robot scanned there and the emitter was below the receiver's
/// floor. That is information (the emitter was far), which the range fit uses. Two comment
/// lines carry the receiver's properties: `# floor_dbm: -95` (the weakest level the radio
/// reports) and `# scan_period_s: 1` (seconds between scans); both are optional.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct RssiReading {
  double t = 0.0;        ///< [s]
  model::Vec3 position;  ///< robot antenna position [m]
  int emitter = 0;       ///< index into RssiLog::emitters
  double rssi_dbm = 0;   ///< [dBm]; meaningless when not heard
  /// False for a scan that did not hear the emitter (below the receiver's floor).
  bool heard = true;
};

struct RssiLog {
  std::string source;                   ///< file name, for messages and plots
  std::vector<std::string> emitters;    ///< BSSIDs in order of first appearance
  std::vector<RssiReading> readings;    ///< in file order
  std::optional<double> floor_dbm;      ///< `# floor_dbm:` of the file [dBm]
  std::optional<double> scan_period_s;  ///< `# scan_period_s:` of the file [s]

  /// Index of `bssid` in emitters, or -1.
  int find(const std::string& bssid) const;
};

}  // namespace rigdesign::localize
