#include "rigdesign/model/filter_params.hpp"

namespace rigdesign::model {

const std::vector<std::string>& stage_names() {
  static const std::vector<std::string> names = {
      "voxel_grid",      "statistical_outlier", "pass_through",      "ransac_plane",
      "floor_removal_1", "floor_removal_2",     "negative_obstacles"};
  return names;
}

std::string stage_name(const StageParams& params) {
  return stage_names()[params.index()];
}

}  // namespace rigdesign::model
