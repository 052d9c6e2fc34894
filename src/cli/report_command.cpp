// `rigdesign report RIG [--out DIR] [--requirements FILE] [--sensors FILE] [--step DEG]`: one
// self-contained HTML page explaining the rig (verdicts with margins, metrics with limiting
// sensors, SC plots, cross-sections, 3D views, N-1 table, costs), with the pictures beside it.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "coverage_files.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/metrics/pair_findings.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/metrics/tolerance_verdicts.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/report/html_report.hpp"
#include "tolerance_figures.hpp"

namespace rigdesign::cli {
namespace {

struct ReportOptions {
  std::string rig;
  std::string out;
  std::string requirements;
  std::string sensors;
  double step_deg = 1.0;
};

int run_report(const ReportOptions& options, std::ostream& out) {
  const RigInputs inputs =
      load_rig_inputs(options.rig, options.sensors, options.requirements, &out);
  const std::string folder = options.out.empty()
                                 ? "report/" + std::filesystem::path(options.rig).stem().string()
                                 : options.out;
  io::StagedFolder staged(folder, "--out");
  staged.refuse_inputs_inside(files_read(inputs));

  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(options.step_deg);
  const std::vector<model::SectorRequirement> sectors =
      inputs.requirements ? inputs.requirements->sectors : std::vector<model::SectorRequirement>{};
  const metrics::RigCoverage coverage =
      metrics::compute_coverage(inputs.rig, inputs.library, sectors, settings);
  const metrics::ResultantMetrics resultant =
      metrics::compute_resultant(inputs.rig, inputs.library);
  report::ReportContent content;
  content.inputs = &inputs;
  content.metrics = &resultant;
  content.coverage = &coverage;
  if (inputs.requirements) {
    content.results = metrics::evaluate_requirements(inputs.rig, resultant, *inputs.requirements,
                                                     &coverage, &inputs.library);
    // Issue 38: the sectors again over the mounts' tolerance boxes, when the rig gives any.
    for (metrics::RequirementResult& result : metrics::tolerance_verdicts(
             inputs.rig,
             metrics::tolerance_coverage(inputs.rig, inputs.library, sectors, settings)))
      content.results.push_back(std::move(result));
    // Crosstalk (D5) and calibration overlap (R9), as check judges them.
    for (metrics::RequirementResult& result :
         metrics::pair_findings(inputs.rig, inputs.library, &*inputs.requirements).verdicts)
      content.results.push_back(std::move(result));
  }

  const std::string figures = staged.path() + "/figures";
  std::filesystem::create_directories(figures);
  const std::vector<double> angles = {0, 90, 180, 270};
  write_coverage_files(inputs.rig, inputs.library, coverage, angles, figures, true);
  content.figures = coverage_figures(figures, angles);
  // Issue 38: SC margin against each mount's pitch and yaw error, where the rig gives them.
  for (report::ReportFigure& figure :
       write_tolerance_figures(inputs.rig, inputs.library, sectors, settings, figures))
    content.figures.push_back(std::move(figure));

  const std::string page = staged.path() + "/report.html";
  io::write_file_atomically(page, report::html_report(content));
  staged.commit();
  out << inputs.rig.name << ": report " << staged.final_name(page) << " (self-contained; pictures "
      << "also in " << staged.final_name(figures) << ")\n";
  std::size_t failed = 0;
  for (const metrics::RequirementResult& result : content.results) {
    failed += result.verdict == metrics::Verdict::fail ? 1 : 0;
  }
  return failed == 0 ? kOk : kRequirementFails;
}

}  // namespace

Command setup_report(CLI::App& parent) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* app = parent.add_subcommand(
      "report",
      "One self-contained HTML page per rig: verdicts with margins, metrics, SC plots, "
      "sections, 3D views, N-1, costs (exit 1 when a requirement fails)");
  add_rig_option(*app, options->rig);
  add_out_option(*app, options->out, "the page and its pictures (default report/<rig file name>)");
  add_requirements_option(*app, options->requirements);
  add_sensors_option(*app, options->sensors);
  app->add_option("--step", options->step_deg, "Azimuth step of the coverage cut [deg]")
      ->check(finite_in(0.1, 45.0, "degrees in [0.1, 45]"))
      ->capture_default_str();
  return {app, [options](std::ostream& out, std::ostream&) { return run_report(*options, out); }};
}

}  // namespace rigdesign::cli
