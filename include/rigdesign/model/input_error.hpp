#pragma once
/// The project's one error type for bad input (STYLE.md rule 8): every finding names the
/// file, line and column, the field, what is wrong and the expected form. Thrown by the
/// loaders, caught once by the CLI and mapped to exit code 2.
#include <stdexcept>
#include <string>
#include <vector>

#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

enum class Severity { error, warning };

struct Diagnostic {
  Diagnostic() = default;
  Diagnostic(SourceLocation where_, std::string field_, std::string problem_,
             std::string expected_ = {}, Severity severity_ = Severity::error)
      : where(std::move(where_)),
        field(std::move(field_)),
        problem(std::move(problem_)),
        expected(std::move(expected_)),
        severity(severity_) {}

  SourceLocation where;
  std::string field;     ///< dotted path, e.g. "mounts[2].pose.xyz[1]"
  std::string problem;   ///< what is wrong
  std::string expected;  ///< the expected form; may be empty
  Severity severity = Severity::error;

  /// "file:line:col: field: problem (expected ...)"
  std::string message() const;
};

class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics);
  explicit InputError(Diagnostic diagnostic);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  /// The same findings, those that name no file (an algorithm's refusal of its input)
  /// pointed at `file`: the CLI knows which input the algorithm was given.
  InputError in_file(const std::string& file) const;

 private:
  std::vector<Diagnostic> diagnostics_;
};

/// Collects findings while a file is read so one run reports all of them, not just the first.
class Diagnostics {
 public:
  void error(SourceLocation where, std::string field, std::string problem,
             std::string expected = {});
  void warning(SourceLocation where, std::string field, std::string problem,
               std::string expected = {});
  void add(Diagnostic diagnostic) { items_.push_back(std::move(diagnostic)); }
  bool has_errors() const;
  const std::vector<Diagnostic>& items() const { return items_; }
  /// Throws InputError carrying every finding (warnings too) when any is an error.
  void throw_if_errors() const;

 private:
  std::vector<Diagnostic> items_;
};

}  // namespace rigdesign::model
