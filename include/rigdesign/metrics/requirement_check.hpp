#pragma once
/// Judges a rig's metrics against application requirements R1-R8 through the satisficing
/// metrics of paper 1 (DESIGN.md section 5): R3/R4/R5 give a minimum F, R6 a maximum R,
/// R7 a maximum N, R8 the lighting conditions L must hold for.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "rigdesign/model/requirements.hpp"

namespace rigdesign::metrics {

enum class Verdict { pass, fail, not_evaluated };

/// Which side of `required` passes: the margin's sign convention.
enum class Bound { none, at_least, at_most };

struct RequirementResult {
  std::string id;      ///< "R5"
  std::string title;   ///< "robot speed"
  std::string metric;  ///< satisficing metric judged: "F", "R", "N", "L", "d", "body", "SC"
  std::string unit;    ///< of required and actual ("Hz", "m", "")
  std::optional<double> required;
  std::optional<double> actual;
  Verdict verdict = Verdict::pass;
  std::vector<std::string> limiting_mounts;  ///< mounts that set the actual value (or fail)
  std::string explanation;      ///< one sentence: how required was derived, what failed
  std::string field;            ///< the requirement's key in its file, e.g. "robot_speed"
  model::SourceLocation where;  ///< the requirement in its file
  Bound bound = Bound::none;
  /// Where in the rig file the rig causes this verdict (the limiting mount's mode, or the rig
  /// itself for coverage and body); empty when the finding is about another file (a nav2
  /// parameter). CI annotations go here: the rig is what a reviewer changes.
  model::SourceLocation rig_where;
  /// Further rig lines the verdict rests on (the other mount of a crosstalk pair): CI
  /// annotations are put there too.
  std::vector<model::SourceLocation> also_where;

  /// actual - required for at-least bounds, required - actual for at-most ones: positive is
  /// headroom, negative how far it misses. Empty without both values or a bound.
  std::optional<double> margin() const;
  /// rig_where when set, else where.
  const model::SourceLocation& annotated_where() const;
};

/// `coverage` judges R2's sectors; computed with requirements.sectors (compute_coverage).
/// Without it, R2 is reported as not evaluated.
/// With `library`, a sector's verdict points at what decides it at its worst angle
/// (metrics/sector_blame.hpp: the mount that would see most there, or the body hiding it);
/// without, at the mount that sees most of it there (raster shares).
std::vector<RequirementResult> evaluate_requirements(const model::Rig& rig,
                                                     const ResultantMetrics& metrics,
                                                     const model::Requirements& requirements,
                                                     const RigCoverage* coverage = nullptr,
                                                     const model::SensorLibrary* library = nullptr);

std::string to_string(Verdict verdict);

}  // namespace rigdesign::metrics
