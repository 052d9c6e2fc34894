#pragma once
/// Which parts of an emitter's position the robot's path can observe, from the spread of its
/// chunk positions: a ground robot at one height cannot observe z (the fit is then in x, y at
/// the robot's height), and chunks along one line cannot tell a point from its mirror image
/// across that line.
#include <vector>

#include "rigdesign/localize/chunking.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::localize {

struct GeometryParams {
  /// Standard deviation of the chunk heights below which z is unobservable [m].
  double min_height_spread = 0.3;
  /// Standard deviation of the chunk positions across the path's principal axis below which
  /// the positions count as collinear (the mirror image is then not resolved) [m].
  double min_lateral_spread = 0.5;
  /// RMS radial residual of a circle fit, as a share of its radius, below which the chunks
  /// count as circular.
  double max_circle_residual = 0.1;
};

struct GeometryAnalysis {
  int chunks = 0;
  model::Vec3 centroid = model::Vec3::Zero();  ///< count-weighted mean chunk position [m]
  model::Vec3 principal_axis =
      model::Vec3::UnitX();     ///< unit direction of largest spread (in x, y when 2D)
  double along_spread = 0.0;    ///< std along the principal axis [m]
  double lateral_spread = 0.0;  ///< std across it (in the fitted dimensions) [m]
  double height_spread = 0.0;   ///< std of the chunk heights [m]
  int dimensions = 2;           ///< 3 when z is observable, else 2 (x, y)
  bool collinear = false;
  /// The chunks lie near a circle (x, y): with an unknown 1 m level a point and its inverse
  /// in that circle explain the ranges alike (every point of the circle sees them at the
  /// same distance ratio: the circle of Apollonius).
  bool circular = false;
  model::Vec3 circle_centre = model::Vec3::Zero();  ///< [m], at the centroid's height
  double circle_radius = 0.0;                       ///< [m]

  /// The point rotated half a turn about the principal line: its mirror image across the
  /// path in 2D, which explains range data from collinear positions equally well.
  model::Vec3 mirror(const model::Vec3& point) const;
  /// The point's inverse in the fitted circle (x, y): centre + R^2 / |p - centre|^2 (p - centre).
  model::Vec3 inverse(const model::Vec3& point) const;
};

/// Needs at least one chunk.
GeometryAnalysis analyse_geometry(const std::vector<Chunk>& chunks,
                                  const GeometryParams& params = {});

}  // namespace rigdesign::localize
