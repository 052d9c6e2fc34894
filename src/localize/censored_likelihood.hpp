#pragma once
// The range fit's measurement model: a scan at p hears
//     y = a - 10 n log10 d(q, p) - W(q, p) + e,   e ~ N(0, sigma^2),
// d the distance to the emitter at q (with a vertical offset, since the phone's height is
// unknown), W the attenuation of the mapped walls in between, and a scan that heard nothing
// says y < floor (Tobit: its likelihood is Phi((floor - mu) / sigma)). Shadowing is correlated
// along the path, so the log-likelihood of the scans, summed as if independent (a composite
// likelihood), is tempered by the effective-sample share k; Gaussian priors on the 1 m level a
// and the exponent n. For a fixed position the objective is concave in (a, n) (mu is linear in
// them and log Phi is concave), so Newton's method profiles them out in a few steps; a Laplace
// term approximates their marginalisation. Private to src/localize.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/localize/walls.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize::detail {

// Scans merged into the cells of a spatial grid: what the likelihood needs of them.
struct ScanCell {
  model::Vec2 position = model::Vec2::Zero();  // mean of the cell's scans [m]
  double heard = 0.0;                          // scans that heard the emitter
  double rssi_sum = 0.0;                       // of the heard scans [dBm]
  double rssi_square_sum = 0.0;                // [dBm^2]
  double unheard = 0.0;                        // scans below the floor
};

// Cells of edge `size` [m], in order of first visit.
std::vector<ScanCell> merge_scans(const std::vector<Scan>& scans, double size);

// The scans merged once at the two sizes the search uses: 1 m cells for the coarse grids, 0.5 m
// cells for the finest grid, the peaks and the noise (merging moves distances of a few metres
// by centimetres).
struct MergedScans {
  std::vector<ScanCell> metre;
  std::vector<ScanCell> half_metre;
};
MergedScans merge_for_search(const std::vector<Scan>& scans);

struct LikelihoodSettings {
  double floor_dbm = -95.0;
  double sigma_db = 6.0;         // per scan, shadowing and fading together
  double effective_share = 1.0;  // k: independent samples per scan
  double level_dbm = -45.0;      // prior mean of a
  double level_sd_db = 8.0;      // prior sd of a
  double exponent = 2.5;         // prior mean of n
  double exponent_sd = 0.5;      // prior sd of n; 0: n fixed at its mean
  double vertical_offset = 0.6;  // [m] between the robot's antenna and the emitter
  // Prior on the position: density falling as exp(-distance to the nearest scan / scale)
  // (0: uniform over the search box).
  double path_prior_scale = 0.0;  // [m]
  std::vector<WallSegment> walls;
};

struct ProfilePoint {
  double log_density = 0.0;  // unnormalised log posterior of the position
  double level_dbm = 0.0;    // a at its conditional optimum
  double exponent = 0.0;     // n at its conditional optimum
  double level_sd_db = 0.0;  // conditional posterior sd of a
  double exponent_sd = 0.0;  // conditional posterior sd of n (0 when fixed)
};

class CensoredLikelihood {
 public:
  // `cells` must outlive the likelihood (it is read, not copied: the search builds many).
  CensoredLikelihood(std::span<const ScanCell> cells, LikelihoodSettings settings);

  // Maximises over (a, n) for the emitter at q.
  ProfilePoint profile(const model::Vec2& q) const;

  // The untempered log-likelihood of the scans for a given sigma, with the emitter at q and
  // the level and exponent given: what sigma is estimated from.
  double log_likelihood(const model::Vec2& q, double level_dbm, double exponent,
                        double sigma_db) const;

  const LikelihoodSettings& settings() const { return settings_; }
  std::span<const ScanCell> cells() const { return cells_; }

  // 10 log10 of the distance the model uses, and the walls' attenuation, for a scan at p.
  double log_distance(const model::Vec2& q, const model::Vec2& p) const;
  double wall_loss(const model::Vec2& q, const model::Vec2& p) const;

 private:
  std::span<const ScanCell> cells_;
  LikelihoodSettings settings_;
};

// log Phi(z) and the inverse Mills ratio phi(z) / Phi(z), accurate far into the lower tail,
// from one erfc.
struct NormalTail {
  double log_cdf;
  double inverse_mills;
};
NormalTail normal_tail(double z);        // tabulated where that is as exact (1e-9)
NormalTail exact_normal_tail(double z);  // erfc, or Mills' expansion in the deep tail
double log_normal_cdf(double z);
double inverse_mills_ratio(double z);

}  // namespace rigdesign::localize::detail
