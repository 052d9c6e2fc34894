// `metrics`' text: the mount table, the resultant F, R, N, L, the cost model's inputs, the
// coverage summary with the N-1 table, the requirement verdicts and the tolerance sectors.
#include <optional>
#include <ostream>

#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/metrics/tolerance_verdicts.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/report/metrics_report.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

void print_filtering_load(const model::FilteringLoads& loads,
                          const std::vector<FilteringLoadRow>& rows, double driver_cpu,
                          std::ostream& out) {
  std::vector<std::string> parts, missing;
  for (const FilteringLoadRow& row : rows) {
    if (row.cores)
      parts.push_back(row.mount_id + " " + fixed(*row.cores, 3));
    else
      missing.push_back(row.mount_id);
  }
  out << "  U_f = " << fixed(total_filtering_cores(rows), 3) << " core-equivalents ("
      << model::join(parts) << "), measured with " << loads.pipeline << " on " << loads.machine
      << " (" << loads.file << ")\n";
  if (!missing.empty()) out << "        not measured: " << model::join(missing) << '\n';
  out << "  U   = U_p + U_f = " << fixed(driver_cpu + total_filtering_cores(rows), 2)
      << " core-equivalents\n";
}

std::string yes_no(bool value) {
  return value ? "yes" : "no";
}

std::string marked(double value, int decimals, model::Basis basis) {
  return fixed(value, decimals) + (basis == model::Basis::estimate ? "*" : "");
}

void print_mount_table(const metrics::ResultantMetrics& metrics, std::ostream& out) {
  using Align = TextTable::Align;
  TextTable table;
  for (const char* header : {"mount", "sensor / mode"}) table.add_column(header, Align::left);
  for (const char* header : {"d [m]", "F [Hz]", "R [mm]", "N [mm]"}) {
    table.add_column(header, Align::right);
  }
  for (const char* header : {"dark", "indoor", "sun"}) table.add_column(header, Align::left);
  for (const char* header : {"B [MB/s]", "U_p [cores]", "price [USD]"}) {
    table.add_column(header, Align::right);
  }
  for (const metrics::MountMetrics& mount : metrics.mounts) {
    table.add_row(
        {mount.mount_id, mount.sensor_id + " / " + mount.mode_id,
         fixed(mount.distance, 2) + (mount.distance_in_range ? "" : "!"), fixed(mount.frequency, 1),
         fixed(mount.point_spacing * 1000, 1), fixed(mount.noise * 1000, 1),
         yes_no(mount.light.dark), yes_no(mount.light.indoor), yes_no(mount.light.sunlight),
         fixed(mount.bandwidth / 1e6, 2), marked(mount.driver_cpu, 2, mount.driver_cpu_basis),
         marked(mount.price, 0, mount.price_basis)});
  }
  table.print(out, "  ");
}

void print_light(const metrics::ResultantMetrics& metrics,
                 const std::optional<model::Requirements>& requirements, std::ostream& out) {
  if (requirements && !requirements->lighting.empty()) {
    bool all = true;
    std::vector<std::string> names;
    for (model::LightCondition condition : requirements->lighting) {
      all = all && metrics.light_for(condition).immune;
      names.push_back(to_string(condition));
    }
    out << "  L = " << (all ? "true" : "false") << "  (required: " << model::join(names) << ")\n";
  }
  for (const metrics::LightResult& light : metrics.light) {
    out << "      " << to_string(light.condition) << ": "
        << (light.immune ? "every sensor works" : "fails for " + model::join(light.failing_mounts))
        << '\n';
  }
}

std::string percent(double share) {
  return fixed(share * 100, 1) + " %";
}

// "+1.8 %", "-0.4 %": a margin in points of share.
std::string signed_percent(double share) {
  return (share >= 0 ? "+" : "") + percent(share);
}

std::string summary_line(const metrics::CoverageSummary& summary) {
  return "min " + percent(summary.min) + " (at " + fixed(model::rad_to_deg(summary.min_theta), 0) +
         " deg), mean " + percent(summary.mean) + ", 100 % at " + percent(summary.full_share) +
         " of angles";
}

void print_coverage(const metrics::RigCoverage& coverage, std::ostream& out) {
  out << "\nSpatial coverage (paper 1, section 2.3): rho in [r, "
      << model::format_number(coverage.distance) << "] m, z in [0, "
      << model::format_number(coverage.height) << "] m, " << coverage.angles.size() << " angles, "
      << (coverage.exact ? "exact path (CGAL polygons)" : "raster path") << "\n";
  out << "  SC complete: " << summary_line(coverage.complete) << '\n';
  out << "  SC floor:    " << summary_line(coverage.floor) << '\n';
  using Align = TextTable::Align;
  TextTable table;
  table.add_column("without", Align::left);
  for (const char* header : {"SC complete min", "mean", "SC floor min", "mean"}) {
    table.add_column(header, Align::right);
  }
  // Both rows on the raster path, so that a row's change is the sensor's alone.
  table.add_row({"(all sensors)", percent(coverage.complete_raster.min),
                 percent(coverage.complete_raster.mean), percent(coverage.floor_raster.min),
                 percent(coverage.floor_raster.mean)});
  for (const metrics::MountLoss& loss : coverage.without_each) {
    table.add_row({loss.mount_id, percent(loss.complete.min), percent(loss.complete.mean),
                   percent(loss.floor.min), percent(loss.floor.mean)});
  }
  out << "  Losing one sensor (N-1, raster path):\n";
  table.print(out, "    ");
}

void print_rig(const MetricsReport& report, std::ostream& out) {
  const io::RigInputs& inputs = *report.inputs;
  const metrics::ResultantMetrics& metrics = report.metrics;
  const std::vector<metrics::RequirementResult>& results = report.results;
  const model::Rig& rig = inputs.rig;
  out << "Rig: " << rig.name << "  (" << rig.file << ", sensors from " << inputs.library.file
      << ")\n";
  out << "Body r = " << model::format_number(rig.body.radius)
      << " m, h = " << model::format_number(rig.body.height)
      << " m; distance of interest d = " << model::format_number(rig.distance_of_interest)
      << " m\n\n";
  print_mount_table(metrics, out);
  out << "\nResultant metrics (paper 1, section 2.3)\n";
  out << "  F = " << model::format_number(metrics.frequency.value, 4)
      << " Hz      slowest: " << model::join(metrics.frequency.mounts) << '\n';
  out << "  R = " << fixed(metrics.point_spacing.value * 1000, 1)
      << " mm   coarsest: " << model::join(metrics.point_spacing.mounts) << '\n';
  out << "  N = " << fixed(metrics.noise.value * 1000, 1)
      << " mm    noisiest: " << model::join(metrics.noise.mounts) << '\n';
  print_light(metrics, inputs.requirements, out);
  out << "\nCost model inputs (paper 1, eqs. 1-7)\n";
  out << "  B   = " << fixed(metrics.bandwidth / 1e6, 2) << " MB/s ("
      << fixed(metrics.bandwidth * 8 / 1e6, 1) << " Mbit/s)\n";
  out << "  U_p = " << fixed(metrics.driver_cpu, 2) << " core-equivalents of "
      << inputs.library.reference_machine << '\n';
  if (report.loads) print_filtering_load(*report.loads, report.load_rows, metrics.driver_cpu, out);
  out << "  C_s = " << fixed(metrics.sensor_cost, 0) << " USD\n";
  if (metrics.any_estimate) out << "  * estimate, not a datasheet or measured value\n";
  print_coverage(report.coverage, out);
  for (const model::Diagnostic& warning : inputs.warnings) out << warning.message() << '\n';
  for (const model::Diagnostic& finding : report.findings) out << finding.message() << '\n';
  if (results.empty()) return;
  out << "\nRequirements (" << inputs.requirements->file << ")\n";
  using Align = TextTable::Align;
  TextTable table;
  table.add_column("req", Align::left);
  table.add_column("title", Align::left);
  table.add_column("verdict", Align::left);
  table.add_column("how", Align::left);
  for (const metrics::RequirementResult& result : results) {
    std::string how = result.explanation;
    if (result.actual) {
      const bool in_mm = result.unit == "m" && (result.metric == "R" || result.metric == "N");
      how = result.metric + " = " +
            (in_mm ? fixed(*result.actual * 1000, 1) + " mm"
                   : model::format_number(*result.actual, 4) + " " + result.unit) +
            "; " + how;
    }
    table.add_row({result.id, result.title, to_string(result.verdict), how});
  }
  table.print(out, "  ");
}

std::string worst_text(double nominal, const metrics::WorstShare& worst) {
  std::vector<std::string> errors;
  for (const metrics::MountError& error : worst.errors)
    errors.push_back(error.mount_id + ": " + metrics::error_text(error.error));
  return percent(nominal) + " -> " + percent(worst.share) +
         (errors.empty() ? "" : " (" + model::join(errors, "; ") + ")");
}

void print_tolerance(const std::vector<metrics::SectorTolerance>& sectors, std::ostream& out) {
  out << "\nMounting tolerance: each sector's minimum with the mounts anywhere in their "
         "tolerance boxes (corners and face centres one mount at a time, then the mounts' worst "
         "together; exact path)\n";
  using Align = TextTable::Align;
  TextTable table;
  for (const char* header : {"sector", "SC complete nominal -> worst", "SC floor nominal -> worst",
                             "margin left", "still met"})
    table.add_column(header, Align::left);
  for (const metrics::SectorTolerance& sector : sectors) {
    table.add_row({sector.sector.name, worst_text(sector.nominal_complete, sector.complete),
                   worst_text(sector.nominal_floor, sector.floor), signed_percent(sector.margin()),
                   yes_no(sector.pass)});
  }
  table.print(out, "  ");
}

}  // namespace

void print_rig_metrics(const MetricsReport& report, std::ostream& out) {
  print_rig(report, out);
  if (!report.tolerance.empty()) print_tolerance(report.tolerance, out);
}

}  // namespace rigdesign::report
