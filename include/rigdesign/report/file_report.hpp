#pragma once
// What `rigdesign check` found in one file: its kind, the problems in it (and in the
// library and requirements a rig pulls in), and the requirement verdicts. check_text,
// check_json, check_junit and check_github render it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/io/file_kind.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/work_budget.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::report {

struct FileReport {
  std::string file;
  std::optional<io::FileKind> kind;
  std::string summary;  ///< one line on what was checked
  std::vector<model::Diagnostic> diagnostics;
  std::vector<metrics::RequirementResult> results;
  /// Wall time [s] of reading the file (and what it pulls in), and per result the time of the
  /// computation its verdict rests on (shared computations, such as the coverage cut that
  /// every R2 sector uses, are counted in each result that uses them).
  double load_seconds = 0.0;
  std::vector<double> result_seconds;

  bool invalid() const;
  bool failing() const;
};

/// The deployed configuration `check` also judges a rig against (issue 14): nav2 costmap
/// parameters and self-filter files, each `FILE` or `MOUNT=FILE`.
struct DeploymentFiles {
  std::string nav2;
  std::vector<std::string> filters;
  double global_frame_height = 0.0;  ///< [m] of the nav2 file's global frame above the floor
  std::string collision_monitor;     ///< nav2 collision_monitor parameters (D4)
  /// No costmap or filter file (the collision monitor is judged on its own).
  bool empty() const { return nav2.empty() && filters.empty(); }
};

/// `budget`, when given, limits and reports the longest part (the tolerance poses).
FileReport check_file(const std::string& path, const std::string& sensors_path,
                      const std::string& requirements_path, const DeploymentFiles& deployment = {},
                      const metrics::WorkBudget* budget = nullptr);

/// How many of `results` have `verdict`.
std::size_t count_verdicts(const std::vector<metrics::RequirementResult>& results,
                           metrics::Verdict verdict);

}  // namespace rigdesign::report
