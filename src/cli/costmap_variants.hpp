#pragma once
// `costmap --variants`: paper 2's Table 1 for the rig's mount subsets (issue 35 item 3).
#include <iosfwd>
#include <string>

#include "inputs.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "rigdesign/scenarios/variant_sweep.hpp"

namespace rigdesign::cli {

/// Sweeps every variant of `inputs.rig` (scenarios::rig_variants) on the scenario, prints
/// the table beside paper 2's, the qualitative checks for a rig of one lidar and one camera,
/// and writes `folder`/variants.json. Progress on `err`.
void run_costmap_variants(std::ostream& out, std::ostream& err, const RigInputs& inputs,
                          const scenarios::ScenarioFactory& make_scenario,
                          const scenarios::ScenarioParams& params,
                          const scenarios::SweepSettings& settings, const std::string& folder);

}  // namespace rigdesign::cli
