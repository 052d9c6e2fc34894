#include "rigdesign/report/select_text.hpp"

#include <filesystem>
#include <ostream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::report {
namespace {

// The cheapest rig of a step that found one: its cost split, why it won among equals, and
// the failures it survives.
void print_found_rig(const SelectReport& report, const select::RelaxationIteration& iteration,
                     std::ostream& out) {
  const select::Selection& selection = iteration.selection;
  out << "    cheapest rig: " << usd(selection.cost.total) << " = sensors "
      << fixed(selection.cost.sensors, 0) << " + transfer " << fixed(selection.cost.transfer, 0)
      << " (" << selection.cost.transfer_id << ") + CPU " << fixed(selection.cost.cpu, 0) << " ("
      << selection.cost.cpu_id << ")  "
      << (iteration.within_budget ? "WITHIN BUDGET" : "over budget") << '\n';
  out << "      " << describe(selection, *report.catalog) << '\n';
  if (selection.cheaper_excluded) {
    out << "      why not cheaper: "
        << describe_excluded(*selection.cheaper_excluded, selection.cost, report.budget,
                             *report.catalog)
        << '\n';
  } else if (selection.cheaper_searched) {
    out << "      no rig with cheaper sensors meets the requirements"
        << (iteration.targets.robustness ? " and survives the failures" : "")
        << ", even with free, unlimited CPU and transfer\n";
  }
  for (const select::FailureImpact& failure : selection.failures) {
    out << "      survives: " << failure.failure << " (every sector still met on the exact path)\n";
  }
  if (selection.cost_without_robustness) {
    out << "      robustness costs "
        << usd(selection.cost.total - *selection.cost_without_robustness)
        << ": the cheapest rig without it costs " << usd(*selection.cost_without_robustness)
        << '\n';
  }
  if (selection.search.ties > 1) {
    out << "      rigs of equal cost meet the requirements (" << selection.search.ties
        << " compared; the search cut those that could not widen the margins): chose the one "
           "with the largest margins to the sector thresholds, compared smallest first "
           "(smallest "
        << model::format_number(100 * selection.search.margin, 3) << " points)\n";
  }
  if (selection.refinement.tried)
    out << "      refined poses: " << describe(selection.refinement) << '\n';
}

// One line per phase: what ran and how long it took.
void print_phases(const std::vector<select::PhaseTime>& phases, const std::string& indent,
                  std::ostream& out) {
  for (const select::PhaseTime& phase : phases)
    out << indent << "phase " << phase.phase << ": " << fixed(phase.seconds, 2) << " s, "
        << phase.work << '\n';
}

void print_search_effort(const select::Selection& selection, std::ostream& out) {
  if (selection.search.nodes == 0) {  // ruled out before any search: nothing was proven
    out << "    search: none ran (the cause above was found before it)\n";
    print_phases(selection.phases, "    ", out);
    out << '\n';
    return;
  }
  out << "    search: " << selection.search.nodes << " nodes, " << selection.search.evaluations
      << " rigs evaluated, " << fixed(selection.seconds, 2) << " s ("
      << selection.search.coverage_classes << " coverage classes for "
      << selection.search.raster_cells << " raster cells, " << selection.search.dominated
      << " dominated options), proven optimal on the raster path";
  if (selection.found) {
    out << ", verified on the exact path";
    if (selection.rejected_by_exact_path > 0) {
      out << " (" << selection.rejected_by_exact_path << " raster winners rejected by it)";
    }
  }
  out << '\n';
  print_phases(selection.phases, "    ", out);
  out << '\n';
}

// Issue 55: where the whole command's wall time went, phase by phase, and how much of it
// the phases account for (the rest is the report itself and the glue between phases).
void print_time_table(const SelectReport& report, std::ostream& out) {
  const std::vector<select::PhaseTime> rows = time_rows(report);
  if (rows.empty() || !(report.wall_seconds > 0)) return;
  using Align = TextTable::Align;
  TextTable table;
  table.add_column("phase", Align::left);
  table.add_column("s", Align::right);
  table.add_column("% of wall", Align::right);
  double sum = 0.0;
  for (const select::PhaseTime& row : rows) {
    sum += row.seconds;
    table.add_row(
        {row.phase, fixed(row.seconds, 2), fixed(100 * row.seconds / report.wall_seconds, 1)});
  }
  out << "\nWhere the time went (wall " << fixed(report.wall_seconds, 2) << " s; the phases sum to "
      << fixed(sum, 2) << " s, " << fixed(100 * sum / report.wall_seconds, 1) << " %)\n";
  table.print(out, "  ");
}

void print_trace_table(const select::RelaxationOutcome& outcome, std::ostream& out) {
  using Align = TextTable::Align;
  TextTable table;
  table.add_column("#", Align::right);
  table.add_column("relaxed", Align::left);
  table.add_column("F >= Hz", Align::right);
  table.add_column("R <= mm", Align::right);
  table.add_column("N <= mm", Align::right);
  table.add_column("cost USD", Align::right);
  table.add_column("within budget", Align::left);
  for (std::size_t i = 0; i < outcome.iterations.size(); ++i) {
    const select::RelaxationIteration& it = outcome.iterations[i];
    table.add_row(
        {std::to_string(i), it.relaxed.empty() ? "-" : it.relaxed,
         model::format_number(it.targets.min_frequency, 4),
         it.targets.max_spacing ? model::format_number(*it.targets.max_spacing * 1000, 4) : "-",
         it.targets.max_noise ? model::format_number(*it.targets.max_noise * 1000, 4) : "-",
         it.selection.found ? fixed(it.selection.cost.total, 0) : "none",
         it.within_budget ? "yes" : "no"});
  }
  out << "Trace\n";
  table.print(out, "  ");
}

void print_chosen(const SelectReport& report, const select::RelaxationIteration& pick,
                  std::ostream& out) {
  out << "\nChosen rig (" << usd(pick.selection.cost.total) << " <= budget " << usd(report.budget)
      << "): " << describe(pick.selection, *report.catalog) << '\n';
  if (pick.selection.refinement.accepted)
    out << "  refined poses: " << describe(pick.selection.refinement) << '\n';
  const metrics::RigCoverage& coverage = pick.selection.coverage;
  out << "  SC complete mean " << percent_digits(coverage.complete.mean) << " %, floor mean "
      << percent_digits(coverage.floor.mean) << " % (exact path)\n";
}

// The policy ran out: the cheapest rig found, if any, and the requirements that bind.
void print_exhausted(const SelectReport& report, const select::RelaxationIteration* cheapest,
                     std::ostream& out) {
  if (report.policy->steps.empty()) {  // no policy: nothing was relaxed, nothing exhausted
    out << "\nNo rig within " << usd(report.budget)
        << (cheapest == nullptr ? " (no rig meets the requirements at any cost)" : "")
        << "; no relaxation policy was given (--policy).\n";
  } else {
    out << "\nThe policy is exhausted: no rig within " << usd(report.budget) << ".\n";
  }
  if (cheapest != nullptr) {
    out << "Cheapest rig found (" << usd(cheapest->selection.cost.total)
        << "): " << describe(cheapest->selection, *report.catalog) << '\n';
  }
  out << "Binding requirements:\n";
  // The budget is named only when a rig exists above it (issue 32).
  if (report.outcome->binding.empty() && cheapest != nullptr)
    out << "  none alone: the budget is below every rig's cost\n";
  if (report.outcome->binding.empty() && cheapest == nullptr) {
    out << "  none alone: no rig exists at any cost, and dropping any one requirement does not "
           "make one; the cause: "
        << report.outcome->iterations.back().selection.infeasible_reason << '\n';
  }
  for (const select::BindingRequirement& item : report.outcome->binding) {
    out << "  " << item.requirement << ": without it the cheapest rig costs "
        << usd(item.cost_without) << '\n';
  }
}

}  // namespace

void print_select_header(const SelectReport& report, std::ostream& out) {
  const model::Catalog& catalog = *report.catalog;
  const model::RelaxationPolicy& policy = *report.policy;
  out << "Catalog: " << catalog.name << " (" << catalog.file << "): " << catalog.slots.size()
      << " slots, " << catalog.sensors.size() << " candidate sensors, " << report.option_count
      << " slot options\n";
  if (report.options_per_slot.size() == catalog.slots.size()) {
    out << "Options per slot (poses left in x modes allowed):";
    for (std::size_t k = 0; k < catalog.slots.size(); ++k)
      out << (k == 0 ? " " : ", ") << catalog.slots[k].id << " " << report.options_per_slot[k];
    out << '\n';
  }
  if (!report.left_out.empty()) {
    out << "Left out before the search, a sensor's data origin inside the body or its housing "
           "cutting into it (a rig with them could not be built):\n";
    for (const select::LeftOutPoses& slot : report.left_out)
      out << "    " << select::describe(slot) << '\n';
  }
  out << "Requirements: " << report.requirements->name << " (" << report.requirements->file
      << ")\n";
  out << "Budget: " << usd(report.budget) << "; relaxation policy: "
      << (policy.steps.empty()
              ? std::string("none")
              : policy.file + ", " + std::to_string(policy.steps.size()) + " steps")
      << "\n\n";
}

void print_select_iteration(const SelectReport& report, std::size_t index,
                            const select::RelaxationIteration& iteration, std::ostream& out) {
  out << "#" << index << "  "
      << (iteration.relaxed.empty() ? "initial requirements" : "relaxed " + iteration.relaxed)
      << '\n';
  out << "    needs: " << describe(iteration.targets) << '\n';
  if (iteration.selection.found) {
    print_found_rig(report, iteration, out);
  } else {
    out << "    no rig: " << iteration.selection.infeasible_reason << '\n';
  }
  print_search_effort(iteration.selection, out);
}

void print_select_summary(const SelectReport& report, std::ostream& out) {
  const select::RelaxationOutcome& outcome = *report.outcome;
  print_trace_table(outcome, out);
  const select::RelaxationIteration* pick = chosen_iteration(outcome);
  if (outcome.within_budget) {
    print_chosen(report, *pick, out);
  } else {
    print_exhausted(report, pick, out);
  }
  if (!outcome.phases.empty() || !report.file_phases.empty()) out << '\n';
  print_phases(outcome.phases, "", out);
  print_phases(report.file_phases, "", out);
  if (!report.files.empty()) {
    // Only what was verified is claimed: check's own verdicts on the files written, then the
    // deployment's own warnings.
    out << "\nwrote " << report.files.size() << " files in "
        << std::filesystem::path(report.files.front()).parent_path().string() << '\n';
    if (!report.check_command.empty()) {
      out << "checked them: `" << report.check_command << "`: " << report.check_pass << " pass, "
          << report.check_fail << " fail\n";
      for (const std::string& failure : report.check_failures) out << "  " << failure << '\n';
    }
    for (const std::string& warning : report.deployment_warnings) out << warning << '\n';
  }
  print_time_table(report, out);
}

}  // namespace rigdesign::report
