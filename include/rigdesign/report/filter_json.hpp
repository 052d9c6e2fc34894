#pragma once
// `rigdesign filter --json`: the same reports as JSON, times in seconds.
#include <nlohmann/json_fwd.hpp>

#include "rigdesign/report/filter_report.hpp"

namespace rigdesign::report {

nlohmann::json filter_clouds_json(const FilterCloudsReport& report);
nlohmann::json filter_scene_json(const FilterSceneReport& report);

}  // namespace rigdesign::report
