#pragma once
/// Per-sensor metrics of paper 1 section 2 (DESIGN.md sections 4 and 5).
#include <string>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::metrics {

struct MountMetrics {
  std::string mount_id;
  std::string sensor_id;
  std::string mode_id;
  double distance = 0.0;       ///< d_i [m] at which spacing and noise are judged
  double frequency = 0.0;      ///< F_i [Hz]: the mode's, or the mount's throttle_hz when lower
  double point_spacing = 0.0;  ///< R_i [m] = d_i * tan(coarser angular resolution)
  double noise = 0.0;          ///< N_i [m] = sigma(d_i)
  model::LightImmunity light;
  double points_per_second = 0.0;           ///< what the driver delivers (the mode's rate)
  double filtered_points_per_second = 0.0;  ///< what passes the throttle to the filters
  double bandwidth = 0.0;                   ///< B_i [B/s] = w_i * f_i (paper 1, eq. 2)
  double driver_cpu = 0.0;                  ///< U_p,i [core-equivalents] (paper 1, eq. 5)
  model::Basis driver_cpu_basis = model::Basis::estimate;
  double price = 0.0;  ///< [USD]
  model::Basis price_basis = model::Basis::datasheet;
  bool distance_in_range = true;  ///< d_i within [min_range, max_range]
};

/// Metrics of one mounted sensor at distance `distance` [m].
MountMetrics compute_mount_metrics(const model::Mount& mount, const model::Sensor& sensor,
                                   const model::SensorMode& mode, double distance);

/// Spacing between neighbouring rays at `distance` [m] for an angular step [rad]:
/// d * tan(step), as paper 1 states it (122 mm for the VLP-16's 2 degrees at 3.5 m).
double ray_spacing(double distance, double angular_step);

}  // namespace rigdesign::metrics
