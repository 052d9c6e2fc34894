#pragma once
/// The README.md `rigdesign export` writes beside the files (issue 34): what each file is for
/// and, per mount, what every layer does with its data: which costmap layer marks with it and
/// over which range and heights, which clears with it, which collision-monitor zones it feeds
/// (and how much of their boundary nothing sees), and what Gazebo simulates for it. One table,
/// so a reviewer sees the same sensor under one name across the stack.
#include <string>
#include <vector>

#include "rigdesign/deploy/deployment.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::deploy {

/// The per-mount visibility table in Markdown (also printed by `export`).
std::string visibility_table(const deploy::Deployment& deployment);

/// The README's text: `header`, the files in `file_names`, the table, the collision monitor's
/// sizing.
std::string export_readme_text(const model::Rig& rig, const deploy::Deployment& deployment,
                               const std::vector<std::string>& file_names,
                               const std::string& header);

}  // namespace rigdesign::deploy
