#include "rigdesign/io/config/rig_references.hpp"

#include <string>
#include <vector>

#include "rigdesign/model/closest_name.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::io {
namespace {

template <typename Items, typename IdOf>
std::string list_ids(const Items& items, IdOf id_of) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + id_of(item);
  return text;
}

// " (did you mean 'x'?)" for a near miss among the items' ids, else "".
template <typename Items, typename IdOf>
std::string suggestion(const std::string& name, const Items& items, IdOf id_of) {
  std::vector<std::string> ids;
  for (const auto& item : items) ids.push_back(id_of(item));
  const std::string closest = model::closest_name(name, ids);
  return closest.empty() ? std::string() : " (did you mean '" + closest + "'?)";
}

std::string mount_field(std::size_t index, const char* key) {
  return "mounts[" + std::to_string(index) + "]." + key;
}

}  // namespace

model::Diagnostics check_rig_references(const model::Rig& rig,
                                        const model::SensorLibrary& library) {
  model::Diagnostics diagnostics;
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::Sensor* sensor = library.find(mount.sensor_id);
    if (sensor == nullptr) {
      diagnostics.error(
          mount.sensor_where, mount_field(i, "sensor"),
          "unknown sensor '" + mount.sensor_id + "' in " + library.file +
              suggestion(mount.sensor_id, library.sensors,
                         [](const model::Sensor& s) { return s.id; }),
          "one of: " + list_ids(library.sensors, [](const model::Sensor& s) { return s.id; }));
      continue;
    }
    const model::SensorMode* mode = sensor->find_mode(mount.mode_id);
    if (mode == nullptr) {
      diagnostics.error(
          mount.mode_where, mount_field(i, "mode"),
          "unknown mode '" + mount.mode_id + "' of sensor '" + sensor->id + "'" +
              suggestion(mount.mode_id, sensor->modes,
                         [](const model::SensorMode& m) { return m.id; }),
          "one of: " + list_ids(sensor->modes, [](const model::SensorMode& m) { return m.id; }));
      continue;
    }
    if (mount.throttle_hz && *mount.throttle_hz >= mode->frequency) {
      diagnostics.warning(mount.throttle_where, mount_field(i, "throttle_hz"),
                          "throttles to " + model::format_number(*mount.throttle_hz) +
                              " Hz, not below the mode's " + model::format_number(mode->frequency) +
                              " Hz: it passes every frame",
                          "a rate below the mode's frequency, or no throttle_hz");
    }
    const double distance = rig.distance_for(mount);
    if (distance > mode->max_range || distance < mode->min_range) {
      diagnostics.warning(mount.where, mount_field(i, "distance_of_interest"),
                          "distance of interest " + model::format_number(distance) +
                              " m is outside the range of " + sensor->id + "/" + mode->id + " [" +
                              model::format_number(mode->min_range) + ", " +
                              model::format_number(mode->max_range) + "] m: it sees nothing there",
                          "a per-mount distance_of_interest within the mode's range");
    }
  }
  return diagnostics;
}

}  // namespace rigdesign::io
