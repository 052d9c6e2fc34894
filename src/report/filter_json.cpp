#include "rigdesign/report/filter_json.hpp"

#include <nlohmann/json.hpp>

namespace rigdesign::report {
namespace {

nlohmann::json cloud_json(const FilterCloudReport& cloud) {
  nlohmann::json stages = nlohmann::json::array();
  for (const filters::StageTiming& stage : cloud.stages) {
    stages.push_back({{"stage", stage.stage},
                      {"points_in", stage.points_in},
                      {"points_out", stage.points_out},
                      {"median_s", stage.seconds.median},
                      {"p95_s", stage.seconds.p95}});
  }
  nlohmann::json item = {{"file", cloud.file},
                         {"format", cloud.format},
                         {"points", cloud.points},
                         {"dropped_non_finite", cloud.dropped_non_finite},
                         {"ignored_fields", cloud.ignored_fields},
                         {"stages", stages},
                         {"total_median_s", cloud.total.median}};
  if (cloud.load) {
    item["filtering_load_cores"] = cloud.load->rate.cores;
    item["filtering_seconds_per_point"] = cloud.load->rate.seconds_per_point;
  }
  if (!cloud.output.empty()) item["output"] = cloud.output;
  return item;
}

}  // namespace

nlohmann::json filter_clouds_json(const FilterCloudsReport& report) {
  nlohmann::json clouds = nlohmann::json::array();
  for (const FilterCloudReport& cloud : report.clouds) clouds.push_back(cloud_json(cloud));
  return {{"pipeline", report.pipeline},
          {"runs", report.runs},
          {"clouds", clouds},
          {"peak_memory_mib", report.peak_memory_mib}};
}

nlohmann::json filter_scene_json(const FilterSceneReport& report) {
  nlohmann::json mounts = nlohmann::json::array();
  for (const FilterMountReport& mount : report.mounts) {
    mounts.push_back({{"mount", mount.mount_id},
                      {"points_per_frame", mount.points_per_frame},
                      {"median_s", mount.seconds_per_frame.median},
                      {"filtering_load_cores", mount.load.cores},
                      {"filtering_seconds_per_point", mount.load.seconds_per_point}});
  }
  return {{"pipeline", report.pipeline},
          {"scene", report.scene},
          {"frames", report.frames},
          {"mounts", mounts},
          {"total_filtering_load_cores", report.total_load_cores}};
}

}  // namespace rigdesign::report
