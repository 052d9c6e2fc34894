#include "rigdesign/report/file_report.hpp"

#include <algorithm>
#include <chrono>

#include "rigdesign/deploy/collision_monitor_check.hpp"
#include "rigdesign/deploy/deployed_check.hpp"
#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/deploy/ros/nav2/collision_monitor_reader.hpp"
#include "rigdesign/deploy/ros/nav2/costmap_params_reader.hpp"
#include "rigdesign/deploy/ros/self_filters/self_filters_reader.hpp"
#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/policy_loader.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/metrics/coverage_findings.hpp"
#include "rigdesign/metrics/mount_placement_verdicts.hpp"
#include "rigdesign/metrics/pair_findings.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/metrics/tolerance_coverage.hpp"
#include "rigdesign/metrics/tolerance_verdicts.hpp"

namespace rigdesign::report {
namespace {

using Clock = std::chrono::steady_clock;

// Seconds since `start` on the monotonic clock.
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string library_summary(const std::string& path) {
  const model::SensorLibrary library = io::load_sensor_library(path);
  std::size_t modes = 0;
  for (const model::Sensor& sensor : library.sensors) modes += sensor.modes.size();
  return "sensor library is valid: " + std::to_string(library.sensors.size()) + " sensors, " +
         std::to_string(modes) + " modes";
}

std::string requirements_summary(const std::string& path) {
  const model::Requirements requirements = io::load_requirements(path);
  return "requirements '" + requirements.name + "' are valid";
}

std::string catalog_summary(const std::string& path, const std::string& sensors_path) {
  const model::Catalog catalog = io::load_catalog(path);
  io::check_catalog_references(catalog, io::load_catalog_library(catalog, sensors_path))
      .throw_if_errors();
  return "catalog '" + catalog.name + "' is valid: " + std::to_string(catalog.slots.size()) +
         " slots, " + std::to_string(catalog.sensors.size()) + " candidate sensors";
}

std::string policy_summary(const std::string& path) {
  const model::RelaxationPolicy policy = io::load_policy(path);
  return "relaxation policy '" + policy.name +
         "' is valid: " + std::to_string(policy.steps.size()) + " steps";
}

std::string rig_summary(const io::RigInputs& inputs) {
  std::string text = "rig '" + inputs.rig.name +
                     "' is valid: " + std::to_string(inputs.rig.mounts.size()) +
                     " mounts, sensors from " + inputs.library.file;
  if (inputs.requirements) text += ", requirements from " + inputs.requirements->file;
  return text;
}

// The nav2 sources and the filters of every self-filter file; `MOUNT=FILE` filters MOUNT.
deploy::DeployedConfig load_deployment(const DeploymentFiles& files, const model::Rig& rig) {
  deploy::DeployedConfig config;
  if (!files.nav2.empty())
    config = deploy::load_deployed_sources(files.nav2, rig, files.global_frame_height);
  for (const std::string& spec : files.filters) {
    const std::size_t equals = spec.find('=');
    const std::string mount = equals == std::string::npos ? "" : spec.substr(0, equals);
    const std::string file = equals == std::string::npos ? spec : spec.substr(equals + 1);
    const bool known =
        mount.empty() || std::any_of(rig.mounts.begin(), rig.mounts.end(),
                                     [&](const model::Mount& m) { return m.id == mount; });
    if (!known) {
      throw model::InputError(model::Diagnostic{{"(command line)", 0, 0},
                                                "--filters",
                                                "'" + mount + "' is no mount of " + rig.file,
                                                "FILE, or MOUNT=FILE for a mount of the rig"});
    }
    for (deploy::DeployedFilter& filter : deploy::load_self_filters(file, mount, rig))
      config.filters.push_back(std::move(filter));
  }
  return config;
}

// The collision monitor's file, its sources matched to mounts by name or by the topics
// `export` gives them (the driver's, or the self-filter's output).
deploy::DeployedCollisionMonitor load_monitor(const std::string& path,
                                              const io::RigInputs& inputs) {
  const deploy::Deployment deployment =
      deploy::plan_deployment(inputs.rig, inputs.library, nullptr, deploy::DeployOptions{});
  std::vector<deploy::MountTopic> topics;
  for (const deploy::SourceConfig& source : deployment.costmap.sources) {
    topics.emplace_back(source.topic, source.mount_id);
    if (source.raw_topic != source.topic) topics.emplace_back(source.raw_topic, source.mount_id);
  }
  return deploy::load_collision_monitor(path, inputs.rig, topics);
}

// Appends D4 for each zone of `monitor`, timed from `started`.
void judge_monitor(const io::RigInputs& inputs, const deploy::DeployedCollisionMonitor& monitor,
                   FileReport& report) {
  const auto step = Clock::now();
  std::vector<metrics::RequirementResult> results =
      deploy::check_collision_monitor(inputs.rig, inputs.library, monitor);
  const double seconds = seconds_since(step);
  for (metrics::RequirementResult& result : results) {
    report.results.push_back(std::move(result));
    report.result_seconds.push_back(seconds);
  }
}

// The verdicts on the rig and its deployment, each with the time of what it rests on.
void judge_rig(const io::RigInputs& inputs, const std::optional<deploy::DeployedConfig>& config,
               const metrics::WorkBudget* budget, FileReport& report) {
  auto step = Clock::now();
  const metrics::ResultantMetrics metrics = metrics::compute_resultant(inputs.rig, inputs.library);
  const double resultant_seconds = seconds_since(step);
  step = Clock::now();
  std::optional<metrics::RigCoverage> coverage;
  if (!inputs.requirements->sectors.empty()) {
    coverage = metrics::compute_coverage(inputs.rig, inputs.library, inputs.requirements->sectors);
  }
  const double coverage_seconds = seconds_since(step);
  // What `metrics` warns about (a mount that sees none of the area), check says too.
  if (coverage) {
    for (model::Diagnostic& finding : metrics::coverage_findings(inputs.rig, metrics, *coverage))
      report.diagnostics.push_back(std::move(finding));
  }
  step = Clock::now();
  report.results = metrics::evaluate_requirements(inputs.rig, metrics, *inputs.requirements,
                                                  coverage ? &*coverage : nullptr, &inputs.library);
  const double judge_seconds = seconds_since(step);
  for (const metrics::RequirementResult& result : report.results) {
    report.result_seconds.push_back(resultant_seconds + judge_seconds +
                                    (result.metric.rfind("SC", 0) == 0 ? coverage_seconds : 0.0));
  }
  // Issue 38: each sector again over the mounts' tolerance boxes, when the rig gives any.
  step = Clock::now();
  const std::vector<metrics::SectorTolerance> tolerance = metrics::tolerance_coverage(
      inputs.rig, inputs.library, inputs.requirements->sectors, {}, budget);
  const double tolerance_seconds = seconds_since(step);
  for (metrics::RequirementResult& result : metrics::tolerance_verdicts(inputs.rig, tolerance)) {
    report.results.push_back(std::move(result));
    report.result_seconds.push_back(tolerance_seconds);
  }
  if (!config) return;
  step = Clock::now();
  deploy::DeploymentCheck deployed = deploy::check_deployment(
      inputs.rig, inputs.library, *inputs.requirements, *config, coverage ? &*coverage : nullptr);
  const double deployed_seconds = seconds_since(step);
  report.diagnostics.insert(report.diagnostics.end(), deployed.warnings.begin(),
                            deployed.warnings.end());
  for (metrics::RequirementResult& result : deployed.results) {
    report.results.push_back(std::move(result));
    report.result_seconds.push_back(deployed_seconds);
  }
}

void check_rig(const std::string& path, const std::string& sensors_path,
               const std::string& requirements_path, const DeploymentFiles& deployment,
               Clock::time_point started, const metrics::WorkBudget* budget, FileReport& report) {
  const io::RigInputs inputs = io::load_rig_inputs(path, sensors_path, requirements_path);
  report.summary = rig_summary(inputs);
  report.diagnostics = inputs.warnings;
  // Issue 52 item 3: a sensor nothing holds is a warning (B1 and B2 are verdicts, below).
  for (model::Diagnostic& floating : metrics::floating_warnings(inputs.rig, inputs.library))
    report.diagnostics.push_back(std::move(floating));
  // Deployment files are read before the coverage is computed: a typo in them is reported
  // at once, not after the slowest step. They are read with or without requirements: D1
  // (every mount feeds the costmap) needs none.
  std::optional<deploy::DeployedConfig> config;
  if (!deployment.empty()) config = load_deployment(deployment, inputs.rig);
  if (config) {
    report.diagnostics.insert(report.diagnostics.end(), config->warnings.begin(),
                              config->warnings.end());
  }
  std::optional<deploy::DeployedCollisionMonitor> monitor;
  if (!deployment.collision_monitor.empty()) {
    monitor = load_monitor(deployment.collision_monitor, inputs);
    report.diagnostics.insert(report.diagnostics.end(), monitor->warnings.begin(),
                              monitor->warnings.end());
  }
  report.load_seconds = seconds_since(started);
  // Issue 38: crosstalk (D5, needs no requirements) and calibration overlap (R9).
  const auto pairs_started = Clock::now();
  metrics::PairFindings pairs = metrics::pair_findings(
      inputs.rig, inputs.library, inputs.requirements ? &*inputs.requirements : nullptr);
  const double pairs_seconds = seconds_since(pairs_started);
  report.diagnostics.insert(report.diagnostics.end(), pairs.warnings.begin(), pairs.warnings.end());
  if (inputs.requirements) {
    judge_rig(inputs, config, budget, report);
  } else if (config) {
    const model::Requirements none;  // only what every deployment must keep is judged
    deploy::DeploymentCheck deployed =
        deploy::check_deployment(inputs.rig, inputs.library, none, *config, nullptr);
    report.diagnostics.insert(report.diagnostics.end(), deployed.warnings.begin(),
                              deployed.warnings.end());
    for (metrics::RequirementResult& result : deployed.results) {
      report.results.push_back(std::move(result));
      report.result_seconds.push_back(seconds_since(started));
    }
  }
  if (monitor) judge_monitor(inputs, *monitor, report);
  for (metrics::RequirementResult& result : pairs.verdicts) {
    report.results.push_back(std::move(result));
    report.result_seconds.push_back(pairs_seconds);
  }
  // Issue 52: B1 and B2, every sensor where it can be bolted on (needs no requirements).
  const auto placement_started = Clock::now();
  std::vector<metrics::RequirementResult> placement =
      metrics::placement_verdicts(inputs.rig, inputs.library);
  const double placement_seconds = seconds_since(placement_started);
  for (metrics::RequirementResult& result : placement) {
    report.results.push_back(std::move(result));
    report.result_seconds.push_back(placement_seconds);
  }
}

}  // namespace

bool FileReport::invalid() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(), [](const model::Diagnostic& d) {
    return d.severity == model::Severity::error;
  });
}

bool FileReport::failing() const {
  return count_verdicts(results, metrics::Verdict::fail) > 0;
}

std::size_t count_verdicts(const std::vector<metrics::RequirementResult>& results,
                           metrics::Verdict verdict) {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(),
                    [&](const metrics::RequirementResult& r) { return r.verdict == verdict; }));
}

FileReport check_file(const std::string& path, const std::string& sensors_path,
                      const std::string& requirements_path, const DeploymentFiles& deployment,
                      const metrics::WorkBudget* budget) {
  FileReport report;
  report.file = path;
  const auto started = Clock::now();
  try {
    report.kind = io::detect_file_kind(path);
    switch (*report.kind) {
      case io::FileKind::sensor_library: report.summary = library_summary(path); break;
      case io::FileKind::requirements: report.summary = requirements_summary(path); break;
      case io::FileKind::catalog: report.summary = catalog_summary(path, sensors_path); break;
      case io::FileKind::policy: report.summary = policy_summary(path); break;
      case io::FileKind::rig:
        check_rig(path, sensors_path, requirements_path, deployment, started, budget, report);
        break;
    }
    if (report.load_seconds == 0.0) report.load_seconds = seconds_since(started);
  } catch (const model::InputError& error) {
    report.diagnostics = error.diagnostics();
    report.summary = "invalid";
    report.load_seconds = seconds_since(started);
  }
  return report;
}

}  // namespace rigdesign::report
