#include "rigdesign/report/json_report.hpp"

#include <nlohmann/json.hpp>

#include "rigdesign/model/units.hpp"

namespace rigdesign::report {

using nlohmann::json;

json to_json(const model::Diagnostic& diagnostic) {
  return {{"file", diagnostic.where.file},
          {"line", diagnostic.where.line},
          {"column", diagnostic.where.column},
          {"field", diagnostic.field},
          {"severity", diagnostic.severity == model::Severity::error ? "error" : "warning"},
          {"problem", diagnostic.problem},
          {"expected", diagnostic.expected},
          {"message", diagnostic.message()}};
}

json to_json(const metrics::RequirementResult& result) {
  json item = {{"id", result.id},
               {"title", result.title},
               {"metric", result.metric},
               {"unit", result.unit},
               {"verdict", to_string(result.verdict)},
               {"limiting_mounts", result.limiting_mounts},
               {"explanation", result.explanation},
               {"field", result.field},
               {"file", result.where.file},
               {"line", result.where.line},
               {"column", result.where.column}};
  item["required"] = result.required ? json(*result.required) : json(nullptr);
  item["actual"] = result.actual ? json(*result.actual) : json(nullptr);
  return item;
}

namespace {

json limiting_json(const metrics::Limiting& limiting, const char* unit) {
  return {{"value", limiting.value}, {"unit", unit}, {"limiting_mounts", limiting.mounts}};
}

json light_json(const model::LightImmunity& light) {
  return {{"dark", light.dark}, {"indoor", light.indoor}, {"sunlight", light.sunlight}};
}

}  // namespace

json to_json(const io::RigInputs& inputs, const metrics::ResultantMetrics& metrics) {
  json mounts = json::array();
  for (const metrics::MountMetrics& mount : metrics.mounts) {
    mounts.push_back({{"id", mount.mount_id},
                      {"sensor", mount.sensor_id},
                      {"mode", mount.mode_id},
                      {"distance_m", mount.distance},
                      {"distance_in_range", mount.distance_in_range},
                      {"frequency_hz", mount.frequency},
                      {"point_spacing_m", mount.point_spacing},
                      {"noise_m", mount.noise},
                      {"light", light_json(mount.light)},
                      {"points_per_second", mount.points_per_second},
                      {"bandwidth_bytes_per_s", mount.bandwidth},
                      {"driver_cpu_cores", mount.driver_cpu},
                      {"driver_cpu_basis", to_string(mount.driver_cpu_basis)},
                      {"price_usd", mount.price},
                      {"price_basis", to_string(mount.price_basis)}});
  }
  json light = json::object();
  for (const metrics::LightResult& result : metrics.light) {
    light[to_string(result.condition)] = {{"immune", result.immune},
                                          {"failing_mounts", result.failing_mounts}};
  }
  json report = {
      {"rig",
       {{"name", inputs.rig.name},
        {"file", inputs.rig.file},
        {"sensor_library", inputs.library.file},
        {"distance_of_interest_m", inputs.rig.distance_of_interest},
        {"body", {{"radius_m", inputs.rig.body.radius}, {"height_m", inputs.rig.body.height}}}}},
      {"mounts", mounts},
      {"resultant",
       {{"F", limiting_json(metrics.frequency, "Hz")},
        {"R", limiting_json(metrics.point_spacing, "m")},
        {"N", limiting_json(metrics.noise, "m")},
        {"L", light},
        {"bandwidth_bytes_per_s", metrics.bandwidth},
        {"driver_cpu_cores", metrics.driver_cpu},
        {"sensor_cost_usd", metrics.sensor_cost},
        {"includes_estimates", metrics.any_estimate}}},
      {"reference_machine", inputs.library.reference_machine}};
  json warnings = json::array();
  for (const model::Diagnostic& warning : inputs.warnings) warnings.push_back(to_json(warning));
  report["warnings"] = warnings;
  return report;
}

namespace {

json summary_json(const metrics::CoverageSummary& summary) {
  return {{"min", summary.min},
          {"min_theta_deg", model::rad_to_deg(summary.min_theta)},
          {"mean", summary.mean},
          {"share_of_angles_at_100_percent", summary.full_share}};
}

}  // namespace

json to_json(const metrics::RigCoverage& coverage, bool curves) {
  json sectors = json::array();
  for (const metrics::SectorCoverage& sector : coverage.sectors) {
    sectors.push_back({{"name", sector.sector.name},
                       {"complete", summary_json(sector.complete)},
                       {"floor", summary_json(sector.floor)},
                       {"required_complete", sector.sector.min_complete_coverage},
                       {"required_floor", sector.sector.min_floor_coverage},
                       {"pass", sector.pass}});
  }
  json losses = json::array();
  for (const metrics::MountLoss& loss : coverage.without_each) {
    losses.push_back({{"without", loss.mount_id},
                      {"complete", summary_json(loss.complete)},
                      {"floor", summary_json(loss.floor)}});
  }
  json report = {
      {"path", coverage.exact ? "exact" : "raster"},
      {"distance_m", coverage.distance},
      {"height_m", coverage.height},
      {"angles", coverage.angles.size()},
      {"complete", summary_json(coverage.complete)},
      {"floor", summary_json(coverage.floor)},
      {"sectors", sectors},
      {"n_minus_1", losses},
      // The whole rig on the raster path, which n_minus_1 is computed on.
      {"n_minus_1_baseline",
       {{"complete", summary_json(coverage.complete_raster)},
        {"floor", summary_json(coverage.floor_raster)}}},
      {"raster_max_abs_error",
       {{"complete", coverage.raster_error_complete}, {"floor", coverage.raster_error_floor}}}};
  if (!curves) return report;
  json samples = json::array();
  for (const metrics::AngleCoverage& angle : coverage.angles) {
    json item = {{"theta_deg", model::rad_to_deg(angle.theta)},
                 {"r_m", angle.r},
                 {"complete", angle.complete},
                 {"floor", angle.floor},
                 {"complete_raster", angle.complete_raster},
                 {"floor_raster", angle.floor_raster},
                 {"redundancy", angle.redundancy}};
    json seen = json::array();
    for (std::size_t i = 0; i < angle.mount_sees.size(); ++i) {
      if (angle.mount_sees[i]) seen.push_back(coverage.mount_ids[i]);
    }
    item["seen_by"] = seen;
    if (angle.coarsest_mount >= 0) {
      item["coarsest"] = {{"mount", coverage.mount_ids[angle.coarsest_mount]},
                          {"spacing_m", angle.coarsest_spacing}};
      item["noisiest"] = {{"mount", coverage.mount_ids[angle.noisiest_mount]},
                          {"noise_m", angle.noisiest_noise}};
    }
    samples.push_back(item);
  }
  report["curves"] = samples;
  return report;
}

}  // namespace rigdesign::report
