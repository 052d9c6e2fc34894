#pragma once
/// What a deployment's self-filter file drops from each mount's data, for `check` (issue 14):
/// ROS 2 parameter files whose top-level keys are node names, each with `ros__parameters`:
/// laser_filters chains (filter1, filter2, ... with name, type, params) and pcl_ros CropBox
/// nodes (min_x .. max_z, negative, input_frame). Modelled: LaserScanAngularBoundsFilter,
/// LaserScanAngularBoundsFilterInPlace, LaserScanRangeFilter, LaserScanBoxFilter (invert:
/// false) and CropBox (negative: true); other laser_filters types drop no fixed region and
/// are passed over.
#include <string>
#include <vector>

#include "rigdesign/deploy/deployed_check.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::deploy {

/// `mount` empty: each node names its mount by its name, `<mount id>` or `<mount id>_...`
/// (as `rigdesign export` writes them); otherwise every node of the file filters `mount`.
/// Box frames may be base_footprint, a link of the rig's description, or an exported sensor
/// frame (`<id>_link`, `<id>_optical_frame`). Throws InputError naming file:line:col and the
/// key for a node that names no mount of `rig`, an unknown frame, a malformed value, or a
/// filter form rigdesign does not model (a box that keeps its inside).
std::vector<deploy::DeployedFilter> load_self_filters(const std::string& path,
                                                      const std::string& mount,
                                                      const model::Rig& rig);

}  // namespace rigdesign::deploy
