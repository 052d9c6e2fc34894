#pragma once
// What `metrics` found for a rig, built once (per-mount and resultant F, R, N, L, bandwidth,
// driver CPU, cost; coverage with N-1; requirement verdicts; the sectors over the mounts'
// tolerance boxes; the measured filtering load), and its text and JSON writers.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/model/filtering_loads.hpp"

namespace rigdesign::report {

/// U_f of one mount from measured seconds per point (paper 1, eq. 5): load = s/point x points/s.
struct FilteringLoadRow {
  std::string mount_id;
  std::optional<double> cores;  ///< unset: the sensor was not measured
};

struct MetricsReport {
  const io::RigInputs* inputs = nullptr;  ///< the rig, its library and requirements
  metrics::ResultantMetrics metrics;
  metrics::RigCoverage coverage;
  std::vector<model::Diagnostic> findings;  ///< coverage findings (a mount that sees nothing)
  std::vector<metrics::RequirementResult> results;
  std::vector<metrics::SectorTolerance> tolerance;
  std::optional<model::FilteringLoads> loads;
  std::vector<FilteringLoadRow> load_rows;  ///< per mount, when `loads` is given
};

/// Everything `metrics` prints for `inputs`, with the filtering load when `loads` is given.
MetricsReport build_metrics_report(const io::RigInputs& inputs,
                                   std::optional<model::FilteringLoads> loads);

/// Sum of the measured rows' cores [core-equivalents].
double total_filtering_cores(const std::vector<FilteringLoadRow>& rows);

void print_rig_metrics(const MetricsReport& report, std::ostream& out);
std::string rig_metrics_json(const MetricsReport& report);

}  // namespace rigdesign::report
