#pragma once
/// Paper 4's KPIs: smallest, mean and RMS error, the data amount C (Algorithm 1: how many
/// measurements it takes until the estimate is within the acceptable error) and the detection
/// percentage (share of runs whose estimate lies within the acceptable error).
#include <optional>
#include <utility>
#include <vector>

#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct KpiParams {
  /// An estimate this close to the truth counts as a detection [m] (DARPA SubT scored reports
  /// within 5 m).
  double acceptable_error = 5.0;
  /// For nls and map, the running estimate is recomputed at this many evenly spaced reading
  /// counts (wls updates after every reading, in O(1)); 0: final KPIs only.
  int checkpoints = 50;
};

struct ErrorStats {
  int count = 0;
  double smallest = 0.0;  ///< [m]
  double mean = 0.0;      ///< [m]
  double median = 0.0;    ///< [m]
  double rms = 0.0;       ///< [m]
};

/// Statistics of a list of errors (all 0 and count 0 when empty).
ErrorStats error_stats(std::vector<double> errors);

/// Error of an estimate against the truth: horizontal when z is unobservable (dimensions 2).
double position_error(const model::Vec3& estimate, const model::Vec3& truth, int dimensions);

/// Paper 4's Algorithm 1: given (measurements consumed, error of the estimate then) in order,
/// the first count whose error is within `acceptable`; empty when none is.
std::optional<int> data_amount(const std::vector<std::pair<int, double>>& errors_by_count,
                               double acceptable);

struct EmitterKpis {
  double final_error = 0.0;  ///< of the first hypothesis at the end of the log [m]
  /// Probability-weighted over the hypotheses: the error of the stated belief, which does not
  /// depend on how ambiguous hypotheses happen to be ordered [m].
  double expected_error = 0.0;
  bool in_region = false;  ///< the truth lies in the stated 95 % region (in_stated_region)
  /// The smallest credible level whose highest-density region holds the truth (nls, map): over
  /// many runs, uniform in [0, 1] when the stated uncertainty is honest.
  std::optional<double> credible_level;
  double nearest_hypothesis_error = 0.0;  ///< of whichever hypothesis is nearest the truth [m]
  ErrorStats running;                     ///< errors of the running estimate over the log
  std::optional<int> data_amount;         ///< C, in readings of this emitter
  bool detected = false;                  ///< final_error within the acceptable error
  double heard_share = 0.0;  ///< readings at or above the cut-off over all its readings
};

/// KPIs of `method` on emitter `emitter` of `log` with its true position. `final_estimate` is
/// the method's result on the whole log.
EmitterKpis evaluate_emitter(const RssiLog& log, int emitter, const model::Vec3& truth,
                             const EmitterEstimate& final_estimate, const LocalizeParams& params,
                             const KpiParams& kpi = {});

}  // namespace rigdesign::localize
