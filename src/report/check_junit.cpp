#include "rigdesign/report/check_junit.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "rigdesign/io/emit/xml_text.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/requirement_text.hpp"

namespace rigdesign::report {
namespace {

struct SuiteCounts {
  std::size_t tests = 0, failures = 0, errors = 0, skipped = 0;
  double seconds = 0.0;
};

SuiteCounts counts_of(const FileReport& report) {
  SuiteCounts counts;
  counts.tests = 1 + report.results.size();
  counts.failures = count_verdicts(report.results, metrics::Verdict::fail);
  counts.errors = report.invalid() ? 1 : 0;
  counts.skipped = count_verdicts(report.results, metrics::Verdict::not_evaluated);
  counts.seconds = report.load_seconds;
  for (const double result_seconds : report.result_seconds) counts.seconds += result_seconds;
  return counts;
}

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6f", seconds);
  return buffer;
}

// file="..." line="..." as the JUnit readers of GitLab, Jenkins and GitHub's test reporters take
// them (the Ant schema has no such attributes; the xunit/pytest dialect does). Every case has
// both (issue 39): a finding about a whole file points at its first line.
std::string location_attributes(const model::SourceLocation& where) {
  return " file=\"" + io::xml_escaped(where.file) + "\" line=\"" +
         std::to_string(std::max(1, where.line)) + "\"";
}

// The file's validity: an error with every problem when invalid, else what was checked.
void validity_case(const FileReport& report, const std::string& name, std::ostream& xml) {
  const model::SourceLocation where = report.invalid() && !report.diagnostics.empty()
                                          ? report.diagnostics.front().where
                                          : model::SourceLocation{report.file, 1, 1};
  xml << "    <testcase classname=\"" << name << "\" name=\"valid "
      << io::xml_escaped(report.kind ? to_string(*report.kind) : "file") << "\""
      << location_attributes(where) << " time=\"" << seconds_text(report.load_seconds) << "\">\n";
  if (report.invalid()) {
    std::string body;
    for (const model::Diagnostic& d : report.diagnostics) body += d.message() + "\n";
    const std::string first =
        report.diagnostics.empty() ? "" : report.diagnostics.front().message();
    xml << "      <error type=\"invalid input\" message=\"" << io::xml_escaped(first) << "\">"
        << io::xml_escaped(body) << "</error>\n";
  } else if (!report.summary.empty()) {
    xml << "      <system-out>" << io::xml_escaped(report.summary) << "</system-out>\n";
  }
  xml << "    </testcase>\n";
}

void requirement_case(const metrics::RequirementResult& result, double seconds,
                      const std::string& name, std::ostream& xml) {
  xml << "    <testcase classname=\"" << name << "\" name=\""
      << io::xml_escaped(result.id + " " + result.title) << "\""
      << location_attributes(result.annotated_where()) << " time=\"" << seconds_text(seconds)
      << "\">\n";
  if (result.verdict == metrics::Verdict::fail) {
    xml << "      <failure type=\"requirement\" message=\"" << io::xml_escaped(result_line(result))
        << "\"/>\n";
  } else if (result.verdict == metrics::Verdict::not_evaluated) {
    xml << "      <skipped message=\"" << io::xml_escaped(result.explanation) << "\"/>\n";
  }
  std::string out = measured_text(result);
  out += (out.empty() ? "" : "\n") + result.explanation;
  if (!result.limiting_mounts.empty()) out += "\nset by: " + model::join(result.limiting_mounts);
  out += "\nrequirement: " + to_string(result.where);
  xml << "      <system-out>" << io::xml_escaped(out) << "</system-out>\n";
  xml << "    </testcase>\n";
}

void testsuite(const FileReport& report, const SuiteCounts& counts, std::ostream& xml) {
  const std::string name = io::xml_escaped(report.file);
  xml << "  <testsuite name=\"" << name << "\" tests=\"" << counts.tests << "\" failures=\""
      << counts.failures << "\" errors=\"" << counts.errors << "\" skipped=\"" << counts.skipped
      << "\" time=\"" << seconds_text(counts.seconds) << "\">\n";
  validity_case(report, name, xml);
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const double seconds = i < report.result_seconds.size() ? report.result_seconds[i] : 0;
    requirement_case(report.results[i], seconds, name, xml);
  }
  std::string warnings;
  for (const model::Diagnostic& d : report.diagnostics) {
    if (d.severity == model::Severity::warning) warnings += d.message() + "\n";
  }
  if (!warnings.empty())
    xml << "    <system-out>" << io::xml_escaped(warnings) << "</system-out>\n";
  xml << "  </testsuite>\n";
}

}  // namespace

std::string format_junit(const std::vector<FileReport>& reports) {
  std::ostringstream suites;
  SuiteCounts all;
  for (const FileReport& report : reports) {
    const SuiteCounts counts = counts_of(report);
    all.tests += counts.tests;
    all.failures += counts.failures;
    all.errors += counts.errors;
    all.skipped += counts.skipped;
    all.seconds += counts.seconds;
    testsuite(report, counts, suites);
  }
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml << "<testsuites name=\"rigdesign check\" tests=\"" << all.tests << "\" failures=\""
      << all.failures << "\" errors=\"" << all.errors << "\" skipped=\"" << all.skipped
      << "\" time=\"" << seconds_text(all.seconds) << "\">\n";
  xml << suites.str() << "</testsuites>\n";
  return xml.str();
}

}  // namespace rigdesign::report
