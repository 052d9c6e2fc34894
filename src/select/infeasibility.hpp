#pragma once
// Why no rig meets the requirements (issue 32, item 3), found on the search's own model by
// relaxing one thing at a time: a metric (F, R, N, L) no option meets alone, a sector every
// option together cannot cover, a CPU or transfer capacity no catalog entry reaches (the
// least load any rig meeting the requirements puts on it, found by the branch and bound
// minimising that load), or the robustness (a rig exists without it).
#include <string>
#include <vector>

#include "rigdesign/select/selection.hpp"

namespace rigdesign::select {

/// The cause, as a sentence for "no rig: ..."; `problem` is what the search ran on,
/// `options` every option of the space per slot (before F, R, N and L filtered them).
std::string infeasibility_cause(const SearchProblem& problem,
                                const std::vector<std::vector<CatalogOption>>& options,
                                const SatisficingTargets& targets, const SelectionSpace& space);

}  // namespace rigdesign::select
