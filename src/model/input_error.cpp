#include "rigdesign/model/input_error.hpp"

#include <algorithm>

namespace rigdesign::model {
namespace {

std::string join_messages(const std::vector<Diagnostic>& diagnostics) {
  std::string text;
  for (const Diagnostic& diagnostic : diagnostics) {
    if (!text.empty()) text += '\n';
    text += diagnostic.message();
  }
  return text;
}

}  // namespace

std::string Diagnostic::message() const {
  std::string text = to_string(where) + ": ";
  if (severity == Severity::warning) text += "warning: ";
  text += field + ": " + problem;
  if (!expected.empty()) text += " (expected " + expected + ")";
  return text;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(join_messages(diagnostics)), diagnostics_(std::move(diagnostics)) {}

InputError::InputError(Diagnostic diagnostic)
    : InputError(std::vector<Diagnostic>{std::move(diagnostic)}) {}

InputError InputError::in_file(const std::string& file) const {
  std::vector<Diagnostic> located = diagnostics_;
  for (Diagnostic& diagnostic : located) {
    if (diagnostic.where.file.empty()) diagnostic.where = {file, 0, 0};
  }
  return InputError(std::move(located));
}

void Diagnostics::error(SourceLocation where, std::string field, std::string problem,
                        std::string expected) {
  items_.push_back({std::move(where), std::move(field), std::move(problem), std::move(expected),
                    Severity::error});
}

void Diagnostics::warning(SourceLocation where, std::string field, std::string problem,
                          std::string expected) {
  items_.push_back({std::move(where), std::move(field), std::move(problem), std::move(expected),
                    Severity::warning});
}

bool Diagnostics::has_errors() const {
  return std::any_of(items_.begin(), items_.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::error; });
}

void Diagnostics::throw_if_errors() const {
  if (has_errors()) throw InputError(items_);
}

}  // namespace rigdesign::model
