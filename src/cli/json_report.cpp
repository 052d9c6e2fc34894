#include "json_report.hpp"

#include <nlohmann/json.hpp>

namespace rigdesign::cli {

using nlohmann::json;

json to_json(const Diagnostic& diagnostic) {
  return {{"file", diagnostic.where.file},
          {"line", diagnostic.where.line},
          {"column", diagnostic.where.column},
          {"field", diagnostic.field},
          {"severity", diagnostic.severity == Severity::error ? "error" : "warning"},
          {"problem", diagnostic.problem},
          {"expected", diagnostic.expected},
          {"message", diagnostic.message()}};
}

json to_json(const RequirementResult& result) {
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

json limiting_json(const Limiting& limiting, const char* unit) {
  return {{"value", limiting.value}, {"unit", unit}, {"limiting_mounts", limiting.mounts}};
}

json light_json(const LightImmunity& light) {
  return {{"dark", light.dark}, {"indoor", light.indoor}, {"sunlight", light.sunlight}};
}

}  // namespace

json to_json(const RigInputs& inputs, const ResultantMetrics& metrics) {
  json mounts = json::array();
  for (const MountMetrics& mount : metrics.mounts) {
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
  for (const LightResult& result : metrics.light) {
    light[to_string(result.condition)] = {{"immune", result.immune},
                                          {"failing_mounts", result.failing_mounts}};
  }
  json report = {{"rig", {{"name", inputs.rig.name},
                          {"file", inputs.rig.file},
                          {"sensor_library", inputs.library.file},
                          {"distance_of_interest_m", inputs.rig.distance_of_interest},
                          {"body", {{"radius_m", inputs.rig.body.radius},
                                    {"height_m", inputs.rig.body.height}}}}},
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
  for (const Diagnostic& warning : inputs.warnings) warnings.push_back(to_json(warning));
  report["warnings"] = warnings;
  return report;
}

}  // namespace rigdesign::cli
