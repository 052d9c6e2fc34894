#pragma once
/// One candidate position of an emitter with its uncertainty, as every estimator reports it.
#include <optional>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct Hypothesis {
  model::Vec3 position =
      model::Vec3::Zero();  ///< [m]; at the robot's mean height when z is unobservable
  model::Mat3 covariance =
      model::Mat3::Zero();      ///< [m^2]; the z row and column are 0 when z is unobservable
  double rssi_at_1m_dbm = 0.0;  ///< the 1 m level used or estimated [dBm]
  double exponent = 0.0;        ///< the path-loss exponent used or estimated
  double cost = 0.0;            ///< the estimator's objective at the position (lower is better)
  /// Share of the posterior probability in this hypothesis' basin (1 for a single estimate).
  double probability = 1.0;
  /// Posterior probability within the decision radius of the position (range fit): how likely
  /// the emitter lies within the acceptable error of it. The range fit lists this first; paper
  /// 4's methods state no posterior, so none.
  std::optional<double> probability_nearby;
  double level_sd_db = 0.0;  ///< posterior sd of the 1 m level at the position (nls) [dB]
  double exponent_sd = 0.0;  ///< posterior sd of the exponent (nls; 0 when fixed)
  /// Side of the robot's path the position lies on, facing the direction of travel (REP-103:
  /// +1 left, -1 right, 0 on it).
  int side = 0;
};

}  // namespace rigdesign::localize
