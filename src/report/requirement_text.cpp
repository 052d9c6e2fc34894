#include "rigdesign/report/requirement_text.hpp"

#include <cmath>
#include <optional>

#include "rigdesign/model/format_number.hpp"

namespace rigdesign::report {
namespace {

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

}  // namespace

// "F = 15 Hz, required >= 14.29 Hz, margin +0.7143 Hz (+5 %)", or "" without numbers.
std::string measured_text(const metrics::RequirementResult& result) {
  if (!result.actual) return "";
  if (result.metric.rfind("SC", 0) == 0 && result.unit.empty()) {  // shares read as percent
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
  for (const model::SourceLocation& where : result.also_where)
    text += " (also " + to_string(where) + ")";
  if (!result.rig_where.file.empty()) text += " (requirement at " + to_string(result.where) + ")";
  return text;
}

}  // namespace rigdesign::report
