#include "rigdesign/report/select_report.hpp"

#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

// An axis value in the catalog file's unit: metres, or degrees for the angles.
std::string axis_value(int axis, double value) {
  return axis < 3 ? model::format_number(value, 4) + " m"
                  : model::format_number(model::rad_to_deg(value), 4) + " deg";
}

}  // namespace

const select::RelaxationIteration* chosen_iteration(const select::RelaxationOutcome& outcome) {
  if (outcome.within_budget) return &outcome.iterations.back();  // the loop stops there
  for (auto it = outcome.iterations.rbegin(); it != outcome.iterations.rend(); ++it) {
    if (it->selection.found) return &*it;
  }
  return nullptr;
}

std::vector<select::PhaseTime> time_rows(const SelectReport& report) {
  std::vector<select::PhaseTime> rows = report.before_phases;
  if (report.outcome != nullptr) {
    const select::RelaxationOutcome& outcome = *report.outcome;
    for (std::size_t i = 0; i < outcome.iterations.size(); ++i) {
      for (const select::PhaseTime& phase : outcome.iterations[i].selection.phases)
        rows.push_back({"#" + std::to_string(i) + " " + phase.phase, phase.work, phase.seconds});
    }
    rows.insert(rows.end(), outcome.phases.begin(), outcome.phases.end());
  }
  rows.insert(rows.end(), report.file_phases.begin(), report.file_phases.end());
  rows.insert(rows.end(), report.after_phases.begin(), report.after_phases.end());
  return rows;
}

std::string usd(double value) {
  return fixed(value, 0) + " USD";
}

std::string percent_digits(double share) {
  return model::format_number(share * 100, 3);
}

std::string describe(const select::SatisficingTargets& targets) {
  std::string text = "F >= " + model::format_number(targets.min_frequency, 4) + " Hz";
  if (targets.max_spacing)
    text += ", R <= " + model::format_number(*targets.max_spacing * 1000, 4) + " mm";
  if (targets.max_noise)
    text += ", N <= " + model::format_number(*targets.max_noise * 1000, 4) + " mm";
  if (!targets.lighting.empty()) {
    text += ", L:";
    for (const model::LightCondition condition : targets.lighting)
      text += " " + to_string(condition);
  }
  for (const model::SectorRequirement& sector : targets.sectors) {
    text += ", SC " + sector.name + " >= " + percent_digits(sector.min_complete_coverage) + "/" +
            percent_digits(sector.min_floor_coverage) + " %";
  }
  return text;
}

std::string describe(const select::PoseRefinement& refinement) {
  // Only moves that change the value as printed: "pitch 10 deg -> 10 deg" is no move.
  std::string moves;
  for (const select::RefinedAxis& axis : refinement.axes) {
    const std::string from = axis_value(axis.axis, axis.grid);
    const std::string to = axis_value(axis.axis, axis.refined);
    if (from == to) continue;
    moves += (moves.empty() ? "" : ", ") + axis.mount + " " + model::kPoseAxisNames[axis.axis] +
             " " + from + " -> " + to;
  }
  if (moves.empty()) moves = "no pose moved";
  std::string verdict = refinement.accepted
                            ? "confirmed on the exact path: the rig written uses these poses"
                        : refinement.refined_margin > refinement.grid_margin
                            ? "the exact path turned it down: the grid poses stand"
                            : "no move widened the margin: the grid poses stand";
  // Margins are compared smallest first: a move may widen the next smallest only.
  const bool same_smallest = refinement.refined_margin == refinement.grid_margin;
  return moves + "; smallest margin" +
         (refinement.counts_failures ? std::string(", after failures included,") : "") + " " +
         model::format_number(100 * refinement.grid_margin, 3) + " -> " +
         model::format_number(100 * refinement.refined_margin, 3) + " points" +
         (same_smallest && refinement.accepted ? " (a larger one widened)" : "") + " (" +
         std::to_string(refinement.evaluations) + " rigs), " + verdict;
}

std::string describe(const select::Selection& selection, const model::Catalog& catalog) {
  return describe(selection.chosen, catalog);
}

std::string describe(const std::vector<const select::CatalogOption*>& chosen,
                     const model::Catalog& catalog) {
  std::string text;
  for (const select::CatalogOption* option : chosen) {
    const model::MountingSlot& slot = catalog.slots[option->slot];
    text +=
        (text.empty() ? "" : ", ") + slot.id + ": " + option->sensor->id + "/" + option->mode->id;
    const std::string& label = slot.poses[option->pose].label;
    if (!label.empty()) text += " at " + label;
  }
  return text;
}

std::string describe_excluded(const select::ExcludedRig& rig, const select::CostBreakdown& chosen,
                              double budget, const model::Catalog& catalog) {
  std::string text = "a rig with " + usd(rig.sensor_cost) + " of sensors meets the requirements (" +
                     describe(rig.chosen, catalog) + ") but ";
  std::vector<std::string> limits;
  if (rig.cpu_too_small) {
    limits.push_back("needs " + model::format_number(rig.cpu, 3) +
                     " core-equivalents of CPU; the catalog's largest CPU, " + rig.largest_cpu_id +
                     ", carries " + model::format_number(rig.largest_cpu, 3));
  }
  if (rig.transfer_too_small) {
    limits.push_back(
        rig.per_sensor_transfer_missing
            ? std::string("a sensor of it sends more than any per-sensor transfer component of "
                          "the catalog carries")
            : "sends " + model::format_number(rig.bandwidth * 8 / 1e9, 3) +
                  " Gbit/s; the catalog's transfer carries at most " +
                  model::format_number(rig.transfer_bottleneck / 1e9, 3) + " Gbit/s (" +
                  rig.transfer_bottleneck_id + ")");
  }
  if (!limits.empty()) return text + model::join(limits, ", and ");
  text += "with the CPU and transfer it needs (CPU " + rig.cost.cpu_id + " " + usd(rig.cost.cpu) +
          ", transfer " + rig.cost.transfer_id + " " + usd(rig.cost.transfer) + ") it costs " +
          usd(rig.cost.total) + ", not less than this rig's " + usd(chosen.total);
  if (rig.cost.total > budget) text += " (and over the budget of " + usd(budget) + ")";
  return text;
}

}  // namespace rigdesign::report
