#include "rigdesign/localize/path_loss_calibration.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "censored_likelihood.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::localize {
namespace {

struct CalibrationSample {
  double x;     // -10 log10(d): the model is a + n x
  double rssi;  // heard: the reading; unheard: the floor
  bool heard;
};

// The log-likelihood of (a, n, log sigma): heard scans by the normal density, unheard ones by
// the probability of lying below the floor.
double censored_log_likelihood(const std::vector<CalibrationSample>& samples,
                               const Eigen::Vector3d& theta) {
  const double sigma = std::exp(theta(2));
  const double half_log_two_pi = 0.5 * std::log(2.0 * std::numbers::pi);
  double sum = 0.0;
  for (const CalibrationSample& s : samples) {
    const double z = (s.rssi - (theta(0) + theta(1) * s.x)) / sigma;
    sum += s.heard ? -0.5 * z * z - theta(2) - half_log_two_pi : detail::log_normal_cdf(z);
  }
  return sum;
}

// Nelder-Mead ascent in three dimensions from `start` (the heard scans' least-squares line):
// the Tobit log-likelihood is concave in (a/sigma, n/sigma, 1/sigma), so its one maximum is
// found from any start.
Eigen::Vector3d maximise_likelihood(const std::vector<CalibrationSample>& samples,
                                    const Eigen::Vector3d& start) {
  std::array<Eigen::Vector3d, 4> simplex;
  std::array<double, 4> value{};
  const Eigen::Vector3d size(3.0, 0.3, 0.3);
  for (int i = 0; i < 4; ++i) {
    simplex[i] = start;
    if (i > 0) simplex[i](i - 1) += size(i - 1);
    value[i] = -censored_log_likelihood(samples, simplex[i]);
  }
  for (int iteration = 0; iteration < 2000; ++iteration) {
    std::array<int, 4> order = {0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int p, int q) { return value[p] < value[q]; });
    const int best = order[0], worst = order[3];
    if (value[worst] - value[best] < 1e-10) break;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) centroid += simplex[order[i]] / 3.0;
    const auto try_point = [&](double t) {
      const Eigen::Vector3d p = centroid + t * (simplex[worst] - centroid);
      return std::pair<Eigen::Vector3d, double>{p, -censored_log_likelihood(samples, p)};
    };
    auto [reflected, reflected_value] = try_point(-1.0);
    if (reflected_value < value[best]) {
      auto [expanded, expanded_value] = try_point(-2.0);
      const bool expand = expanded_value < reflected_value;
      simplex[worst] = expand ? expanded : reflected;
      value[worst] = expand ? expanded_value : reflected_value;
    } else if (reflected_value < value[order[2]]) {
      simplex[worst] = reflected;
      value[worst] = reflected_value;
    } else {
      auto [contracted, contracted_value] = try_point(0.5);
      if (contracted_value < value[worst]) {
        simplex[worst] = contracted;
        value[worst] = contracted_value;
      } else {
        for (int i = 1; i < 4; ++i) {
          simplex[order[i]] = simplex[best] + 0.5 * (simplex[order[i]] - simplex[best]);
          value[order[i]] = -censored_log_likelihood(samples, simplex[order[i]]);
        }
      }
    }
  }
  return simplex[std::min_element(value.begin(), value.end()) - value.begin()];
}

// Standard errors of (a, n) from the observed information (the negative Hessian of the
// log-likelihood by central differences), sigma's uncertainty included.
Eigen::Vector2d level_and_exponent_errors(const std::vector<CalibrationSample>& samples,
                                          const Eigen::Vector3d& theta) {
  const Eigen::Vector3d step(1e-3, 1e-4, 1e-4);
  Eigen::Matrix3d hessian;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d ei = Eigen::Vector3d::Unit(i) * step(i);
      const Eigen::Vector3d ej = Eigen::Vector3d::Unit(j) * step(j);
      hessian(i, j) = (censored_log_likelihood(samples, theta + ei + ej) -
                       censored_log_likelihood(samples, theta + ei - ej) -
                       censored_log_likelihood(samples, theta - ei + ej) +
                       censored_log_likelihood(samples, theta - ei - ej)) /
                      (4.0 * step(i) * step(j));
    }
  }
  const Eigen::Matrix3d covariance = (-hessian).inverse();
  return {std::sqrt(std::max(0.0, covariance(0, 0))), std::sqrt(std::max(0.0, covariance(1, 1)))};
}

}  // namespace

std::optional<PathLossCalibration> calibrate_path_loss(const ScanSeries& scans,
                                                       const model::Vec3& truth,
                                                       const std::vector<WallSegment>& walls) {
  std::vector<CalibrationSample> samples;
  PathLossCalibration c;
  c.nearest_m = std::numeric_limits<double>::infinity();
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const Scan& scan : scans.scans) {
    const double d = (scan.position - truth).norm();
    if (d < kCalibrationMinDistance) continue;
    const double x = -10.0 * std::log10(d);
    // The walls' loss back on: what the reading would be without them.
    const double walls_db = walls.empty() ? 0.0 : wall_loss_db(walls, scan.position, truth);
    const double rssi = (scan.heard ? scan.rssi_dbm : scans.floor_dbm) + walls_db;
    samples.push_back({x, rssi, scan.heard});
    c.nearest_m = std::min(c.nearest_m, d);
    c.farthest_m = std::max(c.farthest_m, d);
    if (!scan.heard) {
      ++c.unheard;
      continue;
    }
    ++c.heard;
    sx += x;
    sy += rssi;
    sxx += x * x;
    sxy += x * rssi;
  }
  if (c.heard < 3) return std::nullopt;
  const double n = c.heard;
  const double spread = sxx - sx * sx / n;
  // Heard log-distances spanning less than 0.1 dB rms (distances within 2.3 %) tell no exponent.
  constexpr double kLeastSpread = 0.1;  // [dB]
  if (!(std::sqrt(std::max(0.0, spread) / n) >= kLeastSpread)) return std::nullopt;
  // The heard scans' least-squares line starts the search.
  const double slope = (sxy - sx * sy / n) / spread;
  const double intercept = (sy - slope * sx) / n;
  double rss = 0.0;
  for (const CalibrationSample& s : samples)
    if (s.heard) rss += std::pow(s.rssi - (intercept + slope * s.x), 2);
  const double sigma0 = std::max(0.5, std::sqrt(rss / n));
  const Eigen::Vector3d theta = maximise_likelihood(samples, {intercept, slope, std::log(sigma0)});
  c.rssi_at_1m_dbm = theta(0);
  c.exponent = theta(1);
  c.sigma_db = std::exp(theta(2));
  const Eigen::Vector2d errors = level_and_exponent_errors(samples, theta);
  c.level_sd_db = errors(0);
  c.exponent_sd = errors(1);
  return c;
}

std::string calibration_problem(const PathLossCalibration& fit) {
  // The ranges of --rssi-at-1m and --exponent: a suggestion the command refuses is no use.
  constexpr double kLowestLevel = -120.0, kHighestLevel = 30.0;  // [dBm]
  constexpr double kLeastExponent = 0.5, kLargestExponent = 10.0;
  constexpr double kLeastSigma = 0.01;  // [dB] a hundredth of the receivers' 1 dB step
  using model::format_number;
  const bool finite = std::isfinite(fit.rssi_at_1m_dbm) && std::isfinite(fit.exponent) &&
                      std::isfinite(fit.sigma_db) && std::isfinite(fit.level_sd_db) &&
                      std::isfinite(fit.exponent_sd);
  if (!finite) return "the fit did not converge to finite values";
  if (!(fit.exponent >= kLeastExponent && fit.exponent <= kLargestExponent)) {
    return "the exponent " + format_number(fit.exponent, 3) +
           " is not a path loss (it lies outside [0.5, 10]: the readings do not fall with "
           "distance as a radio's do)";
  }
  if (!(fit.rssi_at_1m_dbm >= kLowestLevel && fit.rssi_at_1m_dbm <= kHighestLevel)) {
    return "the level at 1 m, " + format_number(fit.rssi_at_1m_dbm, 4) +
           " dBm, lies outside [-120, 30] dBm";
  }
  if (!(fit.sigma_db >= kLeastSigma)) {
    return "the readings lie on the model to " + format_number(fit.sigma_db, 2) +
           " dB (sigma below 0.01 dB): a degenerate fit, not a measurement";
  }
  return {};
}

const std::vector<EnvironmentPreset>& environment_presets() {
  // Paper 4 (Roucek 2020), Table 4 "Path loss exponent (propagation constant) examples", its
  // reference [49], as DESIGN.md section 9 transcribes it; the midpoint where it gives a range.
  // The last row is the thesis's text beside the table, not a row of it.
  static const std::vector<EnvironmentPreset> presets = {
      {"free-space", 2.0, "paper 4, Table 4 (its reference [49]): Free Space, 2"},
      {"urban-area", 3.35, "paper 4, Table 4 (its reference [49]): Urban Area, 2.7 to 4"},
      {"indoor-los", 1.7, "paper 4, Table 4 (its reference [49]): Indoor LOS, 1.6 to 1.8"},
      {"indoor-general", 5.0, "paper 4, Table 4 (its reference [49]): Indoor general, 4 to 6"},
      {"indoor-factories", 2.5, "paper 4, Table 4 (its reference [49]): Indoor factories, 2 to 3"},
      {"indoor-through-floor", 4.5,
       "paper 4, Table 4 (its reference [49]): Indoor through floor, 3 to 6"},
      {"underground-station", 2.6,
       "paper 4, beside Table 4: underground stations, 2.2 to 3 at 2.4 GHz"},
  };
  return presets;
}

const EnvironmentPreset* find_environment_preset(const std::string& name) {
  for (const EnvironmentPreset& preset : environment_presets())
    if (preset.name == name) return &preset;
  return nullptr;
}

}  // namespace rigdesign::localize
