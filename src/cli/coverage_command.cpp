// `rigdesign coverage RIG [--out DIR] [--angles 0,45,90] [--step DEG] [--sweep rotate|arc:R]`:
// SC curves (Cartesian and polar, PNG and SVG), cross-sections at chosen angles, 3D views of
// the FOV volumes (OSMesa), and the numbers as CSV and JSON; with --sweep, the swept coverage
// of a turn in place or an arc (issue 38 item 4) as sweep_<mode>.csv and .png. Runs without a
// display.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

#include "app.hpp"
#include "command.hpp"
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
#include "rigdesign/render/swept_plot.hpp"

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
  std::string sweep;                    // rotate or arc:R; empty: no sweep
  std::optional<double> turn_rate_deg;  // [deg/s] rotate; default: the rim at the robot speed
  std::optional<double> sweep_time;     // [s] default: a full turn, or d at the robot speed
};

constexpr const char* kSweepForm =
    "rotate or arc:R (R: the arc's radius [m], not 0; > 0 turns left)";

// `--sweep`'s value: the motion's kind, an arc's radius and the files' name (sweep_<label>).
struct SweepChoice {
  metrics::SweepKind kind = metrics::SweepKind::rotate;
  double arc_radius = 0.0;
  std::string label;
};

std::optional<SweepChoice> parse_sweep(const std::string& text) {
  if (text == "rotate") return SweepChoice{metrics::SweepKind::rotate, 0.0, "rotate"};
  const std::string prefix = "arc:";
  if (text.rfind(prefix, 0) != 0 || text.size() == prefix.size()) return std::nullopt;
  const std::string number = text.substr(prefix.size());
  if (number.find_first_of(" \t\n") != std::string::npos) return std::nullopt;  // strtod skips it
  char* end = nullptr;
  const double radius = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || !std::isfinite(radius) || radius == 0.0)
    return std::nullopt;
  return SweepChoice{metrics::SweepKind::arc, radius, "arc_" + model::format_number(radius)};
}

// The motion and settings `--sweep` asks for, from the options and the requirements (R5's
// speed and deceleration, R6's obstacle size). Checked before any work starts.
struct SweepRequest {
  std::string option;  // as given: rotate, arc:0.8
  std::string label;   // in file names: rotate, arc_0.8
  metrics::SweepMotion motion;
  metrics::SweepSettings settings;
};

SweepRequest sweep_request(const CoverageOptions& options, const SweepChoice& choice,
                           const RigInputs& inputs, const metrics::CoverageSettings& coverage) {
  const std::optional<model::Requirements>& requirements = inputs.requirements;
  const bool has_speed = requirements && requirements->robot_speed;
  const std::string no_speed = requirements ? requirements->file + " states no robot_speed"
                                            : "the rig names no requirements";
  SweepRequest request;
  request.option = options.sweep;
  request.label = choice.label;
  request.motion.kind = choice.kind;
  if (choice.kind == metrics::SweepKind::rotate) {
    require_option(options.turn_rate_deg || has_speed, "--turn-rate",
                   "is needed: " + no_speed + " (the default turns the rim at the robot speed)",
                   "--turn-rate DEG_PER_S, or requirements with robot_speed");
    request.motion.turn_rate =
        options.turn_rate_deg
            ? model::deg_to_rad(*options.turn_rate_deg)
            : metrics::rim_turn_rate(requirements->robot_speed->speed, inputs.rig.body);
  } else {
    require_option(has_speed, "--sweep", options.sweep + " drives at the robot speed: " + no_speed,
                   "requirements with robot_speed (--requirements FILE)");
    request.motion.arc_radius = choice.arc_radius;
    request.motion.speed = requirements->robot_speed->speed;
  }
  request.settings.horizon = options.sweep_time.value_or(
      metrics::default_horizon(request.motion, inputs.rig.distance_of_interest));
  if (requirements) {
    request.settings.cell = requirements->smallest_obstacle.value_or(metrics::kDefaultSweepCell);
    request.settings.deceleration = requirements->braking_deceleration();
  }
  request.settings.coverage = coverage;
  return request;
}

// One row per cell of the run: centre, first-seen and reached times (empty: never), late.
std::string sweep_csv(const metrics::SweepRun& run) {
  std::ostringstream csv;
  csv << "x_m,y_m,first_seen_s,reached_s,late\n";
  const auto time = [](const std::optional<double>& t) {
    return t ? model::format_number(*t, 8) : std::string();
  };
  for (const metrics::SweepCell& cell : run.cells) {
    csv << model::format_number(cell.centre.x(), 8) << ','
        << model::format_number(cell.centre.y(), 8) << ',' << time(cell.first_seen) << ','
        << time(cell.reached) << ',' << (cell.late ? "1" : "0") << '\n';
  }
  return csv.str();
}

std::string sweep_direction(const metrics::SweepRun& run) {
  if (run.motion.kind == metrics::SweepKind::arc) return "arc";
  return run.motion.turn_rate > 0 ? "left" : "right";
}

// What a run sees: the share of cells, and for a turn the angle after which all are seen.
void print_sweep_run(std::ostream& out, const metrics::SweepRun& run) {
  out << "  " << sweep_direction(run) << ": " << model::format_number(run.seen_share * 100, 4)
      << " % of the cells seen";
  if (run.all_seen_time && run.motion.kind == metrics::SweepKind::rotate) {
    out << "; everything seen after a turn of "
        << model::format_number(
               model::rad_to_deg(*run.all_seen_time * std::abs(run.motion.turn_rate)), 4)
        << " deg (" << model::format_number(*run.all_seen_time, 3) << " s)";
  } else if (run.all_seen_time) {
    out << ", all after " << model::format_number(*run.all_seen_time, 3) << " s";
  } else {
    out << "; the others never within the horizon";
  }
  out << '\n';
}

// The check: the swept path's cells seen at least the stopping time before the body.
void print_sweep_check(std::ostream& out, const metrics::SweptCoverage& sweep) {
  const metrics::SweepRun& run = sweep.worst_run();
  out << "  swept path (" << sweep_direction(run) << "): " << run.swept << " cells, "
      << run.reached_too_soon
      << " reached within t_stop = " << model::format_number(sweep.stopping_time, 3)
      << " s (not judged), " << run.late << " late\n";
  if (run.worst_late) {
    const metrics::SweepCell& cell = run.cells[*run.worst_late];
    out << "  worst: cell at (" << model::format_number(cell.centre.x(), 3) << ", "
        << model::format_number(cell.centre.y(), 3) << ") m, reached at "
        << model::format_number(*cell.reached, 3) << " s, "
        << (cell.first_seen ? "first seen " + model::format_number(*cell.first_seen, 3) + " s"
                            : std::string("never seen before"))
        << '\n';
  }
  out << "  check: no cell of the swept path unseen within t_stop of the body: "
      << (run.swept == run.reached_too_soon ? "pass (nothing to judge)"
          : sweep.pass()                    ? "pass"
                                            : "FAIL")
      << '\n';
}

void print_sweep(std::ostream& out, const SweepRequest& request,
                 const metrics::SweptCoverage& sweep) {
  const metrics::SweepMotion& motion = request.motion;
  out << "sweep " << request.option << ": ";
  if (motion.kind == metrics::SweepKind::rotate) {
    out << "turning in place at " << model::format_number(model::rad_to_deg(motion.turn_rate), 4)
        << " deg/s, both ways";
  } else {
    out << "arc of radius " << model::format_number(motion.arc_radius, 4) << " m at "
        << model::format_number(motion.speed, 4) << " m/s";
  }
  out << ", " << model::format_number(sweep.horizon, 4) << " s; " << sweep.worst_run().cells.size()
      << " cells of " << model::format_number(sweep.cell * 100, 3) << " cm within "
      << model::format_number(sweep.distance, 4) << " m, time step "
      << model::format_number(sweep.time_step * 1000, 3) << " ms\n";
  for (const metrics::SweepRun& run : sweep.runs) print_sweep_run(out, run);
  print_sweep_check(out, sweep);
}

int run_coverage(const CoverageOptions& options, std::ostream& out, std::ostream& err) {
  // --sweep's form is checked by its validator; an empty value means no sweep.
  const std::optional<SweepChoice> sweep_choice = parse_sweep(options.sweep);
  const RigInputs inputs = load_rig_inputs(options.rig, options.sensors, options.requirements);
  const std::string folder = options.out.empty()
                                 ? "coverage/" + std::filesystem::path(options.rig).stem().string()
                                 : options.out;
  io::StagedFolder staged(folder, "--out");  // the old pictures or the new set, never a mix
  staged.refuse_inputs_inside(files_read(inputs));

  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(options.step_deg);
  settings.exact = !options.raster;
  const std::optional<SweepRequest> sweep =
      sweep_choice ? std::optional(sweep_request(options, *sweep_choice, inputs, settings))
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
  std::optional<metrics::SweptCoverage> swept;
  if (sweep) {
    progress.update(2, steps);
    try {
      swept = metrics::swept_coverage(inputs.rig, inputs.library, sweep->motion, sweep->settings);
    } catch (const model::InputError& error) {  // too many samples: the options asked for it
      const model::Diagnostic& refusal = error.diagnostics().front();
      require_option(false, "--sweep", refusal.problem, refusal.expected);
    }
    const std::string stem = staged.path() + "/sweep_" + sweep->label;
    io::write_file_atomically(stem + ".csv", sweep_csv(swept->worst_run()));
    render::plot_swept_coverage(*swept, swept->worst_run(),
                                inputs.rig.name + ": sweep " + sweep->option + " (" +
                                    sweep_direction(swept->worst_run()) + ")",
                                stem + ".png");
    files.push_back(stem + ".csv");
    files.push_back(stem + ".png");
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
  CLI::Option* sweep =
      app->add_option("--sweep", options->sweep,
                      "Swept coverage: rotate (in place, both ways) or arc:R (R [m], > 0 left) at "
                      "the requirements' robot speed; writes sweep_<mode>.csv and .png")
          ->check(CLI::Validator(
              [](std::string& text) -> std::string {
                return parse_sweep(text) ? std::string()
                                         : "is " + text + " (expected " + kSweepForm + ")";
              },
              "rotate|arc:R"));
  app->add_option("--turn-rate", options->turn_rate_deg,
                  "Turn rate of --sweep rotate, deg/s (default: the body's rim at the "
                  "requirements' robot speed)")
      ->check(positive_up_to(3600, "deg/s in (0, 3600]"))
      ->needs(sweep);
  app->add_option("--sweep-time", options->sweep_time,
                  "How long the --sweep motion runs, s (default: one full turn, or the distance "
                  "of interest at the robot speed)")
      ->check(positive_up_to(600, "seconds in (0, 600]"))
      ->needs(sweep);
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_coverage(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
