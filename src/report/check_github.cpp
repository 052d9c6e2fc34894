#include "rigdesign/report/check_github.hpp"

#include <ostream>
#include <sstream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/report/check_text.hpp"
#include "rigdesign/report/requirement_text.hpp"

namespace rigdesign::report {
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

void annotate_failure(std::ostream& out, const metrics::RequirementResult& result) {
  std::string message = measured_text(result);
  message += (message.empty() ? "" : "; ") + result.explanation;
  if (!result.limiting_mounts.empty())
    message += " [set by " + model::join(result.limiting_mounts) + "]";
  message += "\nrequirement at " + to_string(result.where);
  annotate(out, "error", result.annotated_where(), "rigdesign " + result.id + " " + result.title,
           message);
  for (const model::SourceLocation& where : result.also_where)
    annotate(out, "error", where, "rigdesign " + result.id + " " + result.title, message);
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
      if (result.verdict == metrics::Verdict::fail) annotate_failure(out, result);
    }
  }
  out << check_summary(reports);
  return out.str();
}

}  // namespace rigdesign::report
