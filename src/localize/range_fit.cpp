#include "rigdesign/localize/range_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "censored_likelihood.hpp"
#include "posterior_search.hpp"
#include "shadowing_correlation.hpp"

namespace rigdesign::localize {
namespace {

using detail::CensoredLikelihood;
using detail::LikelihoodSettings;

constexpr double kFirstSigma = 6.0;  // [dB] shadowing sigma the first look assumes
// Independent samples per scan the first look assumes: untempered, ten-centimetre scans would
// outweigh the priors on level and exponent and send the first fit anywhere.
constexpr double kFirstShare = 0.1;
constexpr double kLocalLookSize = 2.0;   // [m] the simplex's first size in the second look
constexpr double kPeakTolerance = 0.01;  // [m] the simplex's size when a peak is refined
// Modes whose densest cell lies within this of the best (log) are checked for a peak sharper
// than the grid, however small their basin's share.
constexpr double kSharpPeakBand = 30.0;
constexpr std::size_t kMaxCandidates = 16;           // modes refined, strongest basins first
constexpr double kCurvatureStep = 0.02;              // of a cell, for the Laplace curvature
constexpr double kMinSigma = 0.5, kMaxSigma = 30.0;  // [dB] sigma's search interval

// Nelder-Mead on the profile log density from `start`: the grid's cell centre refined to the
// continuous maximum. Two dimensions, so a few dozen evaluations.
// The search stays in the box: the posterior is only evaluated (and normalised) there.
model::Vec2 refine_peak(const CensoredLikelihood& likelihood, const model::Vec2& start, double size,
                        const detail::SearchBox& box) {
  const auto cost = [&](const model::Vec2& q) {
    return -likelihood.profile(q.cwiseMax(box.low).cwiseMin(box.high)).log_density;
  };
  std::array<model::Vec2, 3> simplex = {start, start + model::Vec2(size, 0),
                                        start + model::Vec2(0, size)};
  std::array<double, 3> value{};
  for (int i = 0; i < 3; ++i) value[i] = cost(simplex[i]);
  for (int iteration = 0; iteration < 80; ++iteration) {
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return value[a] < value[b]; });
    const int best = order[0], middle = order[1], worst = order[2];
    if ((simplex[worst] - simplex[best]).norm() < kPeakTolerance) break;
    const model::Vec2 centroid = 0.5 * (simplex[best] + simplex[middle]);
    const model::Vec2 reflected = centroid + (centroid - simplex[worst]);
    const double reflected_value = cost(reflected);
    if (reflected_value < value[best]) {
      const model::Vec2 expanded = centroid + 2.0 * (centroid - simplex[worst]);
      const double expanded_value = cost(expanded);
      if (expanded_value < reflected_value) {
        simplex[worst] = expanded;
        value[worst] = expanded_value;
      } else {
        simplex[worst] = reflected;
        value[worst] = reflected_value;
      }
    } else if (reflected_value < value[middle]) {
      simplex[worst] = reflected;
      value[worst] = reflected_value;
    } else {
      const model::Vec2 contracted = centroid + 0.5 * (simplex[worst] - centroid);
      const double contracted_value = cost(contracted);
      if (contracted_value < value[worst]) {
        simplex[worst] = contracted;
        value[worst] = contracted_value;
      } else {  // shrink towards the best
        for (const int i : {middle, worst}) {
          simplex[i] = simplex[best] + 0.5 * (simplex[i] - simplex[best]);
          value[i] = cost(simplex[i]);
        }
      }
    }
  }
  const auto best = std::min_element(value.begin(), value.end()) - value.begin();
  return simplex[static_cast<std::size_t>(best)].cwiseMax(box.low).cwiseMin(box.high);
}

// sigma maximising the untempered likelihood (golden-section search on log sigma).
double estimate_sigma(const CensoredLikelihood& likelihood, const model::Vec2& q, double level,
                      double exponent) {
  double low = std::log(kMinSigma), high = std::log(kMaxSigma);
  const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
  const auto f = [&](double log_sigma) {
    return -likelihood.log_likelihood(q, level, exponent, std::exp(log_sigma));
  };
  double x1 = high - golden * (high - low), x2 = low + golden * (high - low);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 50 && high - low > 1e-4; ++i) {
    if (f1 < f2) {
      high = x2;
      x2 = x1;
      f2 = f1;
      x1 = high - golden * (high - low);
      f1 = f(x1);
    } else {
      low = x1;
      x1 = x2;
      f1 = f2;
      x2 = low + golden * (high - low);
      f2 = f(x2);
    }
  }
  return std::exp(0.5 * (low + high));
}

// Residual correlation along the path at the best fit (heard scans only).
detail::ResidualCorrelation correlation_at(const ScanSeries& series,
                                           const CensoredLikelihood& model, const model::Vec2& q,
                                           double level, double exponent) {
  std::vector<double> travelled, residuals;
  std::vector<std::size_t> heard_index;
  double s = 0.0;
  for (std::size_t i = 0; i < series.scans.size(); ++i) {
    const Scan& scan = series.scans[i];
    if (i > 0) s += (scan.position - series.scans[i - 1].position).head<2>().norm();
    travelled.push_back(s);
    if (!scan.heard) continue;
    const model::Vec2 p = scan.position.head<2>();
    residuals.push_back(scan.rssi_dbm -
                        (level - exponent * model.log_distance(q, p) - model.wall_loss(q, p)));
    heard_index.push_back(i);
  }
  return detail::residual_correlation(travelled, residuals, heard_index);
}

// What the heard scans alone say about the exponent at q (level free): the tempered Fisher
// information k / sigma^2 * sum c (L - mean L)^2 over the cells, L = 10 log10 d. A circle
// around q has nearly one distance, a path past q many.
double exponent_information(const CensoredLikelihood& model, const model::Vec2& q) {
  const LikelihoodSettings& settings = model.settings();
  double count = 0.0, sum = 0.0, squares = 0.0;
  for (const detail::ScanCell& cell : model.cells()) {
    if (cell.heard <= 0) continue;
    const double L = model.log_distance(q, cell.position);
    count += cell.heard;
    sum += cell.heard * L;
    squares += cell.heard * L * L;
  }
  if (count <= 0) return 0.0;
  const double spread = squares - sum * sum / count;
  return settings.effective_share * spread / (settings.sigma_db * settings.sigma_db);
}

// The best point of a first look (the coarse grid), refined.
model::Vec2 best_point(const detail::MergedScans& merged, const LikelihoodSettings& settings,
                       const detail::SearchBox& box, const RangeFitParams& params) {
  const detail::PosteriorSearch look = detail::search_posterior(
      merged, settings, box, params.credible_mass, params.min_mode_separation, 1);
  const CensoredLikelihood model(merged.half_metre, settings);
  return refine_peak(model, look.modes.front().peak, look.posterior.cell, box);
}

// sigma (Tobit maximum likelihood) and, unless switched off, the residuals' correlation and
// the effective share it implies, with the emitter at q.
void measure_noise(const ScanSeries& series, const detail::MergedScans& merged,
                   const model::Vec2& q, const RangeFitParams& params, LikelihoodSettings* settings,
                   RangeFitResult* result) {
  const CensoredLikelihood model(merged.half_metre, *settings);
  detail::ProfilePoint at = model.profile(q);
  settings->sigma_db = estimate_sigma(model, q, at.level_dbm, at.exponent);
  at = CensoredLikelihood(model.cells(), *settings).profile(q);
  if (params.correlated_shadowing) {
    const detail::ResidualCorrelation correlation =
        correlation_at(series, model, q, at.level_dbm, at.exponent);
    settings->effective_share = correlation.effective_share;
    result->correlated_share = correlation.correlated_share;
    result->correlation_length = correlation.length;
  }
}

// The probability mass of a peak narrower than the grid's cells, by the Laplace approximation
// (the log density's curvature by central differences): exp(peak - log total) 2 pi / sqrt(det);
// empty when the peak is as wide as a cell, where the grid measures it.
std::optional<double> laplace_share(const CensoredLikelihood& model, const model::Vec2& peak,
                                    const PositionPosterior& posterior) {
  const double h = kCurvatureStep * posterior.cell;
  const auto f = [&](double dx, double dy) {
    return model.profile(peak + model::Vec2(dx, dy)).log_density;
  };
  const double centre = f(0, 0);
  Eigen::Matrix2d curvature;
  curvature(0, 0) = (f(h, 0) - 2 * centre + f(-h, 0)) / (h * h);
  curvature(1, 1) = (f(0, h) - 2 * centre + f(0, -h)) / (h * h);
  curvature(0, 1) = curvature(1, 0) = (f(h, h) - f(h, -h) - f(-h, h) + f(-h, -h)) / (4 * h * h);
  const Eigen::Matrix2d information = -curvature;
  const double det = information.determinant();
  if (!(information(0, 0) > 0 && det > 0)) return std::nullopt;
  const Eigen::Matrix2d covariance = information.inverse();
  const double widest = std::sqrt(std::max(covariance(0, 0), covariance(1, 1)));
  if (widest >= posterior.cell) return std::nullopt;
  return std::exp(centre - posterior.log_total) * 2 * std::numbers::pi / std::sqrt(det);
}

}  // namespace

std::array<model::Vec2, 2> search_area_of(const ScanSeries& series, const RangeFitParams& params) {
  if (params.search_area) return *params.search_area;
  model::Vec2 low = model::Vec2::Constant(std::numeric_limits<double>::max());
  model::Vec2 high = model::Vec2::Constant(std::numeric_limits<double>::lowest());
  for (const Scan& scan : series.scans) {
    low = low.cwiseMin(scan.position.head<2>());
    high = high.cwiseMax(scan.position.head<2>());
  }
  const model::Vec2 margin = model::Vec2::Constant(params.search_margin);
  return {low - margin, high + margin};
}

bool indistinguishable(const Hypothesis& a, const Hypothesis& b, const RangeFitParams& params) {
  return std::abs(a.cost - b.cost) <= params.ambiguity_log_ratio;
}

int side_of_path(const std::vector<Scan>& scans, const model::Vec2& point) {
  if (scans.size() < 2) return 0;
  std::size_t nearest = 0;
  double nearest_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const double d = (scans[i].position.head<2>() - point).squaredNorm();
    if (d < nearest_distance) {
      nearest_distance = d;
      nearest = i;
    }
  }
  // The direction of travel over a few scans either side: robust to position noise.
  constexpr std::size_t kSpan = 5;
  const std::size_t before = nearest >= kSpan ? nearest - kSpan : 0;
  const std::size_t after = std::min(scans.size() - 1, nearest + kSpan);
  const model::Vec2 direction =
      (scans[after].position - scans[before].position).head<2>().normalized();
  const model::Vec2 offset = point - scans[nearest].position.head<2>();
  const double cross = direction.x() * offset.y() - direction.y() * offset.x();
  constexpr double kOnPath = 0.01;  // [m]
  return cross > kOnPath ? 1 : cross < -kOnPath ? -1 : 0;
}

RangeFitResult fit_ranges(const ScanSeries& series, const PathLossParams& path_loss,
                          const RangeFitParams& params, const std::vector<WallSegment>& walls) {
  RangeFitResult result;
  if (series.heard == 0) return result;
  LikelihoodSettings settings;
  settings.floor_dbm = series.floor_dbm;
  settings.sigma_db = kFirstSigma;
  settings.effective_share = params.correlated_shadowing ? kFirstShare : 1.0;
  settings.level_dbm = path_loss.rssi_at_1m_dbm;
  settings.level_sd_db = params.level_prior_db;
  settings.exponent = path_loss.exponent;
  settings.exponent_sd = params.exponent_prior;
  settings.vertical_offset = params.vertical_offset;
  settings.path_prior_scale = params.path_prior_scale;
  settings.walls = walls;
  result.search_area = search_area_of(series, params);
  const detail::SearchBox box{result.search_area[0], result.search_area[1]};

  // A first look with the exponent fixed (a robust start): sigma and the share assumed, then
  // measured at the best point found; then once more with the exponent free under its prior,
  // at that point's peak (a local search: a whole grid again was a sixth of the run time).
  settings.exponent_sd = 0.0;
  const detail::MergedScans merged = detail::merge_for_search(series.scans);
  model::Vec2 best = best_point(merged, settings, box, params);
  measure_noise(series, merged, best, params, &settings, &result);
  if (params.exponent_prior > 0) {
    settings.exponent_sd = params.exponent_prior;
    best = refine_peak(CensoredLikelihood(merged.half_metre, settings), best, kLocalLookSize, box);
    measure_noise(series, merged, best, params, &settings, &result);
  }
  result.sigma_db = settings.sigma_db;
  result.effective_share = settings.effective_share;

  // The posterior with the measured sigma and effective share.
  detail::PosteriorSearch search = detail::search_posterior(
      merged, settings, box, params.credible_mass, params.min_mode_separation);
  const CensoredLikelihood model(search.finest_half_metre ? merged.half_metre : merged.metre,
                                 settings);
  double height = 0.0;
  for (const Scan& scan : series.scans) height += scan.position.z();
  height /= static_cast<double>(series.scans.size());
  // Each mode's probability: its basin's share of the grid, unless its peak is narrower than
  // the cells, which then miss most of its mass: the Laplace mass at the refined peak instead.
  struct Candidate {
    const detail::PosteriorMode* mode;
    model::Vec2 peak;
    double probability;  // the basin's, Laplace-corrected for a peak sharper than the cells
  };
  std::vector<Candidate> candidates;
  double grid_share = 0.0, corrected_share = 0.0;
  const double best_cell = search.modes.front().peak_log_density;
  for (const detail::PosteriorMode& mode : search.modes) {
    if (candidates.size() == kMaxCandidates) break;
    if (mode.probability < params.min_reported_probability &&
        mode.peak_log_density < best_cell - kSharpPeakBand)
      continue;
    const model::Vec2 peak = refine_peak(model, mode.peak, search.posterior.cell, box);
    double probability = mode.probability;
    if (const auto laplace = laplace_share(model, peak, search.posterior))
      probability = std::max(probability, *laplace);
    grid_share += mode.probability;
    corrected_share += probability;
    candidates.push_back({&mode, peak, probability});
  }
  const double total_share = 1.0 - grid_share + corrected_share;
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.probability > b.probability; });
  // Mass the cells miss at a sharp peak (Laplace minus grid share), per hypothesis: it sits
  // at the peak, within any decision radius of it.
  std::vector<double> missed_by_cells;
  for (const Candidate& candidate : candidates) {
    const double probability = candidate.probability / total_share;
    const double missed = (candidate.probability - candidate.mode->probability) / total_share;
    const model::Vec2& peak = candidate.peak;
    // Basins whose peaks refine to one point are one hypothesis.
    const auto same = std::find_if(
        result.hypotheses.begin(), result.hypotheses.end(), [&](const Hypothesis& other) {
          return (other.position.head<2>() - peak).norm() < params.min_mode_separation;
        });
    if (same != result.hypotheses.end()) {
      same->probability += probability;
      missed_by_cells[static_cast<std::size_t>(same - result.hypotheses.begin())] += missed;
      continue;
    }
    if (probability < params.min_reported_probability) continue;
    const detail::ProfilePoint point = model.profile(peak);
    Hypothesis h;
    h.position = model::Vec3(peak.x(), peak.y(), height);
    h.covariance.topLeftCorner<2, 2>() = candidate.mode->covariance;
    h.rssi_at_1m_dbm = point.level_dbm;
    h.exponent = point.exponent;
    h.level_sd_db = point.level_sd_db;
    h.exponent_sd = point.exponent_sd;
    h.cost = -point.log_density;
    h.probability = probability;
    h.side = side_of_path(series.scans, peak);
    result.hypotheses.push_back(h);
    missed_by_cells.push_back(missed);
  }
  // Listed by the probability within the decision radius (RangeFitParams::decision_radius).
  for (std::size_t i = 0; i < result.hypotheses.size(); ++i) {
    Hypothesis& h = result.hypotheses[i];
    h.probability_nearby =
        std::min(1.0, search.posterior.mass_within(h.position.head<2>(), params.decision_radius) /
                              total_share +
                          missed_by_cells[i]);
  }
  std::stable_sort(result.hypotheses.begin(), result.hypotheses.end(),
                   [](const Hypothesis& a, const Hypothesis& b) {
                     return a.probability_nearby.value_or(0.0) > b.probability_nearby.value_or(0.0);
                   });
  // Whether the path's distances to the best hypothesis tell the exponent (a circle around it
  // does not): otherwise its estimate rests on the prior, which the report says.
  if (params.exponent_prior > 0 && !result.hypotheses.empty()) {
    result.exponent_identified =
        exponent_information(model, result.hypotheses.front().position.head<2>()) *
            params.exponent_prior * params.exponent_prior >=
        params.identified_information;
  }
  result.ambiguous = result.hypotheses.size() >= 2 &&
                     indistinguishable(result.hypotheses[0], result.hypotheses[1], params);
  result.posterior = std::move(search.posterior);
  return result;
}

}  // namespace rigdesign::localize
