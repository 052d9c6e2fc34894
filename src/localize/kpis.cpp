#include "rigdesign/localize/kpis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rigdesign/localize/wls_multilateration.hpp"
#include "rigdesign/model/statistics.hpp"

namespace rigdesign::localize {
namespace {

// Errors of the running estimate after each reading (wls: O(1) per reading) or at
// checkpoints (nls, map: a full solve on the chunks so far).
std::vector<std::pair<int, double>> running_errors(const RssiLog& log, int emitter,
                                                   const model::Vec3& truth,
                                                   const EmitterEstimate& final_estimate,
                                                   const LocalizeParams& params,
                                                   const KpiParams& kpi) {
  const int dimensions = final_estimate.geometry.dimensions;
  std::vector<std::pair<int, double>> errors;
  if (final_estimate.method == LocalizeMethod::wls) {
    IncrementalWls wls(params.path_loss, params.chunking);
    int count = 0;
    for (const RssiReading& reading : log.readings) {
      if (reading.emitter != emitter) continue;
      ++count;
      if (!reading.heard || !wls.add(reading.position, reading.rssi_dbm)) continue;
      if (const auto solution = wls.solve(dimensions)) {
        errors.emplace_back(count, position_error(solution->position, truth, dimensions));
      }
    }
    return errors;
  }
  const int total = final_estimate.readings;
  const int checkpoints = std::max(1, std::min(kpi.checkpoints, total));
  if (checkpoints <= 0 || kpi.checkpoints <= 0) return errors;
  ChunkAccumulator accumulator(params.chunking);
  int count = 0, next = 1;
  for (std::size_t line = 0; line < log.readings.size(); ++line) {
    const RssiReading& reading = log.readings[line];
    if (reading.emitter != emitter) continue;
    ++count;
    if (reading.heard && passes_cutoff(reading.rssi_dbm, params.path_loss)) {
      accumulator.add(reading.position, range_from_rssi(reading.rssi_dbm, params.path_loss),
                      reading.rssi_dbm);
    }
    if (count * checkpoints < next * total) continue;
    ++next;
    EmitterEstimate estimate;
    if (final_estimate.method == LocalizeMethod::nls) {
      // The range fit reads scans, heard or not: the log as it stood after this reading.
      RssiLog prefix;
      prefix.source = log.source;
      prefix.emitters = log.emitters;
      prefix.floor_dbm = log.floor_dbm;
      prefix.scan_period_s = log.scan_period_s;
      prefix.readings.assign(log.readings.begin(),
                             log.readings.begin() + static_cast<std::ptrdiff_t>(line + 1));
      estimate = localize_emitter(prefix, emitter, LocalizeMethod::nls, params);
    } else {
      estimate = estimate_from_chunks(accumulator.chunks(), final_estimate.method, params);
    }
    if (!estimate.hypotheses.empty()) {
      errors.emplace_back(count,
                          position_error(estimate.hypotheses.front().position, truth, dimensions));
    }
  }
  return errors;
}

}  // namespace

ErrorStats error_stats(std::vector<double> errors) {
  ErrorStats stats;
  stats.count = static_cast<int>(errors.size());
  if (errors.empty()) return stats;
  std::sort(errors.begin(), errors.end());
  double sum = 0.0, squares = 0.0;
  for (const double e : errors) {
    sum += e;
    squares += e * e;
  }
  const std::size_t n = errors.size();
  stats.smallest = errors.front();
  stats.mean = sum / static_cast<double>(n);
  stats.rms = std::sqrt(squares / static_cast<double>(n));
  stats.median = model::median(errors);
  return stats;
}

double position_error(const model::Vec3& estimate, const model::Vec3& truth, int dimensions) {
  const model::Vec3 offset = estimate - truth;
  return dimensions == 3 ? offset.norm() : std::hypot(offset.x(), offset.y());
}

std::optional<int> data_amount(const std::vector<std::pair<int, double>>& errors_by_count,
                               double acceptable) {
  for (const auto& [count, error] : errors_by_count) {
    if (error <= acceptable) return count;
  }
  return std::nullopt;
}

EmitterKpis evaluate_emitter(const RssiLog& log, int emitter, const model::Vec3& truth,
                             const EmitterEstimate& final_estimate, const LocalizeParams& params,
                             const KpiParams& kpi) {
  EmitterKpis kpis;
  const int dimensions = final_estimate.geometry.dimensions;
  kpis.heard_share = final_estimate.readings > 0
                         ? static_cast<double>(final_estimate.used) / final_estimate.readings
                         : 0.0;
  if (final_estimate.hypotheses.empty()) {
    kpis.final_error = kpis.nearest_hypothesis_error = kpis.expected_error =
        std::numeric_limits<double>::infinity();
  } else {
    kpis.final_error =
        position_error(final_estimate.hypotheses.front().position, truth, dimensions);
    kpis.nearest_hypothesis_error = kpis.final_error;
    double weighted = 0.0, probability = 0.0;
    for (const Hypothesis& h : final_estimate.hypotheses) {
      const double error = position_error(h.position, truth, dimensions);
      kpis.nearest_hypothesis_error = std::min(kpis.nearest_hypothesis_error, error);
      weighted += h.probability * error;
      probability += h.probability;
    }
    kpis.expected_error = probability > 0 ? weighted / probability : kpis.final_error;
  }
  kpis.in_region = in_stated_region(final_estimate, truth);
  if (final_estimate.region)
    kpis.credible_level = final_estimate.region->credible_level(truth.head<2>());
  kpis.detected = kpis.final_error <= kpi.acceptable_error;
  const auto errors = running_errors(log, emitter, truth, final_estimate, params, kpi);
  std::vector<double> values;
  for (const auto& item : errors) values.push_back(item.second);
  kpis.running = error_stats(values);
  kpis.data_amount = data_amount(errors, kpi.acceptable_error);
  return kpis;
}

}  // namespace rigdesign::localize
