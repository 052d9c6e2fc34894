#include "rigdesign/io/config/filtering_loads_io.hpp"

#include <set>

#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::io {

model::FilteringLoads load_filtering_loads(const std::string& path) {
  using io::Need;
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(
      path, diagnostics, "a filtering-loads file: machine, pipeline, scene, frames, sensors");
  model::FilteringLoads loads;
  loads.file = path;
  loads.machine =
      top.text("machine", Need::required, "what one core-equivalent means").value_or("");
  loads.pipeline = top.text("pipeline", Need::required, "the pipeline that was timed").value_or("");
  loads.scene = top.text("scene", Need::optional).value_or("");
  loads.frames = top.integer("frames", Need::optional, "frames per sensor, >= 1").value_or(0);
  std::set<std::string> seen;
  for (io::MapReader& reader : top.maps("sensors", Need::required, "a list of measured sensors")) {
    model::FilteringLoad load;
    load.where = reader.location();
    load.sensor_id = reader.text("sensor", Need::required, "a sensor id").value_or("");
    load.mode_id = reader.text("mode", Need::optional).value_or("");
    load.seconds_per_point =
        io::non_negative(reader, "seconds_per_point", Need::required,
                         "core-seconds of filtering per delivered point, >= 0");
    load.points_per_frame =
        io::non_negative(reader, "points_per_frame", Need::optional, "points, >= 0");
    load.median_seconds_per_frame =
        io::non_negative(reader, "median_seconds_per_frame", Need::optional, "seconds, >= 0");
    reader.reject_unknown_keys();
    if (!load.sensor_id.empty() && !seen.insert(load.sensor_id).second) {
      reader.require(false, "sensor", "lists '" + load.sensor_id + "' twice", "each sensor once");
    }
    loads.sensors.push_back(std::move(load));
  }
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return loads;
}

model::FilteringLoads merge_filtering_loads(const model::FilteringLoads& previous,
                                            const model::FilteringLoads& measured) {
  model::FilteringLoads merged = measured;
  for (const model::FilteringLoad& old : previous.sensors) {
    if (measured.find(old.sensor_id) == nullptr) merged.sensors.push_back(old);
  }
  return merged;
}

}  // namespace rigdesign::io
