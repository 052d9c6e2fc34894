#include "db_domain_model.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace rigdesign::localize::detail {
namespace {

constexpr double kMinDistance = 0.01;  // [m] keeps log10 finite on a chunk's own position
constexpr double kMinExponent = 1.0;   // fitted n stays physical: free space is 2
constexpr double kMaxExponent = 8.0;

// Length in the fitted dimensions (x, y when z is unobservable). Written out: GCC 12 warns
// about Eigen's head(d) with a run-time d on a fixed-size vector.
double norm_in(const model::Vec3& v, int d) {
  return d == 3 ? v.norm() : std::hypot(v.x(), v.y());
}

}  // namespace

double distance(const model::Vec3& q, const model::Vec3& p, int d) {
  return std::max(norm_in(q - p, d), kMinDistance);
}

namespace {

struct Truncated {
  double mean = 0.0;   // expected mean RSSI of a chunk that survived the cut-off [dBm]
  double slope = 1.0;  // its derivative with respect to the model's mu
};

// Readings below the cut-off are dropped, so a chunk whose model level mu lies near it only
// exists when its shadowing was favourable: the surviving mean is the truncated-normal mean
// mu + sigma lambda(alpha), alpha = (cutoff - mu) / sigma, lambda the inverse Mills ratio.
Truncated truncated_mean(double mu, const Model& model) {
  if (model.truncation_sigma <= 0) return {mu, 1.0};
  const double sigma = model.truncation_sigma;
  const double alpha = (model.cutoff - mu) / sigma;
  double lambda;
  if (alpha > 8.0) {
    lambda = alpha + 1.0 / alpha;  // asymptotic: erfc underflows in relative precision
  } else {
    const double density = std::exp(-0.5 * alpha * alpha) / std::sqrt(2.0 * std::numbers::pi);
    lambda = density / (0.5 * std::erfc(alpha / std::numbers::sqrt2));
  }
  return {mu + sigma * lambda, std::clamp(1.0 - lambda * (lambda - alpha), 0.0, 1.0)};
}

double robust_cost(double e, double huber) {
  const double magnitude = std::abs(e);
  return huber > 0 && magnitude > huber ? 2.0 * huber * magnitude - huber * huber : e * e;
}

}  // namespace

// The level (and exponent) minimising the weighted squared residuals for a fixed q: a linear
// least-squares problem in (a, n), which makes scoring a candidate one pass over the data.
Solution closed_form(const std::vector<Observation>& observations, const model::Vec3& q,
                     const Model& model) {
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const Observation& o : observations) {
    const double x = -10.0 * std::log10(distance(q, o.p, model.d));
    sw += o.w;
    sx += o.w * x;
    sy += o.w * o.m;
    sxx += o.w * x * x;
    sxy += o.w * x * o.m;
  }
  Solution s;
  s.q = q;
  s.a = model.a0;
  s.n = model.n0;
  // The prior lambda (a - a0)^2 acts as lambda extra observations of a at a0.
  const double lambda = model.fit_level ? model.prior_weight : 0.0;
  if (model.fit_exponent) {
    const double determinant = (sw + lambda) * sxx - sx * sx;
    if (model.fit_level && determinant > 1e-12 * (sw + lambda) * sxx) {
      s.n = ((sw + lambda) * sxy - sx * (sy + lambda * model.a0)) / determinant;
    } else if (!model.fit_level && sxx > 0) {
      s.n = (sxy - model.a0 * sx) / sxx;
    }
    s.n = std::clamp(s.n, kMinExponent, kMaxExponent);
  }
  if (model.fit_level) {
    s.a = std::clamp((sy - s.n * sx + lambda * model.a0) / (sw + lambda),
                     model.a0 - model.level_bound, model.a0 + model.level_bound);
    if (model.fit_exponent && sxx > 0)
      s.n = std::clamp((sxy - s.a * sx) / sxx, kMinExponent, kMaxExponent);
  }
  // Sum of w (y - a - n x)^2 expanded into the sums, plus the prior.
  double syy = 0;
  for (const Observation& o : observations) syy += o.w * o.m * o.m;
  s.cost = std::max(0.0, syy - 2 * s.a * sy - 2 * s.n * sxy + s.a * s.a * sw + 2 * s.a * s.n * sx +
                             s.n * s.n * sxx) +
           lambda * (s.a - model.a0) * (s.a - model.a0);
  return s;
}

namespace {

// Cost, J^T W J and J^T W e at a parameter point; IRLS weights give the Huber loss.
double linearise(const std::vector<Observation>& observations, const Model& model,
                 const Solution& s, Eigen::MatrixXd* jtj, Eigen::VectorXd* jte) {
  const int parameters = model.parameters();
  if (jtj) jtj->setZero(parameters, parameters);
  if (jte) jte->setZero(parameters);
  Eigen::VectorXd row(parameters);
  double cost = 0.0;
  for (const Observation& o : observations) {
    const model::Vec3 diff = s.q - o.p;
    const double raw = norm_in(diff, model.d);
    const double dist = std::max(raw, kMinDistance);
    const double log_d = std::log10(dist);
    const double mu = s.a - 10.0 * s.n * log_d;
    const Truncated expected = truncated_mean(mu, model);
    const double e = o.m - expected.mean;
    cost += o.w * robust_cost(e, model.huber);
    if (!jtj) continue;
    const double weight =
        o.w * (model.huber > 0 && std::abs(e) > model.huber ? model.huber / std::abs(e) : 1.0);
    // d mu / d q = -10 n / ln 10 * (q - p) / |q - p|^2, times d f / d mu
    const double scale =
        raw > kMinDistance ? -10.0 * s.n / std::numbers::ln10 / (dist * dist) : 0.0;
    for (int k = 0; k < model.d; ++k) row(k) = expected.slope * scale * diff(k);
    int next = model.d;
    if (model.fit_level) row(next++) = expected.slope;
    if (model.fit_exponent) row(next) = -10.0 * log_d * expected.slope;
    jtj->noalias() += weight * row * row.transpose();
    *jte += weight * e * row;
  }
  if (model.fit_level && model.prior_weight > 0) {  // the prior as one more residual on a
    const double e = model.a0 - s.a;
    cost += model.prior_weight * e * e;
    if (jtj) {
      (*jtj)(model.d, model.d) += model.prior_weight;
      (*jte)(model.d) += model.prior_weight * e;
    }
  }
  return cost;
}

Solution step(const Solution& s, const Eigen::VectorXd& delta, const Model& model) {
  Solution next = s;
  for (int k = 0; k < model.d; ++k) next.q(k) += delta(k);
  int index = model.d;
  if (model.fit_level) {
    next.a = std::clamp(next.a + delta(index++), model.a0 - model.level_bound,
                        model.a0 + model.level_bound);
  }
  if (model.fit_exponent) next.n = std::clamp(next.n + delta(index), kMinExponent, kMaxExponent);
  return next;
}

}  // namespace

Solution levenberg_marquardt(const std::vector<Observation>& observations, const Model& model,
                             Solution s, int max_iterations) {
  Eigen::MatrixXd jtj;
  Eigen::VectorXd jte;
  s.cost = linearise(observations, model, s, &jtj, &jte);
  double lambda = 1e-3;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    Eigen::MatrixXd damped = jtj;
    damped.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-9);
    const Eigen::VectorXd delta = damped.ldlt().solve(jte);
    if (!delta.allFinite()) break;
    Solution candidate = step(s, delta, model);
    candidate.cost = linearise(observations, model, candidate, nullptr, nullptr);
    if (candidate.cost < s.cost) {
      const double improvement = s.cost - candidate.cost;
      s = candidate;
      s.cost = linearise(observations, model, s, &jtj, &jte);
      lambda = std::max(lambda * 0.3, 1e-9);
      if (delta.norm() < 1e-7 || improvement < 1e-12 * (1.0 + s.cost)) break;
    } else {
      lambda *= 5.0;
      if (lambda > 1e8) break;
    }
  }
  s.information = jtj;
  return s;
}

// Chunks are in the order the robot first visited them, so consecutive residuals are
// neighbours along the path.
ResidualStats residual_stats(const std::vector<Observation>& observations, const Model& model,
                             const Solution& s) {
  std::vector<double> residuals;
  double weighted = 0.0, total = 0.0;
  for (const Observation& o : observations) {
    const double e = o.m - (s.a - 10.0 * s.n * std::log10(distance(s.q, o.p, model.d)));
    residuals.push_back(e);
    weighted += o.w * e * e;
    total += o.w;
  }
  double lagged = 0.0, squares = 0.0;
  for (std::size_t j = 0; j < residuals.size(); ++j) {
    squares += residuals[j] * residuals[j];
    if (j + 1 < residuals.size()) lagged += residuals[j] * residuals[j + 1];
  }
  ResidualStats stats;
  stats.variance = total > 0 ? weighted / total : 0.0;
  stats.correlation = squares > 0 ? std::clamp(lagged / squares, 0.0, 0.99) : 0.0;
  return stats;
}

}  // namespace rigdesign::localize::detail
