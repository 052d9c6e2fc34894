#include "report/file_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "command.hpp"
#include "inputs.hpp"
#include "report/json_report.hpp"
#include "rigdesign/deploy/deployed_check.hpp"
#include "rigdesign/io/config/catalog_loader.hpp"
#include "rigdesign/io/config/policy_loader.hpp"
#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/deploy/self_filters_loader.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/xml_text.hpp"

namespace rigdesign::cli {
namespace {

// Seconds since `start` on the monotonic clock.
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string rig_summary(const RigInputs& inputs) {
  std::string text = "rig '" + inputs.rig.name +
                     "' is valid: " + std::to_string(inputs.rig.mounts.size()) +
                     " mounts, sensors from " + inputs.library.file;
  if (inputs.requirements) text += ", requirements from " + inputs.requirements->file;
  return text;
}

std::string value_text(double value, const std::string& unit) {
  return model::format_number(value, 4) + (unit.empty() ? "" : " " + unit);
}

std::string bound_text(metrics::Bound bound) {
  switch (bound) {
    case metrics::Bound::at_least: return ">= ";
    case metrics::Bound::at_most: return "<= ";
    case metrics::Bound::none: return "";
  }
  return "";
}

std::string result_line(const metrics::RequirementResult& result) {
  std::string text = to_string(result.annotated_where()) + ": " + result.field + ": " +
                     to_string(result.verdict) + ": " + result.id + " " + result.title;
  if (const std::string measured = measured_text(result); !measured.empty()) {
    text += ": " + measured;
  }
  text += "; " + result.explanation;
  if (!result.limiting_mounts.empty()) {
    text += " [set by ";
    for (std::size_t i = 0; i < result.limiting_mounts.size(); ++i) {
      text += (i ? ", " : "") + result.limiting_mounts[i];
    }
    text += "]";
  }
  if (!result.rig_where.file.empty()) text += " (requirement at " + to_string(result.where) + ")";
  return text;
}

std::size_t count(const std::vector<metrics::RequirementResult>& results,
                  metrics::Verdict verdict) {
  return static_cast<std::size_t>(
      std::count_if(results.begin(), results.end(),
                    [&](const metrics::RequirementResult& r) { return r.verdict == verdict; }));
}

// "check: 3 file(s), 0 invalid; requirements: 7 pass, 1 fail, 0 not evaluated".
std::string check_summary(const std::vector<FileReport>& reports) {
  std::size_t invalid = 0, pass = 0, fail = 0, skipped = 0;
  for (const FileReport& report : reports) {
    invalid += report.invalid() ? 1 : 0;
    pass += count(report.results, metrics::Verdict::pass);
    fail += count(report.results, metrics::Verdict::fail);
    skipped += count(report.results, metrics::Verdict::not_evaluated);
  }
  return "check: " + std::to_string(reports.size()) + " file(s), " + std::to_string(invalid) +
         " invalid; requirements: " + std::to_string(pass) + " pass, " + std::to_string(fail) +
         " fail, " + std::to_string(skipped) + " not evaluated\n";
}

}  // namespace

// "F = 15 Hz, required >= 14.29 Hz, margin +0.7143 Hz (+5 %)", or "" without numbers.
std::string measured_text(const metrics::RequirementResult& result) {
  if (!result.actual) return "";
  if (result.metric == "SC" && result.unit.empty()) {  // shares read as percent
    metrics::RequirementResult percent = result;
    percent.unit = "%";
    percent.actual = *result.actual * 100;
    if (result.required) percent.required = *result.required * 100;
    return measured_text(percent);
  }
  std::string text = result.metric + " = " + value_text(*result.actual, result.unit);
  if (result.required) {
    text += ", required " + bound_text(result.bound) + value_text(*result.required, result.unit);
  }
  if (const std::optional<double> margin = result.margin()) {
    text += ", margin " + std::string(*margin >= 0 ? "+" : "") + value_text(*margin, result.unit);
    if (*result.required != 0.0) {
      const double share = 100.0 * *margin / std::abs(*result.required);
      text += " (" + std::string(share >= 0 ? "+" : "") + model::format_number(share, 3) + " %)";
    }
  }
  return text;
}

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
    const bool known =
        mount.empty() || std::any_of(rig.mounts.begin(), rig.mounts.end(),
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
  const auto started = std::chrono::steady_clock::now();
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
          report.load_seconds = seconds_since(started);
          auto step = std::chrono::steady_clock::now();
          const metrics::ResultantMetrics metrics =
              metrics::compute_resultant(inputs.rig, inputs.library);
          const double resultant_seconds = seconds_since(step);
          step = std::chrono::steady_clock::now();
          std::optional<metrics::RigCoverage> coverage;
          if (!inputs.requirements->sectors.empty()) {
            coverage =
                metrics::compute_coverage(inputs.rig, inputs.library, inputs.requirements->sectors);
          }
          const double coverage_seconds = seconds_since(step);
          step = std::chrono::steady_clock::now();
          report.results = metrics::evaluate_requirements(inputs.rig, metrics, *inputs.requirements,
                                                          coverage ? &*coverage : nullptr);
          const double judge_seconds = seconds_since(step);
          for (const metrics::RequirementResult& result : report.results) {
            report.result_seconds.push_back(resultant_seconds + judge_seconds +
                                            (result.metric == "SC" ? coverage_seconds : 0.0));
          }
          if (config) {
            step = std::chrono::steady_clock::now();
            std::vector<metrics::RequirementResult> deployed =
                deploy::check_deployment(inputs.rig, inputs.library, *inputs.requirements, *config,
                                         coverage ? &*coverage : nullptr);
            const double deployed_seconds = seconds_since(step);
            for (metrics::RequirementResult& result : deployed) {
              report.results.push_back(std::move(result));
              report.result_seconds.push_back(deployed_seconds);
            }
          }
        }
        break;
      }
    }
    if (report.load_seconds == 0.0) report.load_seconds = seconds_since(started);
  } catch (const model::InputError& error) {
    report.diagnostics = error.diagnostics();
    report.summary = "invalid";
    report.load_seconds = seconds_since(started);
  }
  return report;
}

std::string format_text(const std::vector<FileReport>& reports) {
  std::ostringstream out;
  for (const FileReport& report : reports) {
    if (!report.invalid()) out << report.file << ": " << report.summary << '\n';
    for (const model::Diagnostic& diagnostic : report.diagnostics)
      out << diagnostic.message() << '\n';
    for (const metrics::RequirementResult& result : report.results)
      out << result_line(result) << '\n';
  }
  out << check_summary(reports);
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

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
  return buffer;
}

// file="..." line="..." as the JUnit readers of GitLab, Jenkins and GitHub's test reporters take
// them (the Ant schema has no such attributes; the xunit/pytest dialect does).
std::string location_attributes(const model::SourceLocation& where) {
  std::string text = " file=\"" + model::xml_escaped(where.file) + "\"";
  if (where.line > 0) text += " line=\"" + std::to_string(where.line) + "\"";
  return text;
}

// JUnit XML as Jenkins, GitLab and GitHub test reporters read it: one <testsuite> per file,
// one <testcase> for the file's validity and one per requirement.
std::string format_junit(const std::vector<FileReport>& reports) {
  std::ostringstream suites;
  std::size_t all_tests = 0, all_failures = 0, all_errors = 0, all_skipped = 0;
  double all_seconds = 0.0;
  for (const FileReport& report : reports) {
    const std::size_t tests = 1 + report.results.size();
    const std::size_t failures = count(report.results, metrics::Verdict::fail);
    const std::size_t skipped = count(report.results, metrics::Verdict::not_evaluated);
    const std::size_t errors = report.invalid() ? 1 : 0;
    double seconds = report.load_seconds;
    for (const double result_seconds : report.result_seconds) seconds += result_seconds;
    all_tests += tests;
    all_failures += failures;
    all_errors += errors;
    all_skipped += skipped;
    all_seconds += seconds;
    const std::string name = model::xml_escaped(report.file);
    suites << "  <testsuite name=\"" << name << "\" tests=\"" << tests << "\" failures=\""
           << failures << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\""
           << seconds_text(seconds) << "\">\n";
    const model::SourceLocation validity_where = report.invalid() && !report.diagnostics.empty()
                                                     ? report.diagnostics.front().where
                                                     : model::SourceLocation{report.file, 0, 0};
    suites << "    <testcase classname=\"" << name << "\" name=\"valid "
           << model::xml_escaped(report.kind ? to_string(*report.kind) : "file") << "\""
           << location_attributes(validity_where) << " time=\"" << seconds_text(report.load_seconds)
           << "\">\n";
    if (report.invalid()) {
      std::string body;
      for (const model::Diagnostic& d : report.diagnostics) body += d.message() + "\n";
      const std::string first =
          report.diagnostics.empty() ? "" : report.diagnostics.front().message();
      suites << "      <error type=\"invalid input\" message=\"" << model::xml_escaped(first)
             << "\">" << model::xml_escaped(body) << "</error>\n";
    } else if (!report.summary.empty()) {
      suites << "      <system-out>" << model::xml_escaped(report.summary) << "</system-out>\n";
    }
    suites << "    </testcase>\n";
    for (std::size_t i = 0; i < report.results.size(); ++i) {
      const metrics::RequirementResult& result = report.results[i];
      const double result_seconds = i < report.result_seconds.size() ? report.result_seconds[i] : 0;
      suites << "    <testcase classname=\"" << name << "\" name=\""
             << model::xml_escaped(result.id + " " + result.title) << "\""
             << location_attributes(result.annotated_where()) << " time=\""
             << seconds_text(result_seconds) << "\">\n";
      if (result.verdict == metrics::Verdict::fail) {
        suites << "      <failure type=\"requirement\" message=\""
               << model::xml_escaped(result_line(result)) << "\"/>\n";
      } else if (result.verdict == metrics::Verdict::not_evaluated) {
        suites << "      <skipped message=\"" << model::xml_escaped(result.explanation) << "\"/>\n";
      }
      std::string out = measured_text(result);
      out += (out.empty() ? "" : "\n") + result.explanation;
      if (!result.limiting_mounts.empty()) {
        out += "\nset by: " + model::join(result.limiting_mounts);
      }
      out += "\nrequirement: " + to_string(result.where);
      suites << "      <system-out>" << model::xml_escaped(out) << "</system-out>\n";
      suites << "    </testcase>\n";
    }
    std::string warnings;
    for (const model::Diagnostic& d : report.diagnostics) {
      if (d.severity == model::Severity::warning) warnings += d.message() + "\n";
    }
    if (!warnings.empty())
      suites << "    <system-out>" << model::xml_escaped(warnings) << "</system-out>\n";
    suites << "  </testsuite>\n";
  }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml << "<testsuites name=\"rigdesign check\" tests=\"" << all_tests << "\" failures=\""
      << all_failures << "\" errors=\"" << all_errors << "\" skipped=\"" << all_skipped
      << "\" time=\"" << seconds_text(all_seconds) << "\">\n";
  xml << suites.str() << "</testsuites>\n";
  return xml.str();
}

namespace {

// GitHub's workflow-command escapes: % CR LF in the message; also : and , in properties.
std::string github_escape(const std::string& text, bool property) {
  std::string escaped;
  for (const char c : text) {
    switch (c) {
      case '%': escaped += "%25"; break;
      case '\r': escaped += "%0D"; break;
      case '\n': escaped += "%0A"; break;
      case ':': escaped += property ? "%3A" : ":"; break;
      case ',': escaped += property ? "%2C" : ","; break;
      default: escaped += c;
    }
  }
  return escaped;
}

void annotate(std::ostream& out, const std::string& level, const model::SourceLocation& where,
              const std::string& title, const std::string& message) {
  out << "::" << level << " file=" << github_escape(where.file, true);
  if (where.line > 0) out << ",line=" << where.line;
  if (where.column > 0) out << ",col=" << where.column;
  out << ",title=" << github_escape(title, true) << "::" << github_escape(message, false) << '\n';
}

}  // namespace

std::string format_github(const std::vector<FileReport>& reports) {
  std::ostringstream out;
  for (const FileReport& report : reports) {
    for (const model::Diagnostic& d : report.diagnostics) {
      annotate(out, d.severity == model::Severity::error ? "error" : "warning", d.where,
               "rigdesign: " + (d.field.empty() ? std::string("input") : d.field),
               d.problem + (d.expected.empty() ? "" : " (expected " + d.expected + ")"));
    }
    for (const metrics::RequirementResult& result : report.results) {
      if (result.verdict != metrics::Verdict::fail) continue;
      std::string message = measured_text(result);
      message += (message.empty() ? "" : "; ") + result.explanation;
      if (!result.limiting_mounts.empty())
        message += " [set by " + model::join(result.limiting_mounts) + "]";
      message += "\nrequirement at " + to_string(result.where);
      annotate(out, "error", result.annotated_where(),
               "rigdesign " + result.id + " " + result.title, message);
    }
  }
  out << check_summary(reports);
  return out.str();
}

}  // namespace rigdesign::cli
