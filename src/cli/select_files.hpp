#pragma once
// Files `select` writes for the rig it chose: the rig and its final requirements, the Pareto
// and margin plots, the coverage pictures and report page, and the ROS 2 deployment.
#include <string>
#include <vector>

#include "rigdesign/report/select_report.hpp"

namespace rigdesign::io {
class StagedFolder;
}

namespace rigdesign::cli {

/// Writes chosen_rig.yaml, requirements_final.yaml, pareto.png/.svg, a margin plot per chosen
/// slot whose range varies the pitch, with `renders` the coverage pictures and report.html,
/// and deploy/ into the staging folder; returns their paths there in that order
/// (staged.final_names gives where they end up). Writes nothing when no step found a rig.
/// Needs `report.outcome`; `space` is the one searched (the margin plots sweep in it).
/// `progress` hears each part as it starts; `phases` gets the time it all took;
/// `deployment_warnings` what the deployment written warns about (a stop zone partly unseen).
std::vector<std::string> write_selection_files(const report::SelectReport& report,
                                               const select::SelectionSpace& space,
                                               const io::StagedFolder& staged, bool renders,
                                               const select::ProgressSink& progress,
                                               std::vector<select::PhaseTime>& phases,
                                               std::vector<std::string>& deployment_warnings);

}  // namespace rigdesign::cli
