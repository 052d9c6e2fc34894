// `rigdesign coverage RIG [--out DIR] [--angles 0,45,90] [--step DEG] [--sweep rotate|arc:R]`:
// SC curves (Cartesian and polar, PNG and SVG), cross-sections at chosen angles, 3D views of
// the FOV volumes (OSMesa), and the numbers as CSV and JSON; with --sweep, the swept coverage
// of a turn in place or an arc (issue 38 item 4) as sweep_<mode>.csv and .png. Runs without a
// display.
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "coverage_files.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/swept_coverage.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"
#include "sweep_files.hpp"
#include "tolerance_figures.hpp"

namespace rigdesign::cli {
namespace {

// 7200 angles at the finest step: the exact path cuts every mount's FOV at each of them.
constexpr double kFinestCoverageStepDeg = 0.05;

struct CoverageOptions {
  std::string rig;
  std::string out;
  std::vector<double> angles_deg = {0, 45, 90, 180};
  double step_deg = 1.0;
  std::string requirements;
  std::string sensors;
  bool raster = false;
  bool no_3d = false;
  SweepOptions sweep_options;  // --sweep (empty: no sweep), --turn-rate, --sweep-time
};

int run_coverage(const CoverageOptions& options, std::ostream& out, std::ostream& err) {
  // --sweep's form is checked by its validator; an empty value means no sweep.
  const std::optional<SweepChoice> sweep_choice = parse_sweep(options.sweep_options.sweep);
  const RigInputs inputs =
      load_rig_inputs(options.rig, options.sensors, options.requirements, &err);
  const std::string folder = options.out.empty()
                                 ? "coverage/" + std::filesystem::path(options.rig).stem().string()
                                 : options.out;
  io::StagedFolder staged(folder, "--out");  // the old pictures or the new set, never a mix
  staged.refuse_inputs_inside(files_read(inputs));

  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(options.step_deg);
  settings.exact = !options.raster;
  const std::optional<SweepRequest> sweep =
      sweep_choice
          ? std::optional(sweep_request(options.sweep_options, *sweep_choice, inputs, settings))
          : std::nullopt;
  const std::vector<model::SectorRequirement> sectors =
      inputs.requirements ? inputs.requirements->sectors : std::vector<model::SectorRequirement>{};
  // Two steps of similar length on the bundled rigs: the cut at every angle, the pictures.
  const int steps = sweep ? 3 : 2;
  ProgressLine progress(err,
                        "coverage: cut at every " + model::format_number(options.step_deg) +
                            " deg, then pictures" + (sweep ? ", then the sweep" : ""),
                        "steps");
  progress.update(0, steps);
  const metrics::RigCoverage coverage =
      metrics::compute_coverage(inputs.rig, inputs.library, sectors, settings);
  progress.update(1, steps);
  std::vector<std::string> files = write_coverage_files(
      inputs.rig, inputs.library, coverage, options.angles_deg, staged.path(), !options.no_3d);
  // Issue 38: SC margin against each mount's pitch and yaw error, where the rig gives them.
  write_tolerance_figures(inputs.rig, inputs.library, sectors, settings, staged.path(), &files);
  std::optional<metrics::SweptCoverage> swept;
  if (sweep) {
    progress.update(2, steps);
    swept = write_sweep_files(inputs, *sweep, staged.path(), files);
  }
  const std::vector<std::string> written = staged.final_names(files);
  staged.commit();
  progress.clear();

  out << inputs.rig.name << ": SC complete min "
      << model::format_number(coverage.complete.min * 100, 3) << " %, mean "
      << model::format_number(coverage.complete.mean * 100, 3) << " %; SC floor min "
      << model::format_number(coverage.floor.min * 100, 3) << " %, mean "
      << model::format_number(coverage.floor.mean * 100, 3) << " % (" << coverage.angles.size()
      << " angles, " << (coverage.exact ? "exact path" : "raster path") << ")\n";
  for (const metrics::SectorCoverage& sector : coverage.sectors) {
    out << "  sector " << sector.sector.name << ": complete min "
        << model::format_number(sector.complete.min * 100, 3) << " % (needs "
        << model::format_number(sector.sector.min_complete_coverage * 100, 3) << "), floor min "
        << model::format_number(sector.floor.min * 100, 3) << " % (needs "
        << model::format_number(sector.sector.min_floor_coverage * 100, 3)
        << "): " << (sector.pass ? "pass" : "FAIL") << '\n';
  }
  if (swept) print_sweep(out, *sweep, *swept);
  out << "wrote " << written.size() << " files:\n";
  for (const std::string& file : written) out << "  " << file << '\n';
  return kOk;
}

}  // namespace

Command setup_coverage(CLI::App& parent) {
  auto options = std::make_shared<CoverageOptions>();
  CLI::App* app = parent.add_subcommand(
      "coverage", "Spatial coverage curves, cross-sections and 3D FOV views (PNG, SVG, CSV, JSON)");
  add_rig_option(*app, options->rig);
  add_out_option(*app, options->out,
                 "curves, sections and views (default coverage/<rig file name>)");
  app->add_option("--angles", options->angles_deg,
                  "Azimuths of the cross-section images, degrees (default 0,45,90,180)")
      ->delimiter(',')
      ->check(finite_in(-360, 360, "degrees in [-360, 360]"));
  app->add_option("--step", options->step_deg, "Angle between SC samples, degrees (default 1)")
      ->check(finite_in(kFinestCoverageStepDeg, 45, "degrees in [0.05, 45]"));
  add_requirements_option(*app, options->requirements);
  add_sensors_option(*app, options->sensors);
  app->add_flag("--raster", options->raster, "Use the fast raster path for the curves");
  app->add_flag("--no-3d", options->no_3d, "Skip the OSMesa 3D views");
  CLI::Option* sweep =
      app->add_option("--sweep", options->sweep_options.sweep,
                      "Swept coverage: rotate (in place, both ways) or arc:R (R [m], > 0 left) at "
                      "the requirements' robot speed; writes sweep_<mode>.csv and .png")
          ->check(CLI::Validator(
              [](std::string& text) -> std::string {
                return parse_sweep(text) ? std::string()
                                         : "is " + text + " (expected " + kSweepForm + ")";
              },
              "rotate|arc:R"));
  app->add_option("--turn-rate", options->sweep_options.turn_rate_deg,
                  "Turn rate of --sweep rotate, deg/s (default: the body's rim at the "
                  "requirements' robot speed)")
      ->check(positive_up_to(3600, "deg/s in (0, 3600]"))
      ->needs(sweep);
  app->add_option("--sweep-time", options->sweep_options.sweep_time,
                  "How long the --sweep motion runs, s (default: one full turn, or the distance "
                  "of interest at the robot speed)")
      ->check(positive_up_to(600, "seconds in (0, 600]"))
      ->needs(sweep);
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_coverage(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
