#include "select_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include "coverage_files.hpp"
#include "inputs.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/export/deployment_files.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/yaml_writers.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/io/output_folder.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/margin_plot.hpp"
#include "rigdesign/render/pareto_plot.hpp"
#include "rigdesign/report/deployment_report.hpp"
#include "rigdesign/report/html_report.hpp"
#include "rigdesign/report/select_html.hpp"
#include "rigdesign/report/text_table.hpp"
#include "rigdesign/select/pose_refinement.hpp"

namespace rigdesign::cli {
namespace {

constexpr int kPitch = 4;  // "pitch" in model::kPoseAxisNames
constexpr int kMarginSamples = 41;

// The rig file names its sensor library (absolute unless it lies in the folder) and the
// requirements beside it.
std::string write_chosen_rig(const report::SelectReport& report,
                             const model::SensorLibrary& library,
                             const select::Selection& selection, const std::string& folder) {
  // The staging folder becomes the output folder: a library outside it is named absolute.
  const std::string library_from_folder = io::path_seen_from(library.file, folder);
  const select::CostBreakdown& cost = selection.cost;
  const std::string rig_file = folder + "/chosen_rig.yaml";
  io::write_file_atomically(
      rig_file, io::rig_to_yaml(selection.rig, library_from_folder, "requirements_final.yaml",
                                "Chosen by `rigdesign select` from " + report.catalog->file +
                                    "\nCost " + report::fixed(cost.total, 0) + " USD (sensors " +
                                    report::fixed(cost.sensors, 0) + ", transfer " +
                                    cost.transfer_id + " " + report::fixed(cost.transfer, 0) +
                                    ", CPU " + cost.cpu_id + " " + report::fixed(cost.cpu, 0) + ")",
                                folder));
  return rig_file;
}

std::string write_final_requirements(const report::SelectReport& report,
                                     const select::RelaxationIteration& pick,
                                     const std::string& folder) {
  const std::vector<select::RelaxationIteration>& iterations = report.outcome->iterations;
  const std::string file = folder + "/requirements_final.yaml";
  io::write_file_atomically(
      file, io::requirements_to_yaml(
                pick.requirements,
                "Requirements after " + std::to_string(&pick - &iterations.front()) +
                    " relaxation step(s) of " +
                    (report.policy->file.empty() ? "no policy" : report.policy->file)));
  return file;
}

std::vector<std::string> write_pareto_plots(const report::SelectReport& report,
                                            const select::RelaxationIteration& pick,
                                            const std::string& folder) {
  std::vector<std::string> written;
  for (const char* extension : {".png", ".svg"}) {
    const std::string path = folder + "/pareto" + extension;
    render::plot_pareto(pick.selection.search.explored, report.budget, pick.selection.cost.total,
                        pick.selection.coverage.complete.mean,
                        report.catalog->name + ": rigs meeting the " +
                            (pick.relaxed.empty() ? std::string("initial requirements")
                                                  : "requirements relaxed by " + pick.relaxed),
                        path);
    written.push_back(path);
  }
  return written;
}

// SC margin against pitch of chosen mount `m`, the rest of the rig as chosen; none when its
// slot's range does not vary the pitch.
std::optional<render::MarginCurve> pitch_margin_curve(const select::SelectionSpace& space,
                                                      const select::RelaxationIteration& pick,
                                                      std::size_t m) {
  const select::Selection& selection = pick.selection;
  const model::MountingSlot& slot = space.catalog().slots[selection.chosen[m]->slot];
  const auto range = std::find_if(slot.ranges.begin(), slot.ranges.end(),
                                  [](const model::PoseAxisRange& r) { return r.axis == kPitch; });
  if (range == slot.ranges.end()) return std::nullopt;
  const std::array<double, 6>& grid_values = slot.poses[selection.chosen[m]->pose].values;
  const std::array<double, 6>& values =
      selection.refinement.accepted ? selection.refinement.values[m] : grid_values;
  render::MarginCurve curve;
  curve.axis_label = selection.rig.mounts[m].id + " pitch [deg] (positive looks down)";
  for (const model::SectorRequirement& sector : pick.targets.sectors)
    curve.sectors.push_back({sector.name, {}});
  for (const select::MarginSample& sample : select::margin_sweep(
           space, pick.targets, selection.rig, m, values, *range, kMarginSamples)) {
    curve.at.push_back(model::rad_to_deg(sample.at));
    curve.smallest.push_back(100 * sample.smallest);
    for (std::size_t s = 0; s < sample.sectors.size(); ++s)
      curve.sectors[s].second.push_back(100 * sample.sectors[s]);
  }
  const long steps = std::lround((range->high - range->low) / range->step);
  for (long i = 0; i <= steps; ++i)
    curve.grid.push_back(model::rad_to_deg(range->low + static_cast<double>(i) * range->step));
  curve.grid_choice = model::rad_to_deg(grid_values[kPitch]);
  curve.refined = model::rad_to_deg(values[kPitch]);
  return curve;
}

std::vector<std::string> write_margin_plots(const select::SelectionSpace& space,
                                            const select::RelaxationIteration& pick,
                                            const std::string& folder) {
  std::vector<std::string> written;
  const select::Selection& selection = pick.selection;
  for (std::size_t m = 0; m < selection.chosen.size(); ++m) {
    const std::optional<render::MarginCurve> curve = pitch_margin_curve(space, pick, m);
    if (!curve) continue;
    const std::string& mount = selection.rig.mounts[m].id;
    const std::string path = folder + "/margin_" + mount + "_pitch.png";
    render::plot_margin_curve(*curve,
                              mount + " (" + selection.chosen[m]->sensor->id +
                                  "): SC margin against pitch, the rest of the rig as chosen",
                              path);
    written.push_back(path);
  }
  return written;
}

// The chosen rig's report page (html_report) with the selection trace as a section of its
// own; the coverage pictures and the Pareto SVG are read back from where they were written.
std::string selection_page(const report::SelectReport& report, const model::SensorLibrary& library,
                           const select::RelaxationIteration& pick, const model::Rig& rig,
                           const std::string& coverage_folder, const std::vector<double>& angles,
                           const std::string& pareto_svg) {
  RigInputs inputs;
  inputs.rig = rig;
  inputs.library = library;
  inputs.requirements = pick.requirements;
  const metrics::ResultantMetrics resultant = metrics::compute_resultant(rig, inputs.library);
  report::ReportContent content;
  content.inputs = &inputs;
  content.metrics = &resultant;
  content.coverage = &pick.selection.coverage;
  content.results = metrics::evaluate_requirements(rig, resultant, pick.requirements,
                                                   &pick.selection.coverage, &inputs.library);
  content.figures = coverage_figures(coverage_folder, angles);
  content.sections.push_back(
      {"selection", "Selection trace",
       report::selection_trace_html(report, pick,
                                    io::read_file_bytes(pareto_svg, "an SVG picture"))});
  return report::html_report(content);
}

// The coverage pictures of the rig as written (`rig.file` its final name) and the page.
std::vector<std::string> write_renders(const report::SelectReport& report,
                                       const model::SensorLibrary& library,
                                       const select::RelaxationIteration& pick,
                                       const model::Rig& rig, const std::string& folder) {
  const std::string coverage_folder = folder + "/coverage";
  io::prepare_output_folder(coverage_folder, "--out");
  const std::vector<double> angles = {0, 45, 90, 180};
  std::vector<std::string> written =
      write_coverage_files(rig, library, pick.selection.coverage, angles, coverage_folder, true);
  const std::string page = folder + "/report.html";
  io::write_file_atomically(page, selection_page(report, library, pick, rig, coverage_folder,
                                                 angles, folder + "/pareto.svg"));
  written.push_back(page);
  return written;
}

// What the chosen rig means for its ROS 2 stack, as `rigdesign export` writes it.
// The collision monitor's warnings (a zone whose edge no source sees) go to `warnings`.
std::vector<std::string> write_ros_deployment(const model::SensorLibrary& library,
                                              const select::RelaxationIteration& pick,
                                              const model::Rig& rig, const std::string& folder,
                                              std::vector<std::string>& warnings) {
  const deploy::Deployment deployment =
      deploy::plan_deployment(rig, library, &pick.requirements, {});
  if (deployment.collision_monitor) {
    for (const std::string& note : deployment.collision_monitor->notes) {
      if (note.rfind("warning: ", 0) == 0)
        warnings.push_back("deploy/collision_monitor.yaml: " + note);
    }
  }
  return deploy::write_deployment(folder + "/deploy", rig, deployment,
                                  report::deployment_header(rig, &pick.requirements));
}

void append(std::vector<std::string>& to, const std::vector<std::string>& more) {
  to.insert(to.end(), more.begin(), more.end());
}

}  // namespace

std::vector<std::string> write_selection_files(const report::SelectReport& report,
                                               const select::SelectionSpace& space,
                                               const io::StagedFolder& staged, bool renders,
                                               const select::ProgressSink& progress,
                                               std::vector<select::PhaseTime>& phases,
                                               std::vector<std::string>& deployment_warnings) {
  const select::RelaxationIteration* pick = report::chosen_iteration(*report.outcome);
  if (pick == nullptr) return {};
  const std::string& folder = staged.path();
  select::PhaseClock clock(phases, &progress);
  clock.start("files");
  const double parts = renders ? 5 : 4;
  double done = 0;
  const auto next = [&](const char* part) {
    if (progress) progress({"files", done++, parts, "parts", part});
  };
  next("chosen rig");
  const std::string rig_file = write_chosen_rig(report, space.library(), pick->selection, folder);
  std::vector<std::string> written = {rig_file, write_final_requirements(report, *pick, folder)};
  next("Pareto plots");
  append(written, write_pareto_plots(report, *pick, folder));
  next("margin plots");
  append(written, write_margin_plots(space, *pick, folder));
  model::Rig rig = pick->selection.rig;
  rig.file = staged.final_name(rig_file);
  if (renders) {
    next("coverage renders");
    append(written, write_renders(report, space.library(), *pick, rig, folder));
  }
  next("ROS 2 deployment");
  append(written, write_ros_deployment(space.library(), *pick, rig, folder, deployment_warnings));
  clock.stop(std::to_string(written.size()) + " files: the rig, its requirements, plots" +
             (renders ? ", coverage renders" : "") + " and the ROS 2 deployment");
  return written;
}

}  // namespace rigdesign::cli
