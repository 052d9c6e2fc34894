#include "rigdesign/report/select_json.hpp"

#include <nlohmann/json.hpp>

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/report/json_report.hpp"

namespace rigdesign::report {
namespace {

using nlohmann::json;

json cost_json(const select::CostBreakdown& cost) {
  return {{"total", cost.total},       {"sensors", cost.sensors},
          {"transfer", cost.transfer}, {"transfer_id", cost.transfer_id},
          {"cpu", cost.cpu},           {"cpu_id", cost.cpu_id}};
}

// Per chosen option its slot, sensor, mode and pose label.
json rig_json(const select::Selection& selection, const model::Catalog& catalog) {
  json mounts = json::array();
  for (const select::CatalogOption* option : selection.chosen) {
    const model::MountingSlot& slot = catalog.slots[option->slot];
    mounts.push_back({{"slot", slot.id},
                      {"sensor", option->sensor->id},
                      {"mode", option->mode->id},
                      {"pose", slot.poses[option->pose].label}});
  }
  return mounts;
}

// Axis values in SI, as the library holds them: metres, radians.
json refinement_json(const select::PoseRefinement& refinement) {
  json axes = json::array();
  for (const select::RefinedAxis& axis : refinement.axes) {
    axes.push_back({{"mount", axis.mount},
                    {"axis", model::kPoseAxisNames[axis.axis]},
                    {"low", axis.low},
                    {"high", axis.high},
                    {"grid", axis.grid},
                    {"refined", axis.refined},
                    {"unit", axis.axis < 3 ? "m" : "rad"}});
  }
  return {{"accepted", refinement.accepted},
          {"grid_margin", refinement.grid_margin},
          {"refined_margin", refinement.refined_margin},
          {"evaluations", refinement.evaluations},
          {"axes", axes}};
}

json phases_json(const std::vector<select::PhaseTime>& phases) {
  json out = json::array();
  for (const select::PhaseTime& phase : phases)
    out.push_back({{"phase", phase.phase}, {"work", phase.work}, {"seconds", phase.seconds}});
  return out;
}

json iteration_json(const select::RelaxationIteration& it, const model::Catalog& catalog) {
  const select::Selection& selection = it.selection;
  json item = {{"relaxed", it.relaxed},
               {"needs", describe(it.targets)},
               {"found", selection.found},
               {"within_budget", it.within_budget},
               {"nodes", selection.search.nodes},
               {"rigs_evaluated", selection.search.evaluations},
               {"coverage_classes", selection.search.coverage_classes},
               {"raster_cells", selection.search.raster_cells},
               {"dominated_options", selection.search.dominated},
               {"seconds", selection.seconds},
               {"rejected_by_exact_path", selection.rejected_by_exact_path},
               {"phases", phases_json(selection.phases)}};
  if (!selection.found) {
    item["reason"] = selection.infeasible_reason;
    return item;
  }
  item["cost"] = cost_json(selection.cost);
  item["rig"] = rig_json(selection, catalog);
  item["margin"] = selection.search.margin;
  item["ties"] = selection.search.ties;
  if (selection.refinement.tried) item["refinement"] = refinement_json(selection.refinement);
  item["coverage"] = to_json(selection.coverage, false);
  // null: no rig with cheaper sensors meets the requirements (absent: not searched).
  if (selection.cheaper_searched) item["cheaper_excluded"] = nullptr;
  if (selection.cheaper_excluded) {
    const select::ExcludedRig& rig = *selection.cheaper_excluded;
    item["cheaper_excluded"] = {{"rig", describe(rig.chosen, catalog)},
                                {"sensor_cost_usd", rig.sensor_cost},
                                {"cpu_cores", rig.cpu},
                                {"largest_cpu_cores", rig.largest_cpu},
                                {"largest_cpu", rig.largest_cpu_id},
                                {"bandwidth_bytes_per_s", rig.bandwidth},
                                {"cpu_too_small", rig.cpu_too_small},
                                {"transfer_too_small", rig.transfer_too_small},
                                {"cost_with_hardware", cost_json(rig.cost)}};
  }
  return item;
}

}  // namespace

json to_json(const SelectReport& report) {
  const select::RelaxationOutcome& outcome = *report.outcome;
  json iterations = json::array();
  for (const select::RelaxationIteration& it : outcome.iterations)
    iterations.push_back(iteration_json(it, *report.catalog));
  json binding = json::array();
  for (const select::BindingRequirement& item : outcome.binding) {
    binding.push_back({{"requirement", item.requirement}, {"cost_without", item.cost_without}});
  }
  json left_out = json::array();
  for (const select::LeftOutPoses& slot : report.left_out) {
    json reasons = json::array();
    for (const auto& [reason, count] : slot.reasons)
      reasons.push_back({{"reason", reason}, {"poses", count}});
    json sensors = json::array();
    for (const auto& [reason, count] : slot.sensor_reasons)
      sensors.push_back({{"reason", reason}, {"poses", count}});
    left_out.push_back({{"slot", slot.slot},
                        {"poses", slot.of},
                        {"reasons", reasons},
                        {"sensors_left_out", sensors}});
  }
  return {
      {"budget", report.budget},
      {"within_budget", outcome.within_budget},
      {"poses_left_out", left_out},
      {"check",
       {{"command", report.check_command},
        {"pass", report.check_pass},
        {"fail", report.check_fail},
        {"failures", report.check_failures}}},
      {"iterations", iterations},
      {"binding", binding},
      {"phases", phases_json(outcome.phases)},
      {"file_phases", phases_json(report.file_phases)},
      {"options_per_slot", report.options_per_slot},
      {"time", {{"wall_seconds", report.wall_seconds}, {"phases", phases_json(time_rows(report))}}},
      {"files", report.files}};
}

}  // namespace rigdesign::report
