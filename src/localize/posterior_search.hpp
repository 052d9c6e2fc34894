#pragma once
// The range fit's posterior over the emitter's horizontal position, evaluated on grids refined
// where it matters: every cell of a coarse grid over the search box, then the cells near the
// best at finer spacings (coarse cells can miss a sharp peak by a few log units, so the kept
// band is wide at first). The finest grid is split into basins of attraction (steepest ascent
// to a local maximum); maxima closer than a minimum separation are one mode. Private to
// src/localize.
#include <Eigen/Core>
#include <vector>

#include "censored_likelihood.hpp"
#include "rigdesign/localize/position_posterior.hpp"
#include "rigdesign/localize/scan_series.hpp"

namespace rigdesign::localize::detail {

struct PosteriorMode {
  model::Vec2 peak = model::Vec2::Zero();                // centre of the densest cell [m]
  double peak_log_density = 0.0;                         // of that cell
  double probability = 0.0;                              // share of the posterior in the basin
  model::Vec2 mean = model::Vec2::Zero();                // posterior mean within the basin [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  // within the basin [m^2]
};

struct PosteriorSearch {
  PositionPosterior posterior;
  std::vector<PosteriorMode> modes;  // by probability, strongest first
  bool finest_half_metre = false;    // the finest grid used the 0.5 m cells (else 1 m)
};

struct SearchBox {
  model::Vec2 low, high;  // [m]
};

// `levels` > 1 refines; with 1 only the coarse grid is evaluated (a first look).
PosteriorSearch search_posterior(const MergedScans& scans, const LikelihoodSettings& settings,
                                 const SearchBox& box, double credible_mass,
                                 double min_mode_separation, int levels = 3);

}  // namespace rigdesign::localize::detail
