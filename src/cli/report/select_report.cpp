#include "report/select_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "app.hpp"
#include "coverage_files.hpp"
#include "report/deployment_report.hpp"
#include "report/html_report.hpp"
#include "report/json_report.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/yaml_writers.hpp"
#include "rigdesign/io/deploy/deployment_files.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/xml_text.hpp"
#include "rigdesign/render/margin_plot.hpp"
#include "rigdesign/render/pareto_plot.hpp"
#include "rigdesign/select/pose_refinement.hpp"
#include "text_table.hpp"

namespace rigdesign::cli {
namespace {

std::string usd(double value) {
  return fixed(value, 0) + " USD";
}
std::string percent_digits(double share) {
  return model::format_number(share * 100, 3);
}

const select::RelaxationIteration* last_with_rig(const select::RelaxationOutcome& outcome) {
  for (auto it = outcome.iterations.rbegin(); it != outcome.iterations.rend(); ++it) {
    if (it->selection.found) return &*it;
  }
  return nullptr;
}

// The rig to write: the first within budget, else the cheapest of the last iteration found.
const select::RelaxationIteration* chosen(const select::RelaxationOutcome& outcome) {
  if (outcome.within_budget) return &outcome.iterations.back();
  return last_with_rig(outcome);
}

}  // namespace

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

constexpr const char* kAxisNames[6] = {"x", "y", "z", "roll", "pitch", "yaw"};

// An axis value in the file's unit: metres, or degrees for the angles.
std::string axis_value(int axis, double value) {
  return axis < 3 ? model::format_number(value, 4) + " m"
                  : model::format_number(value * 180 / 3.141592653589793, 4) + " deg";
}

std::string describe(const select::PoseRefinement& refinement) {
  std::string moves;
  for (const select::RefinedAxis& axis : refinement.axes) {
    moves += (moves.empty() ? "" : ", ") + axis.mount + " " + kAxisNames[axis.axis] + " " +
             axis_value(axis.axis, axis.grid) + " -> " + axis_value(axis.axis, axis.refined);
  }
  std::string verdict = refinement.accepted
                            ? "confirmed on the exact path: the rig written uses these poses"
                        : refinement.refined_margin > refinement.grid_margin
                            ? "the exact path turned it down: the grid poses stand"
                            : "no move widened the margin: the grid poses stand";
  return moves + "; smallest margin " + model::format_number(100 * refinement.grid_margin, 3) +
         " -> " + model::format_number(100 * refinement.refined_margin, 3) + " points (" +
         std::to_string(refinement.evaluations) + " rigs), " + verdict;
}

// The chosen options with the pose a slot's range settled on.
std::string describe(const select::Selection& selection, const model::Catalog& catalog) {
  std::string text;
  for (const select::CatalogOption* option : selection.chosen) {
    const model::MountingSlot& slot = catalog.slots[option->slot];
    text +=
        (text.empty() ? "" : ", ") + slot.id + ": " + option->sensor->id + "/" + option->mode->id;
    const std::string& label = slot.poses[option->pose].label;
    if (!label.empty()) text += " at " + label;
  }
  return text;
}

SelectReport::SelectReport(const select::SelectionSpace& space,
                           const model::Requirements& requirements,
                           const model::RelaxationPolicy& policy, double budget)
    : space_(space), requirements_(requirements), policy_(policy), budget_(budget) {}

void SelectReport::print_header(std::ostream& out) const {
  const model::Catalog& catalog = space_.catalog();
  out << "Catalog: " << catalog.name << " (" << catalog.file << "): " << catalog.slots.size()
      << " slots, " << catalog.sensors.size() << " candidate sensors, " << space_.option_count()
      << " slot options\n";
  out << "Requirements: " << requirements_.name << " (" << requirements_.file << ")\n";
  out << "Budget: " << usd(budget_) << "; relaxation policy: "
      << (policy_.steps.empty()
              ? std::string("none")
              : policy_.file + ", " + std::to_string(policy_.steps.size()) + " steps")
      << "\n\n";
}

void SelectReport::print_iteration(const select::RelaxationIteration& iteration,
                                   std::ostream& out) {
  out << "#" << printed_++ << "  "
      << (iteration.relaxed.empty() ? "initial requirements" : "relaxed " + iteration.relaxed)
      << '\n';
  out << "    needs: " << describe(iteration.targets) << '\n';
  const select::Selection& selection = iteration.selection;
  if (!selection.found) {
    out << "    no rig: " << selection.infeasible_reason << '\n';
  } else {
    out << "    cheapest rig: " << usd(selection.cost.total) << " = sensors "
        << fixed(selection.cost.sensors, 0) << " + transfer " << fixed(selection.cost.transfer, 0)
        << " (" << selection.cost.transfer_id << ") + CPU " << fixed(selection.cost.cpu, 0) << " ("
        << selection.cost.cpu_id << ")  "
        << (iteration.within_budget ? "WITHIN BUDGET" : "over budget") << '\n';
    out << "      " << describe(selection, space_.catalog()) << '\n';
    for (const select::FailureImpact& failure : selection.failures) {
      out << "      survives: " << failure.failure
          << " (every sector still met on the exact path)\n";
    }
    if (selection.cost_without_robustness) {
      out << "      robustness costs "
          << usd(selection.cost.total - *selection.cost_without_robustness)
          << ": the cheapest rig without it costs " << usd(*selection.cost_without_robustness)
          << '\n';
    }
    if (selection.search.ties > 1) {
      out << "      " << selection.search.ties
          << " rigs of this cost meet the requirements: chose the one with the largest margins "
             "to the sector thresholds, compared smallest first (smallest "
          << model::format_number(100 * selection.search.margin, 3) << " points)\n";
    }
    if (selection.refinement.tried)
      out << "      refined poses: " << describe(selection.refinement) << '\n';
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
  out << "\n\n";
}

void SelectReport::print_summary(const select::RelaxationOutcome& outcome,
                                 const std::vector<std::string>& written, std::ostream& out) const {
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
  const select::RelaxationIteration* pick = chosen(outcome);
  if (outcome.within_budget) {
    out << "\nChosen rig (" << usd(pick->selection.cost.total) << " <= budget " << usd(budget_)
        << "): " << describe(pick->selection, space_.catalog()) << '\n';
    if (pick->selection.refinement.accepted)
      out << "  refined poses: " << describe(pick->selection.refinement) << '\n';
    const metrics::RigCoverage& coverage = pick->selection.coverage;
    out << "  SC complete mean " << percent_digits(coverage.complete.mean) << " %, floor mean "
        << percent_digits(coverage.floor.mean) << " % (exact path)\n";
  } else {
    out << "\nThe policy is exhausted: no rig within " << usd(budget_) << ".\n";
    if (pick != nullptr) {
      out << "Cheapest rig found (" << usd(pick->selection.cost.total)
          << "): " << describe(pick->selection, space_.catalog()) << '\n';
    }
    out << "Binding requirements:\n";
    if (outcome.binding.empty()) out << "  none alone: the budget is below every rig's cost\n";
    for (const select::BindingRequirement& item : outcome.binding) {
      out << "  " << item.requirement << ": without it the cheapest rig costs "
          << usd(item.cost_without) << '\n';
    }
  }
  if (!written.empty()) {
    out << "\nwrote " << written.size() << " files in "
        << std::filesystem::path(written.front()).parent_path().string()
        << " (chosen_rig.yaml passes `rigdesign check`)\n";
  }
}

// SC margin against pitch for each chosen sensor whose slot's range varies its pitch, the
// rest of the rig as chosen.
std::vector<std::string> SelectReport::write_margin_plots(const select::RelaxationIteration& pick,
                                                          const std::string& folder) const {
  constexpr int kPitch = 4;
  constexpr int kSamples = 41;
  std::vector<std::string> written;
  const select::Selection& selection = pick.selection;
  for (std::size_t m = 0; m < selection.chosen.size(); ++m) {
    const model::MountingSlot& slot = space_.catalog().slots[selection.chosen[m]->slot];
    const auto range = std::find_if(slot.ranges.begin(), slot.ranges.end(),
                                    [](const model::PoseAxisRange& r) { return r.axis == kPitch; });
    if (range == slot.ranges.end()) continue;
    const std::array<double, 6>& grid_values = slot.poses[selection.chosen[m]->pose].values;
    const std::array<double, 6>& values =
        selection.refinement.accepted ? selection.refinement.values[m] : grid_values;
    render::MarginCurve curve;
    curve.axis_label = selection.rig.mounts[m].id + " pitch [deg] (positive looks down)";
    constexpr double kDeg = 180 / 3.141592653589793;
    for (const model::SectorRequirement& sector : pick.targets.sectors)
      curve.sectors.push_back({sector.name, {}});
    for (const select::MarginSample& sample :
         select::margin_sweep(space_, pick.targets, selection.rig, m, values, *range, kSamples)) {
      curve.at.push_back(sample.at * kDeg);
      curve.smallest.push_back(100 * sample.smallest);
      for (std::size_t s = 0; s < sample.sectors.size(); ++s)
        curve.sectors[s].second.push_back(100 * sample.sectors[s]);
    }
    const long steps = std::lround((range->high - range->low) / range->step);
    for (long i = 0; i <= steps; ++i)
      curve.grid.push_back((range->low + static_cast<double>(i) * range->step) * kDeg);
    curve.grid_choice = grid_values[kPitch] * kDeg;
    curve.refined = values[kPitch] * kDeg;
    const std::string path = folder + "/margin_" + selection.rig.mounts[m].id + "_pitch.png";
    render::plot_margin_curve(curve,
                              selection.rig.mounts[m].id + " (" + selection.chosen[m]->sensor->id +
                                  "): SC margin against pitch, the rest of the rig as chosen",
                              path);
    written.push_back(path);
  }
  return written;
}

std::vector<std::string> SelectReport::write_files(const select::RelaxationOutcome& outcome,
                                                   const io::StagedFolder& staged,
                                                   bool renders) const {
  const std::string& folder = staged.path();
  const select::RelaxationIteration* pick = chosen(outcome);
  std::vector<std::string> written;
  if (pick == nullptr) return written;
  const std::filesystem::path library =
      std::filesystem::absolute(space_.library().file).lexically_normal();
  const std::string library_from_folder = std::filesystem::absolute(library)
                                              .lexically_relative(std::filesystem::absolute(folder))
                                              .string();
  const std::string rig_file = folder + "/chosen_rig.yaml";
  io::write_file_atomically(
      rig_file, io::rig_to_yaml(pick->selection.rig, library_from_folder, "requirements_final.yaml",
                                "Chosen by `rigdesign select` from " + space_.catalog().file +
                                    "\n"
                                    "Cost " +
                                    fixed(pick->selection.cost.total, 0) + " USD (sensors " +
                                    fixed(pick->selection.cost.sensors, 0) + ", transfer " +
                                    pick->selection.cost.transfer_id + " " +
                                    fixed(pick->selection.cost.transfer, 0) + ", CPU " +
                                    pick->selection.cost.cpu_id + " " +
                                    fixed(pick->selection.cost.cpu, 0) + ")"));
  written.push_back(rig_file);
  const std::string requirements_file = folder + "/requirements_final.yaml";
  io::write_file_atomically(
      requirements_file,
      io::requirements_to_yaml(
          pick->requirements,
          "Requirements after " + std::to_string(&*pick - &outcome.iterations.front()) +
              " relaxation step(s) of " + (policy_.file.empty() ? "no policy" : policy_.file)));
  written.push_back(requirements_file);
  for (const char* extension : {".png", ".svg"}) {
    const std::string path = folder + "/pareto" + extension;
    render::plot_pareto(pick->selection.search.explored, budget_, pick->selection.cost.total,
                        pick->selection.coverage.complete.mean,
                        space_.catalog().name + ": rigs meeting the " +
                            (pick->relaxed.empty() ? std::string("initial requirements")
                                                   : "requirements relaxed by " + pick->relaxed),
                        path);
    written.push_back(path);
  }
  const std::vector<std::string> margins = write_margin_plots(*pick, folder);
  written.insert(written.end(), margins.begin(), margins.end());
  if (renders) {
    const std::string coverage_folder = folder + "/coverage";
    io::prepare_output_folder(coverage_folder, "--out");
    model::Rig rig = pick->selection.rig;
    rig.file = staged.final_name(rig_file);
    const std::vector<double> angles = {0, 45, 90, 180};
    const std::vector<std::string> pictures = write_coverage_files(
        rig, space_.library(), pick->selection.coverage, angles, coverage_folder, true);
    written.insert(written.end(), pictures.begin(), pictures.end());
    const std::string page = folder + "/report.html";
    io::write_file_atomically(
        page, selection_page(outcome, *pick, rig, coverage_folder, angles, folder + "/pareto.svg"));
    written.push_back(page);
  }
  // What the chosen rig means for its ROS 2 stack, as `rigdesign export` writes it.
  model::Rig rig = pick->selection.rig;
  rig.file = staged.final_name(rig_file);
  const deploy::Deployment deployment =
      deploy::plan_deployment(rig, space_.library(), &pick->requirements, {});
  const std::vector<std::string> deployed = io::write_deployment(
      folder + "/deploy", rig, deployment, deployment_header(rig, &pick->requirements));
  written.insert(written.end(), deployed.begin(), deployed.end());
  return written;
}

std::string SelectReport::selection_page(const select::RelaxationOutcome& outcome,
                                         const select::RelaxationIteration& pick,
                                         const model::Rig& rig, const std::string& coverage_folder,
                                         const std::vector<double>& angles,
                                         const std::string& pareto_svg) const {
  RigInputs inputs;
  inputs.rig = rig;
  inputs.library = space_.library();
  inputs.requirements = pick.requirements;
  const metrics::ResultantMetrics resultant = metrics::compute_resultant(rig, inputs.library);
  ReportContent content;
  content.inputs = &inputs;
  content.metrics = &resultant;
  content.coverage = &pick.selection.coverage;
  content.results =
      metrics::evaluate_requirements(rig, resultant, pick.requirements, &pick.selection.coverage);
  content.figures = coverage_figures(coverage_folder, angles);

  // The trace: what each relaxation step asked and what the cheapest rig then cost.
  std::ostringstream trace;
  trace << "<p>Catalog " << model::xml_escaped(space_.catalog().file) << ", budget " << usd(budget_)
        << ", policy "
        << model::xml_escaped(policy_.file.empty() ? std::string("none") : policy_.file)
        << ".</p>\n<table><tr><th>#</th><th class=\"text\">relaxed</th><th class=\"text\">"
           "needs</th><th>cost [USD]</th><th class=\"text\">within budget</th><th>nodes</th>"
           "<th>seconds</th></tr>\n";
  for (std::size_t i = 0; i < outcome.iterations.size(); ++i) {
    const select::RelaxationIteration& it = outcome.iterations[i];
    trace << "<tr><td>" << i << "</td><td class=\"text\">"
          << model::xml_escaped(it.relaxed.empty() ? "-" : it.relaxed) << "</td><td class=\"text\">"
          << model::xml_escaped(describe(it.targets)) << "</td><td>"
          << (it.selection.found ? fixed(it.selection.cost.total, 0) : "none")
          << "</td><td class=\"" << (it.within_budget ? "text pass\">yes" : "text fail\">no")
          << "</td><td>" << it.selection.search.nodes << "</td><td>"
          << fixed(it.selection.seconds, 2) << "</td></tr>\n";
  }
  const select::CostBreakdown& cost = pick.selection.cost;
  trace << "</table>\n<table><tr><th class=\"text\">chosen rig's cost</th><th>USD</th></tr>\n"
        << "<tr><td class=\"text\">sensors</td><td>" << fixed(cost.sensors, 0) << "</td></tr>\n"
        << "<tr><td class=\"text\">transfer: " << model::xml_escaped(cost.transfer_id)
        << "</td><td>" << fixed(cost.transfer, 0)
        << "</td></tr>\n<tr><td class=\"text\">CPU: " << model::xml_escaped(cost.cpu_id)
        << "</td><td>" << fixed(cost.cpu, 0) << "</td></tr>\n<tr><th class=\"text\">total</th><th>"
        << fixed(cost.total, 0) << "</th></tr>\n</table>\n<p>"
        << model::xml_escaped(describe(pick.selection, space_.catalog())) << "</p>\n";
  trace << "<figure id=\"pareto\">"
        << inline_svg(io::read_file_bytes(pareto_svg, "an SVG picture"), "pareto-")
        << "<figcaption>Cost against mean coverage of the rigs meeting the requirements of the "
           "chosen step.</figcaption></figure>\n";
  content.sections.push_back({"selection", "Selection trace", trace.str()});
  return html_report(content);
}

nlohmann::json SelectReport::to_json(const select::RelaxationOutcome& outcome,
                                     const std::vector<std::string>& written) const {
  nlohmann::json iterations = nlohmann::json::array();
  for (const select::RelaxationIteration& it : outcome.iterations) {
    nlohmann::json item = {{"relaxed", it.relaxed},
                           {"needs", describe(it.targets)},
                           {"found", it.selection.found},
                           {"within_budget", it.within_budget},
                           {"nodes", it.selection.search.nodes},
                           {"rigs_evaluated", it.selection.search.evaluations},
                           {"coverage_classes", it.selection.search.coverage_classes},
                           {"raster_cells", it.selection.search.raster_cells},
                           {"dominated_options", it.selection.search.dominated},
                           {"seconds", it.selection.seconds},
                           {"rejected_by_exact_path", it.selection.rejected_by_exact_path}};
    if (it.selection.found) {
      item["cost"] = {
          {"total", it.selection.cost.total},       {"sensors", it.selection.cost.sensors},
          {"transfer", it.selection.cost.transfer}, {"transfer_id", it.selection.cost.transfer_id},
          {"cpu", it.selection.cost.cpu},           {"cpu_id", it.selection.cost.cpu_id}};
      nlohmann::json mounts = nlohmann::json::array();
      for (const select::CatalogOption* option : it.selection.chosen) {
        const model::MountingSlot& slot = space_.catalog().slots[option->slot];
        mounts.push_back({{"slot", slot.id},
                          {"sensor", option->sensor->id},
                          {"mode", option->mode->id},
                          {"pose", slot.poses[option->pose].label}});
      }
      item["rig"] = mounts;
      item["margin"] = it.selection.search.margin;
      item["ties"] = it.selection.search.ties;
      const select::PoseRefinement& refinement = it.selection.refinement;
      if (refinement.tried) {
        nlohmann::json axes = nlohmann::json::array();
        for (const select::RefinedAxis& axis : refinement.axes) {
          axes.push_back({{"mount", axis.mount},
                          {"axis", kAxisNames[axis.axis]},
                          {"low", axis.low},
                          {"high", axis.high},
                          {"grid", axis.grid},
                          {"refined", axis.refined},
                          {"unit", axis.axis < 3 ? "m" : "rad"}});
        }
        item["refinement"] = {{"accepted", refinement.accepted},
                              {"grid_margin", refinement.grid_margin},
                              {"refined_margin", refinement.refined_margin},
                              {"evaluations", refinement.evaluations},
                              {"axes", axes}};
      }
      item["coverage"] = cli::to_json(it.selection.coverage, false);
    } else {
      item["reason"] = it.selection.infeasible_reason;
    }
    iterations.push_back(item);
  }
  nlohmann::json binding = nlohmann::json::array();
  for (const select::BindingRequirement& item : outcome.binding) {
    binding.push_back({{"requirement", item.requirement}, {"cost_without", item.cost_without}});
  }
  return {{"budget", budget_},
          {"within_budget", outcome.within_budget},
          {"iterations", iterations},
          {"binding", binding},
          {"files", written}};
}

}  // namespace rigdesign::cli
