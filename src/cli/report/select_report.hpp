#pragma once
// What `select` shows and writes: the trace of the relaxation loop, the chosen rig as a rig
// file with the final requirements beside it, the Pareto plot and the coverage renders.
#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "rigdesign/select/relaxation.hpp"

namespace rigdesign::io {
class StagedFolder;
}

namespace rigdesign::cli {

class SelectReport {
 public:
  SelectReport(const select::SelectionSpace& space, const model::Requirements& requirements,
               const model::RelaxationPolicy& policy, double budget);

  void print_header(std::ostream& out) const;
  void print_iteration(const select::RelaxationIteration& iteration, std::ostream& out);
  void print_summary(const select::RelaxationOutcome& outcome,
                     const std::vector<std::string>& written, std::ostream& out) const;
  /// Writes the chosen rig, final requirements, Pareto plot and renders into the staging
  /// folder; returns their paths there (staged.final_names gives where they end up).
  std::vector<std::string> write_files(const select::RelaxationOutcome& outcome,
                                       const io::StagedFolder& staged, bool renders) const;
  nlohmann::json to_json(const select::RelaxationOutcome& outcome,
                         const std::vector<std::string>& written) const;

 private:
  /// The chosen rig's report page (html_report) with the relaxation trace, cost breakdown and
  /// Pareto plot as a section of its own.
  std::string selection_page(const select::RelaxationOutcome& outcome,
                             const select::RelaxationIteration& pick, const model::Rig& rig,
                             const std::string& coverage_folder, const std::vector<double>& angles,
                             const std::string& pareto_svg) const;
  std::vector<std::string> write_margin_plots(const select::RelaxationIteration& pick,
                                              const std::string& folder) const;

  const select::SelectionSpace& space_;
  const model::Requirements& requirements_;
  const model::RelaxationPolicy& policy_;
  double budget_;
  int printed_ = 0;
};

/// "F >= 10 Hz, R <= 150 mm, N <= 50 mm, L: dark, indoor, SC front >= 75 / 80 % ...".
std::string describe(const select::SatisficingTargets& targets);

/// The chosen rig: per slot its sensor/mode and, for a pose range, the pose chosen.
std::string describe(const select::Selection& selection, const model::Catalog& catalog);

}  // namespace rigdesign::cli
