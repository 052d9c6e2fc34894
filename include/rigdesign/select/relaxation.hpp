#pragma once
/// The relaxation loop (paper 1, Fig. 1): while the cheapest rig costs more than the budget,
/// relax the next application requirement of the user's policy and search again.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/relaxation_policy.hpp"
#include "rigdesign/select/selection.hpp"

namespace rigdesign::select {

struct RelaxationIteration {
  std::string relaxed;  ///< what this iteration relaxed ("" for the first)
  model::Requirements requirements;
  SatisficingTargets targets;
  Selection selection;
  bool within_budget = false;
};

/// A requirement that keeps the rig over budget: the cheapest rig without it.
struct BindingRequirement {
  std::string requirement;  ///< e.g. "R5 robot_speed", "R2 sectors.back"
  bool feasible_without = false;
  double cost_without = 0.0;  ///< [USD]
};

struct RelaxationOutcome {
  std::vector<RelaxationIteration> iterations;
  bool within_budget = false;
  /// When the policy is exhausted: requirements whose removal alone would bring the rig
  /// within budget or make it feasible, else those whose removal lowers the cost most.
  std::vector<BindingRequirement> binding;
  std::vector<PhaseTime> phases;  ///< after the loop (the binding-requirement probes)
};

/// Runs the loop; every iteration is reported to `on_iteration` as soon as it is done.
/// Precondition: every policy step applies (relax() throws otherwise; check before).
RelaxationOutcome select_within_budget(
    const SelectionSpace& space, const model::Requirements& requirements,
    const model::RelaxationPolicy& policy, double budget,
    const std::function<void(const RelaxationIteration&)>& on_iteration = {},
    const ProgressSink& progress = {});

/// Applies every step in order, so a bad policy fails before any search (throws InputError).
model::Requirements check_policy(const model::Requirements& requirements,
                                 const model::RelaxationPolicy& policy);

}  // namespace rigdesign::select
