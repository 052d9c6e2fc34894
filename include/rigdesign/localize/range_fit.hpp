#pragma once
/// The better estimator (`nls`): the posterior of the emitter's horizontal position under the
/// log-distance model with log-normal shadowing, from every scan, heard or not:
///     y = a - 10 n log10 d - W + e,  e ~ N(0, sigma^2),  a scan below the floor: y < floor
/// (a Tobit likelihood: unheard scans say the emitter was far). The 1 m level a and the
/// exponent n are estimated with Gaussian priors about the assumed values (the exponent only
/// as far as the path's spread of distances allows: the fit says when the prior decides it);
/// W is the loss of mapped walls (`--walls`), which can tell mirror images apart.
///
/// Shadowing is correlated along the path, so the scans are not independent: a first fit
/// measures the residuals' correlation along the path (a correlated share and a length, fitted
/// to the empirical correlogram) and sigma (Tobit maximum likelihood), and the log-likelihood
/// is tempered by the effective-sample share they imply. The posterior is evaluated on a grid
/// refined where it matters (2 m, 1 m, 0.5 m); its modes are the hypotheses, each with the
/// probability of its basin, and its highest-density region of 95 % is the stated uncertainty.
/// Modes whose probabilities differ by less than what the noise can tell (likelihood-ratio
/// test at 95 %: ratio above exp(-3.84 / 2)) are reported as ambiguous, not ranked.
#include <array>
#include <optional>
#include <vector>

#include "rigdesign/localize/hypothesis.hpp"
#include "rigdesign/localize/path_loss.hpp"
#include "rigdesign/localize/position_posterior.hpp"
#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/localize/walls.hpp"

namespace rigdesign::localize {

struct RangeFitParams {
  /// Prior sd of the 1 m level about PathLossParams' value [dB]: phones' transmit powers and
  /// antennas differ by several dB.
  double level_prior_db = 4.0;
  /// Prior sd of the exponent about PathLossParams' value (0: the exponent is fixed).
  double exponent_prior = 0.5;
  /// Prior on the position, off by default (issue 33: it was scaled on the test matrix and pulls
  /// an emitter inside a room the path circles towards the path): the density falls as
  /// exp(-sqrt(d) / scale) with the distance d from the robot's path [m]; 0: uniform over the
  /// search area. Kept as a labelled option for comparison.
  double path_prior_scale = 0.0;
  /// The area the user searches (a rectangle in the log's frame, [m]): the prior on the
  /// position is uniform inside it and zero outside, and the posterior is evaluated there
  /// alone. Not given: the explored area, the path's bounding box grown by `search_margin`.
  std::optional<std::array<model::Vec2, 2>> search_area;
  /// [m] How far beyond the path's bounding box the explored area reaches when no search area
  /// is given: the rooms beside the corridors a robot drives (office rooms are 4-6 m deep).
  /// An assumption about where the user searches, stated in every report; `--search-area`
  /// replaces it. Without a bound the prior's area decides: on a path circling the emitter a
  /// wide plateau of far positions (each fitting with a strong transmitter and a low exponent)
  /// outweighs the emitter by its area alone.
  double search_margin = 5.0;
  /// Height between the robot's antenna and the emitter, unknown, taken as this [m].
  double vertical_offset = 0.6;
  /// Temper the likelihood by the effective-sample share of correlated shadowing.
  bool correlated_shadowing = true;
  double credible_mass = 0.95;  ///< of the stated region
  /// Two hypotheses are indistinguishable when their peaks' (tempered) log posterior densities
  /// differ by at most this: 3.84 / 2, a likelihood-ratio test at 95 %, one degree of freedom.
  /// Their probabilities (basin masses) may still differ, e.g. by how wide each peak is.
  double ambiguity_log_ratio = 1.92;
  double min_mode_separation = 2.0;  ///< [m] closer modes are one hypothesis
  /// The hypotheses are listed by their posterior probability within this distance [m]: the
  /// first is the point most likely to lie within the acceptable error of the emitter (the
  /// KPI's radius: paper 4's acceptable error, DARPA's 5 m). Listing by basin share instead
  /// put a wide basin first, however thinly spread (issue 33: on a loop round the phone,
  /// the far plateau or the path's band).
  double decision_radius = 5.0;
  double min_reported_probability = 0.01;  ///< weaker modes are not listed
  /// The exponent counts as told by the path when the heard scans' information about it at the
  /// best hypothesis is at least this many times the prior's (1: the data alone would halve the
  /// prior's variance); otherwise the report says its estimate rests on the prior (a circle
  /// around the emitter has nearly one distance).
  double identified_information = 1.0;
};

struct RangeFitResult {
  /// By probability, strongest first; empty without heard scans.
  std::vector<Hypothesis> hypotheses;
  /// The first two hypotheses are indistinguishable (see indistinguishable()).
  bool ambiguous = false;
  double sigma_db = 0.0;            ///< per scan, shadowing and fading (Tobit ML) [dB]
  double correlated_share = 0.0;    ///< of the residual variance that is correlated
  double correlation_length = 0.0;  ///< of the correlated part along the path [m]
  double effective_share = 1.0;     ///< independent samples per scan the tempering uses
  /// The path tells the exponent (see identified_information); otherwise its estimate rests on
  /// the prior.
  bool exponent_identified = false;
  /// The rectangle the posterior covers (low, high corners, [m]): the user's search area or
  /// the explored area (RangeFitParams::search_margin).
  std::array<model::Vec2, 2> search_area{model::Vec2::Zero(), model::Vec2::Zero()};
  std::optional<PositionPosterior> posterior;
};

/// The rectangle the position prior is uniform on: RangeFitParams::search_area if given, else
/// the scans' bounding box grown by RangeFitParams::search_margin.
std::array<model::Vec2, 2> search_area_of(const ScanSeries& scans, const RangeFitParams& params);

RangeFitResult fit_ranges(const ScanSeries& scans, const PathLossParams& path_loss,
                          const RangeFitParams& params = {},
                          const std::vector<WallSegment>& walls = {});

/// Whether the data cannot tell `a` from `b`: their peaks' costs (-log density) differ by at
/// most RangeFitParams::ambiguity_log_ratio.
bool indistinguishable(const Hypothesis& a, const Hypothesis& b, const RangeFitParams& params);

/// The side of the path `point` lies on (+1 left, -1 right, 0 within 1 cm), facing the
/// direction of travel at the scan nearest to it.
int side_of_path(const std::vector<Scan>& scans, const model::Vec2& point);

}  // namespace rigdesign::localize
