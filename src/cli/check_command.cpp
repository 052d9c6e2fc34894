// `rigdesign check FILE... [--requirements FILE] [--nav2 FILE] [--collision-monitor FILE]
// [--filters [MOUNT=]FILE]...
// [--format text|json|junit|github] [--output FILE]`:
// validates rig, sensor and requirement files for CI and judges rigs against requirements.
// Exit 0 when all pass, 1 when a requirement fails, 2 when any input is invalid.
#include <CLI/CLI.hpp>
#include <limits>
#include <memory>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "number_checks.hpp"
#include "progress_line.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/report/check_github.hpp"
#include "rigdesign/report/check_json.hpp"
#include "rigdesign/report/check_junit.hpp"
#include "rigdesign/report/check_text.hpp"
#include "rigdesign/report/file_report.hpp"

namespace rigdesign::cli {
namespace {

struct CheckOptions {
  std::vector<std::string> files;
  std::string requirements;
  std::string sensors;
  std::string format = "text";
  std::string output;
  report::DeploymentFiles deployment;
  double max_seconds = std::numeric_limits<double>::infinity();
};

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<report::FileReport> reports;
  // The tolerance poses are the one part that can run for minutes (76 moved rigs per mount
  // with a six-axis tolerance): counted on a progress line, stopped at --max-seconds.
  ProgressLine progress(err, "check", "tolerance poses");
  metrics::WorkBudget budget;
  budget.max_seconds = options.max_seconds;
  budget.progress = [&progress](double done, double total) { progress.update(done, total); };
  for (const std::string& file : options.files) {
    progress.retitle("check " + file);
    reports.push_back(report::check_file(file, options.sensors, options.requirements,
                                         options.deployment, &budget));
  }
  progress.clear();
  const int exit_code = check_exit_code(reports);
  std::string text;
  if (options.format == "json") {
    text = report::format_json(reports, exit_code);
  } else if (options.format == "junit") {
    text = report::format_junit(reports);
  } else if (options.format == "github") {
    text = report::format_github(reports);
  } else {
    text = report::format_text(reports);
  }
  if (options.output.empty()) {
    out << text;
  } else {
    io::write_file_atomically(options.output, text);
  }
  return exit_code;
}

}  // namespace

int check_exit_code(const std::vector<report::FileReport>& reports) {
  int exit_code = kOk;
  for (const report::FileReport& report : reports) {
    if (report.invalid()) exit_code = kBadInput;
    if (report.failing() && exit_code == kOk) exit_code = kRequirementFails;
  }
  return exit_code;
}

Command setup_check(CLI::App& parent) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* app = parent.add_subcommand(
      "check",
      "Validate rig, sensor and requirement files and judge rigs against requirements "
      "(exit 0 pass, 1 a requirement fails, 2 invalid input)");
  app->add_option("files", options->files, "Rig, sensors.yaml or requirement files")->required();
  add_requirements_option(*app, options->requirements);
  add_sensors_option(*app, options->sensors);
  app->add_option("--global-frame-height", options->deployment.global_frame_height,
                  "Height [m] of the nav2 file's global frame (odom) above the floor, as "
                  "export --global-frame-height wrote it (default 0)")
      ->check(finite_in(-10.0, 10.0, "a height in metres within +-10"));
  app->add_option("--nav2", options->deployment.nav2,
                  "nav2 costmap parameters the rig is deployed with: every mount needs an "
                  "observation source whose range and height band keep the requirements");
  app->add_option("--collision-monitor", options->deployment.collision_monitor,
                  "nav2 collision_monitor parameters (Humble or Jazzy): fails when a zone's "
                  "edge has an arc none of its sources sees (D4)");
  app->add_option("--filters", options->deployment.filters,
                  "Self-filter file (laser_filters chains, pcl_ros crop boxes), FILE or "
                  "MOUNT=FILE; repeatable. Fails when a filter hides a required sector");
  app->add_option("--format", options->format,
                  "Report format: text; json; junit (file, line, time, measured value and "
                  "margin per requirement); github (workflow-command annotations on the rig's "
                  "lines)")
      ->check(CLI::IsMember({"text", "json", "junit", "github"}))
      ->capture_default_str();
  app->add_option("--output", options->output,
                  "Write the report to this file (atomically) instead of standard output");
  app->add_option("--max-seconds", options->max_seconds,
                  "Stop with exit 2 when the mounting-tolerance poses (the part that can run for "
                  "minutes) are still being judged this many seconds after the start, saying "
                  "how many were judged and about how long the rest needs (default: no limit)")
      ->check(positive_up_to(1e7, "a time in seconds, > 0"));
  return {app, [options](std::ostream& out, std::ostream& err) {
            return run_check(*options, out, err);
          }};
}

}  // namespace rigdesign::cli
