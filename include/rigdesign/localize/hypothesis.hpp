#pragma once
/// One candidate position of an emitter with its uncertainty, as every estimator reports it.
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
};

}  // namespace rigdesign::localize
