// `rigdesign coverage RIG [--out DIR] [--angles 0,45,90] [--step DEG]`: SC curves (Cartesian
// and polar, PNG and SVG), cross-sections at chosen angles, 3D views of the FOV volumes
// (OSMesa), and the numbers as CSV and JSON. Runs without a display.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "coverage_files.hpp"
#include "inputs.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/io/staged_folder.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

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
};

int run_coverage(const CoverageOptions& options, std::ostream& out, std::ostream& err) {
  const RigInputs inputs = load_rig_inputs(options.rig, options.sensors, options.requirements);
  const std::string folder = options.out.empty()
                                 ? "coverage/" + std::filesystem::path(options.rig).stem().string()
                                 : options.out;
  io::StagedFolder staged(folder, "--out");  // the old pictures or the new set, never a mix
  staged.refuse_inputs_inside(files_read(inputs));

  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(options.step_deg);
  settings.exact = !options.raster;
  const std::vector<model::SectorRequirement> sectors =
      inputs.requirements ? inputs.requirements->sectors : std::vector<model::SectorRequirement>{};
  // Two steps of similar length on the bundled rigs: the cut at every angle, the pictures.
  ProgressLine progress(
      err,
      "coverage: cut at every " + model::format_number(options.step_deg) + " deg, then pictures",
      "steps");
  progress.update(0, 2);
  const metrics::RigCoverage coverage =
      metrics::compute_coverage(inputs.rig, inputs.library, sectors, settings);
  progress.update(1, 2);
  const std::vector<std::string> written = staged.final_names(write_coverage_files(
      inputs.rig, inputs.library, coverage, options.angles_deg, staged.path(), !options.no_3d));
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
  out << "wrote " << written.size() << " files:\n";
  for (const std::string& file : written) out << "  " << file << '\n';
  return kOk;
}

}  // namespace

Command setup_coverage(CLI::App& parent) {
  auto options = std::make_shared<CoverageOptions>();
  CLI::App* app = parent.add_subcommand(
      "coverage", "Spatial coverage curves, cross-sections and 3D FOV views (PNG, SVG, CSV, JSON)");
  app->add_option("rig,--rig", options->rig, "Rig file (rigs/*.yaml; positional or --rig)")
      ->required();
  app->add_option("--out", options->out, "Output folder (default: coverage/<rig file name>)");
  app->add_option("--angles", options->angles_deg,
                  "Azimuths of the cross-section images, degrees (default 0,45,90,180)")
      ->delimiter(',')
      ->check(finite_in(-360, 360, "degrees in [-360, 360]"));
  app->add_option("--step", options->step_deg, "Angle between SC samples, degrees (default 1)")
      ->check(finite_in(kFinestCoverageStepDeg, 45, "degrees in [0.05, 45]"));
  app->add_option("--requirements", options->requirements,
                  "Requirements whose sector thresholds are drawn (default: the rig's)");
  app->add_option("--sensors", options->sensors, "Sensor library");
  app->add_flag("--raster", options->raster, "Use the fast raster path for the curves");
  app->add_flag("--no-3d", options->no_3d, "Skip the OSMesa 3D views");
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_coverage(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
