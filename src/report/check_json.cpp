#include "rigdesign/report/check_json.hpp"

#include <nlohmann/json.hpp>

#include "rigdesign/report/json_report.hpp"

namespace rigdesign::report {

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

}  // namespace rigdesign::report
