#pragma once
/// The range fit's posterior over the emitter's horizontal position, on a grid: what its
/// hypotheses, their probabilities and its credible region are read from. Stored at the finest
/// level of the search (cells of `cell` metres; cells never evaluated hold -infinity).
#include <vector>

#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct PositionPosterior {
  model::Vec2 origin = model::Vec2::Zero();  ///< lower-left corner of cell (0, 0) [m]
  double cell = 0.25;                        ///< cell edge [m]
  int columns = 0, rows = 0;
  std::vector<double> log_density;  ///< row-major, unnormalised; -inf where not evaluated
  double log_total = 0.0;           ///< log of the sum of density times cell area
  double credible_mass = 0.95;      ///< the level of `threshold`
  /// Cells at or above this log density make up the highest-density region holding
  /// `credible_mass` of the probability.
  double threshold = 0.0;

  model::Vec2 centre(int column, int row) const;
  /// The cell holding `point`, or -1 outside the grid.
  int index_of(const model::Vec2& point) const;
  /// Whether `point` lies in the highest-density region of `credible_mass`.
  bool contains(const model::Vec2& point) const;
  /// The probability mass of the cells denser than the one holding `point`: the smallest
  /// credible level whose highest-density region contains it (1 outside the evaluated cells).
  double credible_level(const model::Vec2& point) const;
  /// The probability of the evaluated cells whose centres lie within `radius` of `point`.
  double mass_within(const model::Vec2& point, double radius) const;
};

/// A posterior from a grid of unnormalised log densities (-inf: not evaluated): its total and
/// the threshold of its highest-density region holding `credible_mass`.
PositionPosterior make_posterior(const model::Vec2& origin, double cell, int columns, int rows,
                                 std::vector<double> log_density, double credible_mass);

}  // namespace rigdesign::localize
