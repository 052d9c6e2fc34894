#include "file_report.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "command.hpp"
#include "inputs.hpp"
#include "json_report.hpp"
#include "rigdesign/deploy/deployed_check.hpp"
#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/policy_loader.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/deploy/self_filters_loader.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::cli {
namespace {

std::string rig_summary(const RigInputs& inputs) {
  std::string text = "rig '" + inputs.rig.name +
                     "' is valid: " + std::to_string(inputs.rig.mounts.size()) +
                     " mounts, sensors from " + inputs.library.file;
  if (inputs.requirements) text += ", requirements from " + inputs.requirements->file;
  return text;
}

std::string result_line(const metrics::RequirementResult& result) {
  std::string text = to_string(result.where) + ": " + result.field + ": " +
                     to_string(result.verdict) + ": " + result.id + " " + result.title;
  if (result.actual) {
    text += ": " + result.metric + " = " + model::format_number(*result.actual, 4) +
            (result.unit.empty() ? "" : " " + result.unit);
  }
  text += "; " + result.explanation;
  if (!result.limiting_mounts.empty()) {
    text += " [set by ";
    for (std::size_t i = 0; i < result.limiting_mounts.size(); ++i) {
      text += (i ? ", " : "") + result.limiting_mounts[i];
    }
    text += "]";
  }
  return text;
}

std::string xml_escape(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&apos;"; break;
      default: escaped += c;
    }
  }
  return escaped;
}

std::size_t count(const std::vector<metrics::RequirementResult>& results,
                  metrics::Verdict verdict) {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(),
                    [&](const metrics::RequirementResult& r) { return r.verdict == verdict; }));
}

}  // namespace

bool FileReport::invalid() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(), [](const model::Diagnostic& d) {
    return d.severity == model::Severity::error;
  });
}

bool FileReport::failing() const {
  return count(results, metrics::Verdict::fail) > 0;
}

// The nav2 sources and the filters of every self-filter file; `MOUNT=FILE` filters MOUNT.
deploy::DeployedConfig load_deployment(const DeploymentFiles& files, const model::Rig& rig) {
  deploy::DeployedConfig config;
  if (!files.nav2.empty()) config = io::load_deployed_sources(files.nav2, rig);
  for (const std::string& spec : files.filters) {
    const std::size_t equals = spec.find('=');
    const std::string mount = equals == std::string::npos ? "" : spec.substr(0, equals);
    const std::string file = equals == std::string::npos ? spec : spec.substr(equals + 1);
    const bool known = mount.empty() || std::any_of(rig.mounts.begin(), rig.mounts.end(),
                                                    [&](const model::Mount& m) { return m.id == mount; });
    require_option(known, "--filters", "'" + mount + "' is no mount of " + rig.file,
                   "FILE, or MOUNT=FILE for a mount of the rig");
    for (deploy::DeployedFilter& filter : io::load_self_filters(file, mount, rig))
      config.filters.push_back(std::move(filter));
  }
  return config;
}

FileReport check_file(const std::string& path, const std::string& sensors_path,
                      const std::string& requirements_path, const DeploymentFiles& deployment) {
  FileReport report;
  report.file = path;
  try {
    report.kind = io::detect_file_kind(path);
    switch (*report.kind) {
      case io::FileKind::sensor_library: {
        const model::SensorLibrary library = io::load_sensor_library(path);
        std::size_t modes = 0;
        for (const model::Sensor& sensor : library.sensors) modes += sensor.modes.size();
        report.summary = "sensor library is valid: " + std::to_string(library.sensors.size()) +
                         " sensors, " + std::to_string(modes) + " modes";
        break;
      }
      case io::FileKind::requirements: {
        const model::Requirements requirements = io::load_requirements(path);
        report.summary = "requirements '" + requirements.name + "' are valid";
        break;
      }
      case io::FileKind::catalog: {
        const model::Catalog catalog = io::load_catalog(path);
        io::check_catalog_references(catalog, load_catalog_library(catalog, sensors_path))
            .throw_if_errors();
        report.summary = "catalog '" + catalog.name +
                         "' is valid: " + std::to_string(catalog.slots.size()) + " slots, " +
                         std::to_string(catalog.sensors.size()) + " candidate sensors";
        break;
      }
      case io::FileKind::policy: {
        const model::RelaxationPolicy policy = io::load_policy(path);
        report.summary = "relaxation policy '" + policy.name +
                         "' is valid: " + std::to_string(policy.steps.size()) + " steps";
        break;
      }
      case io::FileKind::rig: {
        const RigInputs inputs = load_rig_inputs(path, sensors_path, requirements_path);
        report.summary = rig_summary(inputs);
        report.diagnostics = inputs.warnings;
        if (inputs.requirements) {
          // Deployment files are read before the coverage is computed: a typo in them is
          // reported at once, not after the slowest step.
          std::optional<deploy::DeployedConfig> config;
          if (!deployment.empty()) config = load_deployment(deployment, inputs.rig);
          const metrics::ResultantMetrics metrics =
              metrics::compute_resultant(inputs.rig, inputs.library);
          std::optional<metrics::RigCoverage> coverage;
          if (!inputs.requirements->sectors.empty()) {
            coverage =
                metrics::compute_coverage(inputs.rig, inputs.library, inputs.requirements->sectors);
          }
          report.results = metrics::evaluate_requirements(inputs.rig, metrics, *inputs.requirements,
                                                          coverage ? &*coverage : nullptr);
          if (config) {
            for (metrics::RequirementResult& result :
                 deploy::check_deployment(inputs.rig, inputs.library, *inputs.requirements, *config,
                                          coverage ? &*coverage : nullptr)) {
              report.results.push_back(std::move(result));
            }
          }
        }
        break;
      }
    }
  } catch (const model::InputError& error) {
    report.diagnostics = error.diagnostics();
    report.summary = "invalid";
  }
  return report;
}

std::string format_text(const std::vector<FileReport>& reports) {
  std::ostringstream out;
  std::size_t invalid = 0, pass = 0, fail = 0, skipped = 0;
  for (const FileReport& report : reports) {
    if (!report.invalid()) out << report.file << ": " << report.summary << '\n';
    for (const model::Diagnostic& diagnostic : report.diagnostics)
      out << diagnostic.message() << '\n';
    for (const metrics::RequirementResult& result : report.results)
      out << result_line(result) << '\n';
    invalid += report.invalid() ? 1 : 0;
    pass += count(report.results, metrics::Verdict::pass);
    fail += count(report.results, metrics::Verdict::fail);
    skipped += count(report.results, metrics::Verdict::not_evaluated);
  }
  out << "check: " << reports.size() << " file(s), " << invalid
      << " invalid; requirements: " << pass << " pass, " << fail << " fail, " << skipped
      << " not evaluated\n";
  return out.str();
}

std::string format_json(const std::vector<FileReport>& reports, int exit_code) {
  nlohmann::json files = nlohmann::json::array();
  for (const FileReport& report : reports) {
    nlohmann::json diagnostics = nlohmann::json::array();
    for (const model::Diagnostic& diagnostic : report.diagnostics)
      diagnostics.push_back(to_json(diagnostic));
    nlohmann::json results = nlohmann::json::array();
    for (const metrics::RequirementResult& result : report.results)
      results.push_back(to_json(result));
    files.push_back({{"file", report.file},
                     {"kind", report.kind ? to_string(*report.kind) : "unknown"},
                     {"status", report.invalid()   ? "invalid"
                                : report.failing() ? "fail"
                                                   : "pass"},
                     {"summary", report.summary},
                     {"diagnostics", diagnostics},
                     {"requirements", results}});
  }
  return nlohmann::json({{"files", files}, {"exit_code", exit_code}}).dump(2) + "\n";
}

// JUnit XML as Jenkins, GitLab and GitHub test reporters read it: one <testsuite> per file,
// one <testcase> for the file's validity and one per requirement.
std::string format_junit(const std::vector<FileReport>& reports) {
  std::ostringstream suites;
  std::size_t all_tests = 0, all_failures = 0, all_errors = 0, all_skipped = 0;
  for (const FileReport& report : reports) {
    const std::size_t tests = 1 + report.results.size();
    const std::size_t failures = count(report.results, metrics::Verdict::fail);
    const std::size_t skipped = count(report.results, metrics::Verdict::not_evaluated);
    const std::size_t errors = report.invalid() ? 1 : 0;
    all_tests += tests;
    all_failures += failures;
    all_errors += errors;
    all_skipped += skipped;
    const std::string name = xml_escape(report.file);
    suites << "  <testsuite name=\"" << name << "\" tests=\"" << tests << "\" failures=\""
           << failures << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\">\n";
    suites << "    <testcase classname=\"" << name << "\" name=\"valid "
           << xml_escape(report.kind ? to_string(*report.kind) : "file") << "\">\n";
    if (report.invalid()) {
      std::string body;
      for (const model::Diagnostic& d : report.diagnostics) body += d.message() + "\n";
      const std::string first =
          report.diagnostics.empty() ? "" : report.diagnostics.front().message();
      suites << "      <error type=\"invalid input\" message=\"" << xml_escape(first) << "\">"
             << xml_escape(body) << "</error>\n";
    }
    suites << "    </testcase>\n";
    for (const metrics::RequirementResult& result : report.results) {
      suites << "    <testcase classname=\"" << name << "\" name=\""
             << xml_escape(result.id + " " + result.title) << "\">\n";
      if (result.verdict == metrics::Verdict::fail) {
        suites << "      <failure type=\"requirement\" message=\""
               << xml_escape(result_line(result)) << "\"/>\n";
      } else if (result.verdict == metrics::Verdict::not_evaluated) {
        suites << "      <skipped message=\"" << xml_escape(result.explanation) << "\"/>\n";
      }
      suites << "    </testcase>\n";
    }
    std::string warnings;
    for (const model::Diagnostic& d : report.diagnostics) {
      if (d.severity == model::Severity::warning) warnings += d.message() + "\n";
    }
    if (!warnings.empty())
      suites << "    <system-out>" << xml_escape(warnings) << "</system-out>\n";
    suites << "  </testsuite>\n";
  }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml << "<testsuites name=\"rigdesign check\" tests=\"" << all_tests << "\" failures=\""
      << all_failures << "\" errors=\"" << all_errors << "\" skipped=\"" << all_skipped << "\">\n";
  xml << suites.str() << "</testsuites>\n";
  return xml.str();
}

}  // namespace rigdesign::cli
