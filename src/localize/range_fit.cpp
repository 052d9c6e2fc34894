#include "rigdesign/localize/range_fit.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>

#include "db_domain_model.hpp"
#include "rigdesign/localize/wls_multilateration.hpp"

namespace rigdesign::localize {
namespace {

using detail::closed_form;
using detail::levenberg_marquardt;
using detail::Model;
using detail::Observation;
using detail::residual_stats;
using detail::ResidualStats;
using detail::Solution;

constexpr int kGridStarts = 4;       // best local minima of the grid that seed the search
constexpr double kMinSigma2 = 1e-6;  // [dB^2]

std::vector<Observation> observations_of(const std::vector<Chunk>& chunks) {
  double total = 0;
  for (const Chunk& chunk : chunks) total += chunk.count;
  const double mean = total / static_cast<double>(chunks.size());
  std::vector<Observation> observations;
  observations.reserve(chunks.size());
  for (const Chunk& chunk : chunks)
    observations.push_back({chunk.position(), chunk.mean_rssi(), chunk.count / mean});
  return observations;
}

// Chunks merged into cells of `size`: the grid scores candidates on these, not every chunk.
// Positions are finite and within the readers' coordinate limit, so cell indices fit.
std::vector<Chunk> coarsen(const std::vector<Chunk>& chunks, double size) {
  std::map<std::array<long long, 3>, std::size_t> index_of;
  std::vector<Chunk> merged;
  for (const Chunk& chunk : chunks) {
    const model::Vec3 p = chunk.position();
    const std::array<long long, 3> key = {static_cast<long long>(std::floor(p.x() / size)),
                                          static_cast<long long>(std::floor(p.y() / size)),
                                          static_cast<long long>(std::floor(p.z() / size))};
    const auto [it, inserted] = index_of.try_emplace(key, merged.size());
    if (inserted) merged.emplace_back();
    Chunk& cell = merged[it->second];
    cell.position_sum += chunk.position_sum;
    cell.range_sum += chunk.range_sum;
    cell.rssi_sum += chunk.rssi_sum;
    cell.count += chunk.count;
  }
  return merged;
}

// Local minima of the closed-form cost on a regular grid around the chunks, best first.
std::vector<model::Vec3> grid_starts(const std::vector<Observation>& coarse, const Model& model,
                                     const RangeFitParams& params, double margin) {
  model::Vec3 low = model::Vec3::Constant(1e300), high = model::Vec3::Constant(-1e300);
  for (const Observation& o : coarse) {
    low = low.cwiseMin(o.p);
    high = high.cwiseMax(o.p);
  }
  const int n = std::max(3, model.d == 3 ? params.grid_cells * 2 / 3 : params.grid_cells);
  const int nz = model.d == 3 ? n : 1;
  for (int k = 0; k < model.d; ++k) {
    low(k) -= margin;
    high(k) += margin;
  }
  const model::Vec3 cell = (high - low) / n;
  const auto centre = [&](int i, int j, int k) {
    model::Vec3 c(low.x() + (i + 0.5) * cell.x(), low.y() + (j + 0.5) * cell.y(), model.height);
    if (model.d == 3) c.z() = low.z() + (k + 0.5) * cell.z();
    return c;
  };
  std::vector<double> cost(static_cast<std::size_t>(n * n * nz));
  const auto at = [&](int i, int j, int k) -> double& {
    return cost[static_cast<std::size_t>((k * n + j) * n + i)];
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) at(i, j, k) = closed_form(coarse, centre(i, j, k), model).cost;
  std::vector<std::pair<double, model::Vec3>> minima;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        bool minimum = true;
        for (int dk = -1; dk <= 1 && minimum; ++dk)
          for (int dj = -1; dj <= 1 && minimum; ++dj)
            for (int di = -1; di <= 1 && minimum; ++di) {
              const int ii = i + di, jj = j + dj, kk = k + dk;
              if ((di || dj || dk) && ii >= 0 && jj >= 0 && kk >= 0 && ii < n && jj < n &&
                  kk < nz) {
                minimum = at(i, j, k) <= at(ii, jj, kk);
              }
            }
        if (minimum) minima.emplace_back(at(i, j, k), centre(i, j, k));
      }
  std::sort(minima.begin(), minima.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<model::Vec3> starts;
  for (std::size_t i = 0; i < minima.size() && static_cast<int>(i) < kGridStarts; ++i)
    starts.push_back(minima[i].second);
  return starts;
}

// Solutions more than 0.5 m from every better one (the input sorted best first).
std::vector<Solution> distinct(const std::vector<Solution>& sorted) {
  constexpr double kSame = 0.5;  // [m]
  std::vector<Solution> kept;
  for (const Solution& s : sorted) {
    if (std::none_of(kept.begin(), kept.end(),
                     [&](const Solution& k) { return (k.q - s.q).norm() < kSame; })) {
      kept.push_back(s);
    }
  }
  return kept;
}

// LM from every start, best first.
std::vector<Solution> solve_from(const std::vector<model::Vec3>& starts,
                                 const std::vector<Observation>& observations, const Model& model,
                                 int max_iterations) {
  std::vector<Solution> solutions;
  for (const model::Vec3& q : starts) {
    solutions.push_back(levenberg_marquardt(observations, model,
                                            closed_form(observations, q, model), max_iterations));
  }
  std::sort(solutions.begin(), solutions.end(),
            [](const Solution& a, const Solution& b) { return a.cost < b.cost; });
  return solutions;
}

Hypothesis to_hypothesis(const Solution& s, const Model& model, double sigma2) {
  Hypothesis h;
  h.position = s.q;
  h.rssi_at_1m_dbm = s.a;
  h.exponent = s.n;
  h.cost = s.cost;
  const Eigen::MatrixXd covariance =
      sigma2 * s.information.completeOrthogonalDecomposition().pseudoInverse();
  h.covariance.topLeftCorner(model.d, model.d) = covariance.topLeftCorner(model.d, model.d);
  return h;
}

}  // namespace

RangeFitResult fit_ranges(const std::vector<Chunk>& chunks, const GeometryAnalysis& geometry,
                          const PathLossParams& path_loss, const RangeFitParams& params) {
  RangeFitResult result;
  Model model;
  model.d = geometry.dimensions;
  model.fit_level = params.estimate_level;
  model.fit_exponent = params.estimate_exponent;
  model.a0 = path_loss.rssi_at_1m_dbm;
  model.n0 = path_loss.exponent;
  model.level_bound = params.level_bound_db;
  model.height = geometry.centroid.z();
  model.huber = params.huber_db;
  const int parameters = model.parameters();
  if (static_cast<int>(chunks.size()) <= parameters) return result;
  const std::vector<Observation> observations = observations_of(chunks);
  const std::vector<Chunk> merged = coarsen(chunks, params.coarse_chunk);
  const std::vector<Observation> coarse = observations_of(merged);

  std::vector<model::Vec3> starts;
  double median_range = 0.0;
  {
    std::vector<double> ranges;
    for (const Chunk& chunk : merged) ranges.push_back(chunk.mean_range());
    std::nth_element(ranges.begin(), ranges.begin() + static_cast<long>(ranges.size() / 2),
                     ranges.end());
    median_range = ranges[ranges.size() / 2];
  }
  if (const auto linear = wls_multilateration(chunks, model.d, WlsReference::weighted_mean)) {
    model::Vec3 q = linear->position;
    if (model.d == 2) q.z() = model.height;
    starts.push_back(q);
    starts.push_back(geometry.mirror(q));
  }
  for (const model::Vec3& q :
       grid_starts(coarse, model, params, std::max(params.grid_margin, median_range)))
    starts.push_back(q);

  // Pass 1 on the merged chunks, as if independent and without prior: finds the minima
  // cheaply; the residuals of all chunks at the best one measure the correlation.
  const std::vector<Solution> first =
      distinct(solve_from(starts, coarse, model, params.max_iterations));
  if (first.empty()) return result;  // no start gave a finite cost: no hypothesis
  std::vector<Observation> weighted = observations;
  model.cutoff = path_loss.cutoff_dbm;
  if (params.correlated_shadowing || params.level_prior_db > 0 || params.model_cutoff) {
    const ResidualStats stats = residual_stats(observations, model, first.front());
    result.residual_correlation = stats.correlation;
    if (params.correlated_shadowing) {
      const double share = (1.0 - stats.correlation) / (1.0 + stats.correlation);
      for (Observation& o : weighted) o.w *= share;
    }
    if (params.level_prior_db > 0)
      model.prior_weight = stats.variance / (params.level_prior_db * params.level_prior_db);
    if (params.model_cutoff) model.truncation_sigma = std::sqrt(stats.variance);
  }
  // Pass 2 from pass 1's minima: they move little when the weights change.
  std::vector<model::Vec3> refined;
  for (const Solution& s : first) refined.push_back(s.q);
  // On a circle the best point's inverse is the twin of an unknown level: search it too.
  if (geometry.circular && model.fit_level) refined.push_back(geometry.inverse(first.front().q));
  std::vector<Solution> solutions = solve_from(refined, weighted, model, params.max_iterations);
  if (solutions.empty()) return result;  // no start gave a finite cost: no hypothesis
  const Solution best = solutions.front();
  // On collinear chunks the mirror of the best minimum fits exactly as well: make sure it is
  // among the candidates even when no start led there.
  if (geometry.collinear) {
    Solution mirrored = best;
    mirrored.q = geometry.mirror(best.q);
    solutions.push_back(levenberg_marquardt(weighted, model, mirrored, params.max_iterations));
  }
  double total_weight = 0;
  for (const Observation& o : weighted) total_weight += o.w;
  result.effective_chunks = total_weight;
  const double dof = std::max(1.0, total_weight - parameters);
  // A floor of (1 mdB)^2 keeps the twin test meaningful on noise-free data.
  const double sigma2 = std::max(best.cost / dof, kMinSigma2);
  result.sigma_db = std::sqrt(sigma2);
  result.hypotheses.push_back(to_hypothesis(best, model, sigma2));
  std::sort(solutions.begin() + 1, solutions.end(),
            [](const Solution& a, const Solution& b) { return a.cost < b.cost; });
  for (std::size_t i = 1; i < solutions.size(); ++i) {
    const Solution& other = solutions[i];
    if ((other.q - best.q).norm() < params.min_twin_separation) continue;
    if ((other.cost - best.cost) / sigma2 < params.twin_chi2) {
      result.hypotheses.push_back(to_hypothesis(other, model, sigma2));
      result.twin = true;
    }
    break;
  }
  return result;
}

}  // namespace rigdesign::localize
