#pragma once
// `coverage --sweep`: the option's forms, the motion it asks for (from the options and the
// requirements), and the files and text the swept coverage (issue 38 item 4) gives.
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "inputs.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/swept_coverage.hpp"

namespace rigdesign::cli {

inline constexpr const char* kSweepForm =
    "rotate or arc:R (R: the arc's radius [m], not 0; > 0 turns left)";

/// What `--turn-rate` and `--sweep-time` say (nothing: their defaults) and `--sweep` itself.
struct SweepOptions {
  std::string sweep;
  std::optional<double> turn_rate_deg;  ///< [deg/s]
  std::optional<double> sweep_time;     ///< [s]
};

// `--sweep`'s value: the motion's kind, an arc's radius and the files' name (sweep_<label>).
struct SweepChoice {
  metrics::SweepKind kind = metrics::SweepKind::rotate;
  double arc_radius = 0.0;
  std::string label;
};

/// `--sweep`'s value parsed, or nothing when it is not rotate or arc:R (R finite, not 0).
std::optional<SweepChoice> parse_sweep(const std::string& text);

// The motion and settings `--sweep` asks for, from the options and the requirements (R5's
// speed and deceleration, R6's obstacle size). Checked before any work starts.
struct SweepRequest {
  std::string option;  // as given: rotate, arc:0.8
  std::string label;   // in file names: rotate, arc_0.8
  metrics::SweepMotion motion;
  metrics::SweepSettings settings;
};

/// The request for `choice`; exit 2 (naming the option) when the requirements lack what it
/// needs. Checked before any work starts.
SweepRequest sweep_request(const SweepOptions& options, const SweepChoice& choice,
                           const RigInputs& inputs, const metrics::CoverageSettings& coverage);

/// Runs the sweep and writes sweep_<label>.csv and .png into `folder`, appending their paths to
/// `written`.
metrics::SweptCoverage write_sweep_files(const RigInputs& inputs, const SweepRequest& request,
                                         const std::string& folder,
                                         std::vector<std::string>& written);

/// The summary `coverage` prints.
void print_sweep(std::ostream& out, const SweepRequest& request,
                 const metrics::SweptCoverage& sweep);

}  // namespace rigdesign::cli
