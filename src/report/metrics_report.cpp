#include "rigdesign/report/metrics_report.hpp"

#include <utility>

#include "rigdesign/metrics/coverage_findings.hpp"
#include "rigdesign/metrics/tolerance_verdicts.hpp"

namespace rigdesign::report {
namespace {

std::vector<FilteringLoadRow> filtering_load_rows(const metrics::ResultantMetrics& metrics,
                                                  const model::FilteringLoads& loads) {
  std::vector<FilteringLoadRow> rows;
  for (const metrics::MountMetrics& mount : metrics.mounts) {
    const model::FilteringLoad* load = loads.find(mount.sensor_id);
    rows.push_back({mount.mount_id, load ? std::optional<double>(load->seconds_per_point *
                                                                 mount.filtered_points_per_second)
                                         : std::nullopt});
  }
  return rows;
}

}  // namespace

double total_filtering_cores(const std::vector<FilteringLoadRow>& rows) {
  double total = 0.0;
  for (const FilteringLoadRow& row : rows) total += row.cores.value_or(0.0);
  return total;
}

MetricsReport build_metrics_report(const io::RigInputs& inputs,
                                   std::optional<model::FilteringLoads> loads) {
  MetricsReport report;
  report.inputs = &inputs;
  report.metrics = metrics::compute_resultant(inputs.rig, inputs.library);
  const std::vector<model::SectorRequirement> sectors =
      inputs.requirements ? inputs.requirements->sectors : std::vector<model::SectorRequirement>{};
  report.coverage = metrics::compute_coverage(inputs.rig, inputs.library, sectors);
  report.findings = metrics::coverage_findings(inputs.rig, report.metrics, report.coverage);
  if (inputs.requirements) {
    report.results = metrics::evaluate_requirements(
        inputs.rig, report.metrics, *inputs.requirements, &report.coverage, &inputs.library);
  }
  // Issue 38: the sectors over the mounts' tolerance boxes, when the rig gives any.
  report.tolerance = metrics::tolerance_coverage(inputs.rig, inputs.library, sectors);
  for (metrics::RequirementResult& result :
       metrics::tolerance_verdicts(inputs.rig, report.tolerance))
    report.results.push_back(std::move(result));
  if (loads) report.load_rows = filtering_load_rows(report.metrics, *loads);
  report.loads = std::move(loads);
  return report;
}

}  // namespace rigdesign::report
