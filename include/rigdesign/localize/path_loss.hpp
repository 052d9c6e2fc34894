#pragma once
/// Log-distance path-loss model (paper 4; DESIGN.md section 8): rssi = a - 10 n log10(r),
/// so r = 10^((a - rssi) / (10 n)). Paper 4's methods (wls, map) drop readings at or below the
/// cut-off: the thesis keeps a reading only when it is stronger than -80 dBm ("-80 dBm or worse"
/// is dropped). passes_cutoff is the one test every user of the cut-off calls.
namespace rigdesign::localize {

struct PathLossParams {
  /// RSSI at 1 m [dBm]. Paper 4 calibrates a per phone; its value is not quoted in
  /// DESIGN.md, so this default is an assumption for a phone's Wi-Fi hotspot.
  double rssi_at_1m_dbm = -45.0;
  /// Path-loss exponent n (2 in free space, 2-4 indoors); assumed, as above.
  double exponent = 2.5;
  /// Readings at or below this are dropped [dBm] (paper 4: "-80 dBm or worse").
  double cutoff_dbm = -80.0;
};

/// Whether paper 4's methods use a reading of `rssi_dbm`: strictly stronger than the cut-off.
inline bool passes_cutoff(double rssi_dbm, const PathLossParams& params) {
  return rssi_dbm > params.cutoff_dbm;
}

/// Distance [m] at which the model predicts `rssi_dbm`.
double range_from_rssi(double rssi_dbm, const PathLossParams& params);

/// RSSI [dBm] the model predicts at `range` [m] (> 0).
double rssi_at_range(double range, const PathLossParams& params);

}  // namespace rigdesign::localize
