#pragma once
// The dB-domain measurement model of the range fit and its solver: the chunks' mean RSSI
// against a - 10 n log10 |q - p|, the closed-form level (and exponent) for a fixed position,
// and Levenberg-Marquardt over (q, a[, n]) with an optional Gaussian prior on a, a Huber
// loss and a truncated-normal model of the cut-off. Private to src/localize.
#include <Eigen/Core>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize::detail {

struct Observation {
  model::Vec3 p;
  double m = 0.0;  // mean RSSI [dBm]
  double w = 0.0;  // chunk count over the mean count
};

struct Model {
  int d = 2;
  bool fit_level = true;
  bool fit_exponent = false;
  double a0 = 0.0;
  double n0 = 2.0;
  double level_bound = 15.0;
  double prior_weight = 0.0;      // lambda of the prior term lambda (a - a0)^2, in cost units
  double cutoff = -80.0;          // [dBm]
  double truncation_sigma = 0.0;  // shadowing sigma of the truncation model; 0: off
  double height = 0.0;            // z of a 2D fit
  double huber = 0.0;
  int parameters() const { return d + (fit_level ? 1 : 0) + (fit_exponent ? 1 : 0); }
};

struct Solution {
  model::Vec3 q = model::Vec3::Zero();
  double a = 0.0;
  double n = 0.0;
  double cost = 0.0;
  Eigen::MatrixXd information;  // J^T W J at q
};

struct ResidualStats {
  double variance = 0.0;     // weighted mean squared residual [dB^2]
  double correlation = 0.0;  // lag-1 autocorrelation between consecutive chunks, in [0, 0.99]
};

/// Distance in the model's dimensions, at least 1 cm.
double distance(const model::Vec3& q, const model::Vec3& p, int d);

// The level (and exponent) minimising the weighted squared residuals for a fixed q: a linear
// least-squares problem in (a, n), which makes scoring a candidate one pass over the data.
Solution closed_form(const std::vector<Observation>& observations, const model::Vec3& q,
                     const Model& model);

/// Levenberg-Marquardt from `s`; the result carries J^T W J for the covariance.
Solution levenberg_marquardt(const std::vector<Observation>& observations, const Model& model,
                             Solution s, int max_iterations);

// Chunks are in the order the robot first visited them, so consecutive residuals are
// neighbours along the path.
ResidualStats residual_stats(const std::vector<Observation>& observations, const Model& model,
                             const Solution& s);

}  // namespace rigdesign::localize::detail
