#pragma once
// What `select` reports, as data: the catalog, requirements, policy and budget it searched
// with, the relaxation loop's outcome and the files written. select_text, select_json and
// select_html render it; the phrases below name a requirement set, a rig and a pose
// refinement the same way in every format.
#include <cstddef>
#include <string>
#include <vector>

#include "rigdesign/select/relaxation.hpp"

namespace rigdesign::report {

struct SelectReport {
  const model::Catalog* catalog = nullptr;
  std::size_t option_count = 0;                        ///< slot options the search chose from
  const model::Requirements* requirements = nullptr;   ///< as given, before any relaxation
  const model::RelaxationPolicy* policy = nullptr;     ///< no steps: none given
  double budget = 0.0;                                 ///< [USD]
  const select::RelaxationOutcome* outcome = nullptr;  ///< null while the loop runs
  std::vector<std::string> files;                      ///< written, where they end up
  std::vector<select::PhaseTime> file_phases;          ///< writing them
  /// Slot poses left out before the search: the sensor would be inside the body.
  std::vector<select::LeftOutPoses> left_out;
  /// What the deployment written for the chosen rig warns about (a collision monitor zone
  /// whose edge no source sees), each with the file it is about.
  std::vector<std::string> deployment_warnings;
  /// Issue 52 item 6: `rigdesign check` run on the files written (the chosen rig with its
  /// requirements, nav2 costmap and collision monitor): the command, its verdict counts and
  /// each failure as check prints it. Empty command: nothing was written.
  std::string check_command;
  std::size_t check_pass = 0;
  std::size_t check_fail = 0;
  std::vector<std::string> check_failures;
  /// Issue 55: per slot (catalog order), the options it gave after the poses left out.
  std::vector<std::size_t> options_per_slot;
  /// The phases before the relaxation loop (loading, placing, rasterising) and after the
  /// files (checking them), and the whole command's wall time, so the report says where
  /// every second went.
  std::vector<select::PhaseTime> before_phases;
  std::vector<select::PhaseTime> after_phases;
  double wall_seconds = 0.0;
};

/// Every phase of the run in order: before the loop, each step's ("#1 search"), the binding
/// probes, the files and after them; their seconds sum to about the wall time.
std::vector<select::PhaseTime> time_rows(const SelectReport& report);

/// The iteration whose rig is written: the first within budget, else the last that found a
/// rig (the cheapest found); null when none did.
const select::RelaxationIteration* chosen_iteration(const select::RelaxationOutcome& outcome);

/// "2749 USD": whole dollars.
std::string usd(double value);

/// A share as a percentage of three significant digits: 0.368 gives "36.8".
std::string percent_digits(double share);

/// "F >= 10 Hz, R <= 150 mm, N <= 50 mm, L: dark, indoor, SC front >= 75 / 80 % ...".
std::string describe(const select::SatisficingTargets& targets);

/// The chosen rig: per slot its sensor/mode and, for a pose range, the pose chosen.
std::string describe(const select::Selection& selection, const model::Catalog& catalog);

/// Options of a rig, as describe(Selection) names them.
std::string describe(const std::vector<const select::CatalogOption*>& chosen,
                     const model::Catalog& catalog);

/// Issue 55 item 3: why the cheaper rig lost against the chosen rig of cost `chosen`: the
/// CPU or transfer it needs beyond the catalog's, or what its CPU and transfer cost.
std::string describe_excluded(const select::ExcludedRig& rig, const select::CostBreakdown& chosen,
                              double budget, const model::Catalog& catalog);

/// The axes the refinement moved, the smallest margin before and after, and its verdict.
std::string describe(const select::PoseRefinement& refinement);

}  // namespace rigdesign::report
