// `rigdesign metrics RIG [--requirements FILE] [--sensors FILE] [--filtering-loads FILE] [--format
// json]`: per-sensor and resultant F, R, N, L, bandwidth, driver CPU load and sensor cost (paper 1,
// section 2).
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <ostream>
#include <utility>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "inputs.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/report/metrics_report.hpp"

namespace rigdesign::cli {
namespace {

struct MetricsOptions {
  std::string rig;
  std::string requirements;
  std::string sensors;
  std::string filtering_loads;
  bool json = false;
};

int run_metrics(const MetricsOptions& options, std::ostream& out) {
  const RigInputs inputs = load_rig_inputs(options.rig, options.sensors, options.requirements);
  std::optional<model::FilteringLoads> loads;
  if (!options.filtering_loads.empty()) loads = io::load_filtering_loads(options.filtering_loads);
  const report::MetricsReport report = report::build_metrics_report(inputs, std::move(loads));
  if (options.json) {
    out << report::rig_metrics_json(report);
  } else {
    report::print_rig_metrics(report, out);
  }
  return kOk;
}

}  // namespace

Command setup_metrics(CLI::App& parent) {
  auto options = std::make_shared<MetricsOptions>();
  CLI::App* app = parent.add_subcommand(
      "metrics", "Per-sensor and resultant F, R, N, L, bandwidth, driver CPU load and cost");
  add_rig_option(*app, options->rig);
  add_requirements_option(*app, options->requirements);
  add_sensors_option(*app, options->sensors);
  app->add_option(
      "--filtering-loads", options->filtering_loads,
      "Measured filtering loads (`rigdesign filter --write-loads`): adds U_f per mount");
  add_format_option(*app, options->json);
  return {app, [options](std::ostream& out, std::ostream&) { return run_metrics(*options, out); }};
}

}  // namespace rigdesign::cli
