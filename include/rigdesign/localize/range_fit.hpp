#pragma once
/// The better estimator: maximum likelihood under log-normal shadowing, i.e. nonlinear least
/// squares in the dB domain on the chunks' mean RSSI,
///     m_j = a - 10 n log10 |q - p_j| + e_j,   e_j ~ N(0, sigma^2 / c_j),
/// solved by Levenberg-Marquardt over (q, a[, n]). The 1 m level a (and optionally n) has a
/// closed form for a fixed q, which scores start candidates cheaply: the weighted-mean
/// linearised solution, its mirror across the path, and the local minima of a coarse grid.
/// Distinct minima whose costs differ by less than a chi-square margin are all reported (a
/// mirror twin on a straight path, the inverse-point twin of a circular path with unknown
/// level), each with the covariance sigma^2 (J^T W J)^-1.
///
/// Shadowing is correlated along the path, so 10 cm chunks are far from independent. A first
/// fit measures the residuals' lag-1 autocorrelation rho between consecutive chunks; the
/// second fit weights the chunks by the AR(1) effective-sample share (1 - rho) / (1 + rho),
/// which makes the covariances and the twin test honest and gives a weak Gaussian prior on
/// the 1 m level its proper say.
#include <vector>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/localize/geometry_analysis.hpp"
#include "rigdesign/localize/hypothesis.hpp"
#include "rigdesign/localize/path_loss.hpp"

namespace rigdesign::localize {

struct RangeFitParams {
  bool estimate_level = true;      ///< fit the 1 m level a (else PathLossParams' value)
  bool estimate_exponent = false;  ///< also fit n (else PathLossParams' value)
  /// The fitted level stays within this of the assumed one [dB]: phones differ by a few dB,
  /// and without a bound a circular path lets a far-away twin with an implausibly strong
  /// transmitter explain the data as well as the phone.
  double level_bound_db = 15.0;
  /// Standard deviation of the Gaussian prior on the 1 m level about the assumed one [dB]
  /// (0: no prior). Phones' transmit powers and antennas differ by a few dB.
  double level_prior_db = 4.0;
  /// Weight chunks by the effective-sample share measured from the residuals (see above).
  bool correlated_shadowing = true;
  /// Model the cut-off: a chunk near it survives only with favourable shadowing, so its
  /// expected mean is the truncated-normal mean (sigma from the first fit's residuals).
  bool model_cutoff = false;
  /// Huber threshold on dB residuals [dB]; 0 means plain least squares. Robust against walls.
  double huber_db = 0.0;
  int max_iterations = 60;
  /// A second minimum is reported when its cost exceeds the best by less than this many
  /// sigma^2 (chi-square, 2 degrees of freedom, 95 %: 5.99).
  double twin_chi2 = 5.99;
  double min_twin_separation = 2.0;  ///< [m] closer minima are the same hypothesis
  int grid_cells = 24;               ///< start grid cells per axis
  double grid_margin = 15.0;         ///< [m] the grid extends this far beyond the chunks
  double coarse_chunk = 1.0;         ///< [m] chunks merged to this size to score the grid
};

struct RangeFitResult {
  std::vector<Hypothesis> hypotheses;  ///< best first; empty when there are too few chunks
  bool twin = false;                   ///< more than one hypothesis fits about as well
  double sigma_db = 0.0;               ///< residual standard deviation per chunk [dB]
  double residual_correlation = 0.0;   ///< lag-1 autocorrelation of consecutive chunks' residuals
  double effective_chunks = 0.0;       ///< chunks times the effective-sample share
};

RangeFitResult fit_ranges(const std::vector<Chunk>& chunks, const GeometryAnalysis& geometry,
                          const PathLossParams& path_loss, const RangeFitParams& params = {});

}  // namespace rigdesign::localize
