#pragma once
/// Log-distance path-loss model (paper 4; DESIGN.md section 8): rssi = a - 10 n log10(r),
/// so r = 10^((a - rssi) / (10 n)). Readings below the cut-off are dropped by both
/// estimators, as paper 4 does.
namespace rigdesign::localize {

struct PathLossParams {
  /// RSSI at 1 m [dBm]. Paper 4 calibrates a per phone; its value is not quoted in
  /// DESIGN.md, so this default is an assumption for a phone's Wi-Fi hotspot.
  double rssi_at_1m_dbm = -45.0;
  /// Path-loss exponent n (2 in free space, 2-4 indoors); assumed, as above.
  double exponent = 2.5;
  /// Readings weaker than this are dropped [dBm] (paper 4: -80 dBm).
  double cutoff_dbm = -80.0;
};

/// Distance [m] at which the model predicts `rssi_dbm`.
double range_from_rssi(double rssi_dbm, const PathLossParams& params);

/// RSSI [dBm] the model predicts at `range` [m] (> 0).
double rssi_at_range(double range, const PathLossParams& params);

}  // namespace rigdesign::localize
