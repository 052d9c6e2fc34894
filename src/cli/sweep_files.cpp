#include "sweep_files.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "command.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/swept_plot.hpp"

namespace rigdesign::cli {
namespace {

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

}  // namespace

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

SweepRequest sweep_request(const SweepOptions& options, const SweepChoice& choice,
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

metrics::SweptCoverage write_sweep_files(const RigInputs& inputs, const SweepRequest& request,
                                         const std::string& folder,
                                         std::vector<std::string>& written) {
  std::optional<metrics::SweptCoverage> swept;
  try {
    swept = metrics::swept_coverage(inputs.rig, inputs.library, request.motion, request.settings);
  } catch (const model::InputError& error) {  // too many samples: the options asked for it
    const model::Diagnostic& refusal = error.diagnostics().front();
    require_option(false, "--sweep", refusal.problem, refusal.expected);
  }
  const std::string stem = folder + "/sweep_" + request.label;
  io::write_file_atomically(stem + ".csv", sweep_csv(swept->worst_run()));
  render::plot_swept_coverage(*swept, swept->worst_run(),
                              inputs.rig.name + ": sweep " + request.option + " (" +
                                  sweep_direction(swept->worst_run()) + ")",
                              stem + ".png");
  written.push_back(stem + ".csv");
  written.push_back(stem + ".png");
  return *swept;
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

}  // namespace rigdesign::cli
