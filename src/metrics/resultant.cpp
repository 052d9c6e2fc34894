#include "rigdesign/metrics/resultant.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace rigdesign::metrics {
namespace {

// Values within this relative distance count as tied, so every limiting mount is named.
constexpr double kTieTolerance = 1e-9;

Limiting limiting(const std::vector<MountMetrics>& mounts, double MountMetrics::*field,
                  bool smallest) {
  Limiting result;
  result.value =
      smallest ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (const MountMetrics& mount : mounts) {
    const double value = mount.*field;
    if (smallest ? value < result.value : value > result.value) result.value = value;
  }
  for (const MountMetrics& mount : mounts) {
    const double scale = std::max(1.0, std::abs(result.value));
    if (std::abs(mount.*field - result.value) <= kTieTolerance * scale) {
      result.mounts.push_back(mount.mount_id);
    }
  }
  return result;
}

}  // namespace

const LightResult& ResultantMetrics::light_for(model::LightCondition condition) const {
  return light[static_cast<std::size_t>(condition)];
}

ResultantMetrics compute_resultant(const model::Rig& rig, const model::SensorLibrary& library) {
  ResultantMetrics result;
  for (const model::Mount& mount : rig.mounts) {
    const model::Sensor* sensor = library.find(mount.sensor_id);
    const model::SensorMode* mode = sensor ? sensor->find_mode(mount.mode_id) : nullptr;
    if (mode == nullptr) {
      throw std::logic_error("compute_resultant: unresolved mount '" + mount.id + "'");
    }
    result.mounts.push_back(compute_mount_metrics(mount, *sensor, *mode, rig.distance_for(mount)));
  }
  if (result.mounts.empty()) throw std::logic_error("compute_resultant: rig without mounts");

  result.frequency = limiting(result.mounts, &MountMetrics::frequency, true);
  result.point_spacing = limiting(result.mounts, &MountMetrics::point_spacing, false);
  result.noise = limiting(result.mounts, &MountMetrics::noise, false);
  for (std::size_t i = 0; i < model::kLightConditions.size(); ++i) {
    LightResult& light = result.light[i];
    light.condition = model::kLightConditions[i];
    for (const MountMetrics& mount : result.mounts) {
      if (!mount.light.immune_to(light.condition)) light.failing_mounts.push_back(mount.mount_id);
    }
    light.immune = light.failing_mounts.empty();
  }
  for (const MountMetrics& mount : result.mounts) {
    result.bandwidth += mount.bandwidth;
    result.driver_cpu += mount.driver_cpu;
    result.sensor_cost += mount.price;
    result.any_estimate = result.any_estimate || mount.price_basis == model::Basis::estimate ||
                          mount.driver_cpu_basis == model::Basis::estimate;
  }
  // The masts and brackets that hold them are bought with the sensors (issue 52 item 3).
  for (const model::RigSupport& support : rig.supports) result.sensor_cost += support.price;
  return result;
}

}  // namespace rigdesign::metrics
