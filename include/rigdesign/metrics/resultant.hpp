#pragma once
/// The rig's resultant metrics (paper 1, section 2.3; DESIGN.md section 4):
/// F = min F_i, R = max R_i, N = max N_i, L = every sensor immune to each condition;
/// and the sums of paper 1's cost model: B = sum B_i, U_p = sum U_p,i, C_s = sum of prices.
#include <array>
#include <string>
#include <vector>

#include "rigdesign/metrics/mount_metrics.hpp"

namespace rigdesign::metrics {

/// A resultant value and the mounts that set it (several when tied).
struct Limiting {
  double value = 0.0;
  std::vector<std::string> mounts;
};

struct LightResult {
  model::LightCondition condition = model::LightCondition::dark;
  bool immune = true;                       ///< every mount works in this condition
  std::vector<std::string> failing_mounts;  ///< mounts that do not
};

struct ResultantMetrics {
  std::vector<MountMetrics> mounts;
  Limiting frequency;                ///< F [Hz], the slowest sensor
  Limiting point_spacing;            ///< R [m], the coarsest spacing at the distance of interest
  Limiting noise;                    ///< N [m], the noisiest sensor at its distance of interest
  std::array<LightResult, 3> light;  ///< L, in kLightConditions order
  double bandwidth = 0.0;            ///< B [B/s]
  double driver_cpu = 0.0;           ///< U_p [core-equivalents]
  double sensor_cost = 0.0;          ///< C_s [USD]
  bool any_estimate = false;         ///< some price or driver load is an estimate

  const LightResult& light_for(model::LightCondition condition) const;
};

/// Precondition: check_rig_references(rig, library) reported no error.
ResultantMetrics compute_resultant(const model::Rig& rig, const model::SensorLibrary& library);

}  // namespace rigdesign::metrics
