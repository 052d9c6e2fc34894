// `metrics --format json`: the rig's metrics, the filtering load, the coverage summary, the
// tolerance sectors and the requirement verdicts, as one document.
#include <nlohmann/json.hpp>

#include "rigdesign/model/units.hpp"
#include "rigdesign/report/json_report.hpp"
#include "rigdesign/report/metrics_report.hpp"

namespace rigdesign::report {
namespace {

nlohmann::json error_json(const metrics::PoseError& error) {
  return {{"xyz_m", {error.xyz.x(), error.xyz.y(), error.xyz.z()}},
          {"rpy_deg",
           {model::rad_to_deg(error.rpy.x()), model::rad_to_deg(error.rpy.y()),
            model::rad_to_deg(error.rpy.z())}}};
}

nlohmann::json tolerance_json(const std::vector<metrics::SectorTolerance>& sectors) {
  nlohmann::json list = nlohmann::json::array();
  for (const metrics::SectorTolerance& sector : sectors) {
    const auto worst = [](double nominal, const metrics::WorstShare& share) {
      nlohmann::json errors = nlohmann::json::array();
      for (const metrics::MountError& error : share.errors)
        errors.push_back({{"mount", error.mount_id}, {"error", error_json(error.error)}});
      return nlohmann::json{{"nominal", nominal}, {"worst", share.share}, {"errors", errors}};
    };
    list.push_back({{"sector", sector.sector.name},
                    {"complete", worst(sector.nominal_complete, sector.complete)},
                    {"floor", worst(sector.nominal_floor, sector.floor)},
                    {"still_met", sector.pass},
                    {"margin", sector.margin()}});
  }
  return list;
}

}  // namespace

std::string rig_metrics_json(const MetricsReport& report) {
  const io::RigInputs& inputs = *report.inputs;
  nlohmann::json document = to_json(inputs, report.metrics);
  if (report.loads) {
    nlohmann::json mounts = nlohmann::json::object();
    for (const FilteringLoadRow& row : report.load_rows)
      mounts[row.mount_id] = row.cores ? nlohmann::json(*row.cores) : nlohmann::json();
    document["filtering_load"] = {{"file", report.loads->file},
                                  {"pipeline", report.loads->pipeline},
                                  {"machine", report.loads->machine},
                                  {"mounts_cores", mounts},
                                  {"total_cores", total_filtering_cores(report.load_rows)}};
  }
  document["coverage"] = to_json(report.coverage, false);
  if (!report.tolerance.empty()) document["tolerance"] = tolerance_json(report.tolerance);
  if (inputs.requirements) {
    nlohmann::json list = nlohmann::json::array();
    for (const metrics::RequirementResult& result : report.results) list.push_back(to_json(result));
    document["requirements"] = {{"file", inputs.requirements->file}, {"results", list}};
  }
  return document.dump(2) + '\n';
}

}  // namespace rigdesign::report
