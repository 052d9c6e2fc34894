#include "rigdesign/model/filter_params.hpp"

namespace rigdesign::model {

const std::vector<std::string>& stage_names() {
  static const std::vector<std::string> names(kStageNames.begin(), kStageNames.end());
  return names;
}

std::string stage_name(const StageParams& params) {
  return std::visit([](const auto& stage) { return std::string(stage.kName); }, params);
}

}  // namespace rigdesign::model
