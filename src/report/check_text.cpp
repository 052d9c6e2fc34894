#include "rigdesign/report/check_text.hpp"

#include <sstream>

#include "rigdesign/report/requirement_text.hpp"

namespace rigdesign::report {

std::string check_summary(const std::vector<FileReport>& reports) {
  std::size_t invalid = 0, pass = 0, fail = 0, skipped = 0;
  for (const FileReport& report : reports) {
    invalid += report.invalid() ? 1 : 0;
    pass += count_verdicts(report.results, metrics::Verdict::pass);
    fail += count_verdicts(report.results, metrics::Verdict::fail);
    skipped += count_verdicts(report.results, metrics::Verdict::not_evaluated);
  }
  return "check: " + std::to_string(reports.size()) + " file(s), " + std::to_string(invalid) +
         " invalid; requirements: " + std::to_string(pass) + " pass, " + std::to_string(fail) +
         " fail, " + std::to_string(skipped) + " not evaluated\n";
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

}  // namespace rigdesign::report
