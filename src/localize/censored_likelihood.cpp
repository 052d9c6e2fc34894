#include "censored_likelihood.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

namespace rigdesign::localize::detail {
namespace {

constexpr double kDeepTail = -30.0;  // below this z, the tail expansions replace erfc
// 10 log10 d = (5 / ln 10) ln d^2: glibc's log is faster than its log10, Eigen's faster still.
constexpr double kFiveOverLn10 = 5.0 / std::numbers::ln10;
constexpr int kNewtonSteps = 12;
// Newton stops when a step moves the level and exponent less than this: far below what the
// data tell (tenths of a dB, hundredths of the exponent).
constexpr double kLevelTolerance = 1e-4;  // [dB]
constexpr double kExponentTolerance = 1e-5;
// The path-loss exponent's physical interval: 1.5 in corridors that guide the wave, up to 6
// in cluttered buildings (Rappaport, Wireless Communications, table 4.2). Outside it a fit
// reports impossible propagation (an exponent of -219 under a 1e5 dB wall).
constexpr double kMinExponent = 1.5, kMaxExponent = 6.0;

// The censored cells of one position: count, log distance and wall loss.
struct CensoredTerm {
  double count, log_distance, wall;
};

}  // namespace

NormalTail exact_normal_tail(double z) {
  if (z > kDeepTail) {
    const double cdf = 0.5 * std::erfc(-z / std::numbers::sqrt2);
    const double pdf = std::exp(-0.5 * z * z) / std::sqrt(2 * std::numbers::pi);
    return {std::log(cdf), pdf / cdf};
  }
  // Mills' expansion: Phi(z) ~ phi(z) / -z (1 - 1/z^2 + 3/z^4 - 15/z^6), within 2e-10 of erfc
  // at z = -30 (two terms were 4e-6 off).
  const double w = 1.0 / (z * z);
  const double series = w * (-1.0 + w * (3.0 - 15.0 * w));
  return {-0.5 * z * z - std::log(-z) - 0.5 * std::log(2 * std::numbers::pi) + std::log1p(series),
          -z / (1.0 + series)};
}

namespace {

// The search evaluates the tail for every unheard cell in every Newton step at every grid
// point: a log, an exp and an erfc each time were half its run time. Between the deep tail and
// z = 9 (where Phi is 1 to 1e-19) a table at 1/32 steps, interpolated by cubic Hermite
// polynomials with the exact derivatives (d log Phi / dz = lambda, d lambda / dz =
// -lambda (z + lambda)), is within about 1e-9 of the exact values.
class NormalTailTable {
 public:
  static constexpr double kStep = 1.0 / 32.0;
  static constexpr double kTop = 9.0;

  NormalTailTable() {
    const auto count = static_cast<std::size_t>((kTop - kDeepTail) / kStep) + 1;
    log_cdf_.resize(count);
    mills_.resize(count);
    mills_slope_.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      const double z = kDeepTail + static_cast<double>(i) * kStep;
      const NormalTail exact = exact_normal_tail(z);
      log_cdf_[i] = exact.log_cdf;
      mills_[i] = exact.inverse_mills;
      mills_slope_[i] = -exact.inverse_mills * (z + exact.inverse_mills);
    }
  }

  bool covers(double z) const { return z > kDeepTail && z < kTop - kStep; }

  NormalTail operator()(double z) const {
    const double u = (z - kDeepTail) / kStep;
    const auto i = static_cast<std::size_t>(u);
    const double t = u - static_cast<double>(i);
    // Hermite basis on [0, 1]; the slopes scale by the step.
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
    const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    return {h00 * log_cdf_[i] + h10 * kStep * mills_[i] + h01 * log_cdf_[i + 1] +
                h11 * kStep * mills_[i + 1],
            h00 * mills_[i] + h10 * kStep * mills_slope_[i] + h01 * mills_[i + 1] +
                h11 * kStep * mills_slope_[i + 1]};
  }

 private:
  std::vector<double> log_cdf_, mills_, mills_slope_;
};

}  // namespace

NormalTail normal_tail(double z) {
  static const NormalTailTable table;
  return table.covers(z) ? table(z) : exact_normal_tail(z);
}

double log_normal_cdf(double z) {
  return normal_tail(z).log_cdf;
}

double inverse_mills_ratio(double z) {
  return normal_tail(z).inverse_mills;
}

std::vector<ScanCell> merge_scans(const std::vector<Scan>& scans, double size) {
  std::map<std::pair<long long, long long>, std::size_t> index_of;
  std::vector<ScanCell> cells;
  std::vector<double> counts;
  // A path stays in a cell for several scans: the previous scan's cell is tried first.
  std::pair<long long, long long> last_key = {0, 0};
  std::size_t last = cells.max_size();
  for (const Scan& scan : scans) {
    const model::Vec2 p = scan.position.head<2>();
    const std::pair<long long, long long> key = {static_cast<long long>(std::floor(p.x() / size)),
                                                 static_cast<long long>(std::floor(p.y() / size))};
    if (last == cells.max_size() || key != last_key) {
      const auto [it, inserted] = index_of.try_emplace(key, cells.size());
      if (inserted) {
        cells.emplace_back();
        counts.push_back(0.0);
      }
      last = it->second;
      last_key = key;
    }
    ScanCell& cell = cells[last];
    double& count = counts[last];
    cell.position = (cell.position * count + p) / (count + 1.0);
    count += 1.0;
    if (scan.heard) {
      cell.heard += 1.0;
      cell.rssi_sum += scan.rssi_dbm;
      cell.rssi_square_sum += scan.rssi_dbm * scan.rssi_dbm;
    } else {
      cell.unheard += 1.0;
    }
  }
  return cells;
}

MergedScans merge_for_search(const std::vector<Scan>& scans) {
  return {merge_scans(scans, 1.0), merge_scans(scans, 0.5)};
}

CensoredLikelihood::CensoredLikelihood(std::span<const ScanCell> cells, LikelihoodSettings settings)
    : cells_(cells), settings_(std::move(settings)) {}

double CensoredLikelihood::log_distance(const model::Vec2& q, const model::Vec2& p) const {
  const double h = settings_.vertical_offset;
  return kFiveOverLn10 * std::log((q - p).squaredNorm() + h * h + 1e-6);
}

double CensoredLikelihood::wall_loss(const model::Vec2& q, const model::Vec2& p) const {
  return settings_.walls.empty() ? 0.0 : wall_loss_db(settings_.walls, p, q);
}

namespace {

// The heard scans' sums at one position: their squared residuals are a quadratic in (a, n)
// with these coefficients. And the squared distance from the position to the nearest scan.
struct CensoredSums {
  double C = 0, CL = 0, CLL = 0, Y = 0, YL = 0, Q = 0;
  double nearest = std::numeric_limits<double>::infinity();
};

// The sums of the heard cells, and one term per unheard cell in `censored`.
CensoredSums censored_sums(const CensoredLikelihood& likelihood, const model::Vec2& q,
                           std::vector<CensoredTerm>& censored) {
  const std::span<const ScanCell> cells = likelihood.cells();
  const LikelihoodSettings& s = likelihood.settings();
  CensoredSums sums;
  auto& [C, CL, CLL, Y, YL, Q, nearest] = sums;
  // The logs of the distances, one per cell at every grid point, are most of the search's
  // time: Eigen evaluates them two at a time (its SIMD log).
  thread_local Eigen::ArrayXd log_distances;
  log_distances.resize(static_cast<Eigen::Index>(cells.size()));
  const double h2 = s.vertical_offset * s.vertical_offset + 1e-6;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double squared = (q - cells[i].position).squaredNorm();
    nearest = std::min(nearest, squared);
    log_distances[static_cast<Eigen::Index>(i)] = squared + h2;
  }
  log_distances = kFiveOverLn10 * log_distances.log();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const ScanCell& cell = cells[i];
    const double L = log_distances[static_cast<Eigen::Index>(i)];
    const double W = likelihood.wall_loss(q, cell.position);
    if (cell.heard > 0) {
      const double y = cell.rssi_sum + cell.heard * W;  // sum of (y + W)
      C += cell.heard;
      CL += cell.heard * L;
      CLL += cell.heard * L * L;
      Y += y;
      YL += L * y;
      Q += cell.rssi_square_sum + 2 * W * cell.rssi_sum + cell.heard * W * W;
    }
    if (cell.unheard > 0) censored.push_back({cell.unheard, L, W});
  }
  return sums;
}

// The profile's objective in (a, n) at one position: the tempered log-likelihood of the heard
// sums and the censored terms, and the priors.
struct CensoredObjective {
  const LikelihoodSettings& s;
  const CensoredSums& sums;
  const std::vector<CensoredTerm>& censored;
  bool fit_exponent;
  double k, inv_var, prior_a, prior_n;

  // The objective, its gradient and Hessian in (a, n).
  double operator()(double a, double n, Eigen::Vector2d* g, Eigen::Matrix2d* H) const;
  // The heard scans alone (a linear least-squares problem with the priors).
  void start(double& a, double& n) const;
};

CensoredObjective censored_objective(const LikelihoodSettings& s, const CensoredSums& sums,
                                     const std::vector<CensoredTerm>& censored) {
  const bool fit_exponent = s.exponent_sd > 0.0;
  const double k = s.effective_share;
  const double inv_var = 1.0 / (s.sigma_db * s.sigma_db);
  const double prior_a = 1.0 / (s.level_sd_db * s.level_sd_db);
  const double prior_n = fit_exponent ? 1.0 / (s.exponent_sd * s.exponent_sd) : 0.0;
  return {s, sums, censored, fit_exponent, k, inv_var, prior_a, prior_n};
}

double CensoredObjective::operator()(double a, double n, Eigen::Vector2d* g,
                                     Eigen::Matrix2d* H) const {
  const auto& [C, CL, CLL, Y, YL, Q, nearest] = sums;
  const double squares = Q - 2 * a * Y + 2 * n * YL + a * a * C - 2 * a * n * CL + n * n * CLL;
  double value = -0.5 * k * inv_var * squares;
  Eigen::Vector2d grad(k * inv_var * (Y - a * C + n * CL), k * inv_var * (-YL + a * CL - n * CLL));
  Eigen::Matrix2d hess;
  hess << -C, CL, CL, -CLL;
  hess *= k * inv_var;
  for (const CensoredTerm& t : censored) {
    const double z = (s.floor_dbm - a + n * t.log_distance + t.wall) / s.sigma_db;
    const NormalTail tail = normal_tail(z);
    value += k * t.count * tail.log_cdf;
    const double lambda = tail.inverse_mills;
    const double kappa = lambda * (z + lambda);
    const double scale = k * t.count / s.sigma_db;
    grad(0) -= scale * lambda;
    grad(1) += scale * lambda * t.log_distance;
    const double curvature = k * t.count * kappa * inv_var;
    hess(0, 0) -= curvature;
    hess(0, 1) += curvature * t.log_distance;
    hess(1, 0) += curvature * t.log_distance;
    hess(1, 1) -= curvature * t.log_distance * t.log_distance;
  }
  value -= 0.5 * prior_a * (a - s.level_dbm) * (a - s.level_dbm);
  grad(0) -= prior_a * (a - s.level_dbm);
  hess(0, 0) -= prior_a;
  if (fit_exponent) {
    value -= 0.5 * prior_n * (n - s.exponent) * (n - s.exponent);
    grad(1) -= prior_n * (n - s.exponent);
    hess(1, 1) -= prior_n;
  }
  *g = grad;
  *H = hess;
  return value;
}

void CensoredObjective::start(double& a, double& n) const {
  const auto& [C, CL, CLL, Y, YL, Q, nearest] = sums;
  if (fit_exponent) {
    Eigen::Matrix2d A;
    A << k * inv_var * C + prior_a, -k * inv_var * CL, -k * inv_var * CL,
        k * inv_var * CLL + prior_n;
    const Eigen::Vector2d b(k * inv_var * Y + prior_a * s.level_dbm,
                            -k * inv_var * YL + prior_n * s.exponent);
    const Eigen::Vector2d x = A.partialPivLu().solve(b);
    a = x(0);
    n = std::clamp(x(1), kMinExponent, kMaxExponent);
  } else {
    a = (k * inv_var * (Y + n * CL) + prior_a * s.level_dbm) / (k * inv_var * C + prior_a);
  }
}

// Newton's method from (a, n), where the objective is `value` with gradient `g` and Hessian
// `H`; leaves all five at the optimum.
void censored_newton(const CensoredObjective& evaluate, double& a, double& n, double& value,
                     Eigen::Vector2d& g, Eigen::Matrix2d& H) {
  for (int step = 0; step < kNewtonSteps; ++step) {
    Eigen::Vector2d delta;
    if (evaluate.fit_exponent) {
      delta = -H.partialPivLu().solve(g);
    } else {
      delta = Eigen::Vector2d(-g(0) / H(0, 0), 0.0);
    }
    // Concave, but a full Newton step can overshoot where log Phi bends: halve until it gains.
    double factor = 1.0;
    Eigen::Vector2d g_new;
    Eigen::Matrix2d H_new;
    // The exponent stays in its physical interval (a projected step).
    const auto moved_n = [&](double f) {
      return std::clamp(n + f * delta(1), kMinExponent, kMaxExponent);
    };
    double value_new = evaluate(a + delta(0), moved_n(1.0), &g_new, &H_new);
    while (value_new < value - 1e-12 && factor > 1e-3) {
      factor *= 0.5;
      value_new = evaluate(a + factor * delta(0), moved_n(factor), &g_new, &H_new);
    }
    if (value_new < value - 1e-12) break;
    a += factor * delta(0);
    const double n_before = n;
    n = moved_n(factor);
    delta(1) = factor > 0 ? (n - n_before) / factor : 0.0;
    value = value_new;
    g = g_new;
    H = H_new;
    if (std::abs(factor * delta(0)) < kLevelTolerance &&
        std::abs(factor * delta(1)) < kExponentTolerance)
      break;
  }
}

// The optimum with the Laplace term for marginalising (a, n), or a alone, out.
ProfilePoint laplace_point(double a, double n, double value, const Eigen::Matrix2d& H,
                           bool fit_exponent) {
  ProfilePoint point;
  point.level_dbm = a;
  point.exponent = n;
  if (fit_exponent) {
    const Eigen::Matrix2d information = -H;
    const double det = std::max(information.determinant(), 1e-300);
    point.log_density = value - 0.5 * std::log(det);
    const Eigen::Matrix2d covariance = information.inverse();
    point.level_sd_db = std::sqrt(std::max(covariance(0, 0), 0.0));
    point.exponent_sd = std::sqrt(std::max(covariance(1, 1), 0.0));
  } else {
    const double information = std::max(-H(0, 0), 1e-300);
    point.log_density = value - 0.5 * std::log(information);
    point.level_sd_db = std::sqrt(1.0 / information);
  }
  return point;
}

}  // namespace

ProfilePoint CensoredLikelihood::profile(const model::Vec2& q) const {
  const LikelihoodSettings& s = settings_;
  thread_local std::vector<CensoredTerm> censored;
  censored.clear();
  const CensoredSums sums = censored_sums(*this, q, censored);
  const CensoredObjective evaluate = censored_objective(s, sums, censored);
  double a = s.level_dbm, n = s.exponent;
  evaluate.start(a, n);
  Eigen::Vector2d g;
  Eigen::Matrix2d H;
  double value = evaluate(a, n, &g, &H);
  censored_newton(evaluate, a, n, value, g, H);
  if (s.path_prior_scale > 0) value -= std::sqrt(sums.nearest) / s.path_prior_scale;
  return laplace_point(a, n, value, H, evaluate.fit_exponent);
}

double CensoredLikelihood::log_likelihood(const model::Vec2& q, double level_dbm, double exponent,
                                          double sigma_db) const {
  double sum = 0.0;
  const double log_sigma = std::log(sigma_db);
  for (const ScanCell& cell : cells_) {
    const double mu =
        level_dbm - exponent * log_distance(q, cell.position) - wall_loss(q, cell.position);
    if (cell.heard > 0) {
      const double squares = cell.rssi_square_sum - 2 * mu * cell.rssi_sum + cell.heard * mu * mu;
      sum += -cell.heard * log_sigma - 0.5 * squares / (sigma_db * sigma_db);
    }
    if (cell.unheard > 0)
      sum += cell.unheard * log_normal_cdf((settings_.floor_dbm - mu) / sigma_db);
  }
  return sum;
}

}  // namespace rigdesign::localize::detail
