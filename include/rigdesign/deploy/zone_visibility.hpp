#pragma once
/// What a collision monitor's sources see of a protective zone (issue 34): an obstacle enters
/// a zone across its boundary, so every boundary point outside the robot's own outline must be
/// seen by some source, on the column from the floor to the top of the area to perceive within
/// the heights that source passes. Exact along each column (MountedFov::covered_along, with
/// the body's occlusion); sampled along the boundary every `kBoundaryStep`, so an unseen gap
/// narrower than that step can be missed. Only the part of a zone within the viewers' reach
/// (their distance from the axis plus their max range) is sampled: beyond it nothing is seen,
/// so the work is bounded by the sensors, not by the zone a file types.
#include <vector>

#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/model/eigen_types.hpp"

namespace rigdesign::deploy {

/// [m] spacing of the boundary samples; interior samples (whether a source sees the zone at
/// all) are kInteriorStep apart.
inline constexpr double kBoundaryStep = 0.005;
inline constexpr double kInteriorStep = 0.02;
/// Most interior columns tried per viewer: a zone wider than about 20 m within the sensors'
/// reach is sampled more coarsely than kInteriorStep.
inline constexpr double kMaxInteriorSamples = 1e6;
/// Most samples along one edge within reach (5 km at kBoundaryStep); longer stretches are
/// sampled more coarsely.
inline constexpr double kMaxEdgeSamples = 1e6;

/// One source as the collision monitor filters it.
struct ZoneViewer {
  const geometry::MountedFov* fov = nullptr;
  /// [m] above the floor: the heights whose points the source passes (a LaserScan source
  /// passes every height its plane meets).
  double min_z = 0.0;
  double max_z = 0.0;
};

/// The robot's own outline: nothing can enter a zone through it. A round body is its radius
/// (`hull` empty), any other the convex hull nav2's footprint is.
struct BodyOutline {
  std::vector<model::Vec2> hull;  ///< counter-clockwise
  double radius = 0.0;            ///< [m] for a round body
  /// True when `p` lies inside the outline or within `tolerance` [m] of it.
  bool holds(const model::Vec2& p, double tolerance) const;
};

/// A stretch of a zone's boundary [m, robot frame], counter-clockwise from `from` to `to`.
struct BoundaryArc {
  model::Vec2 from = model::Vec2::Zero();
  model::Vec2 to = model::Vec2::Zero();
  double length = 0.0;
};

struct ZoneVisibility {
  std::vector<bool> sees;             ///< per viewer: some boundary or interior point
  std::vector<double> seen_boundary;  ///< per viewer: boundary length it sees [m]
  std::vector<BoundaryArc> unseen;    ///< boundary outside the body that no viewer sees
  double checked_boundary = 0.0;      ///< boundary length outside the body [m]
};

/// `zone`: a simple polygon (either winding) in the robot frame (z up from the floor).
/// `area_top` [m]: an obstacle is a column from the floor to it.
ZoneVisibility zone_visibility(const std::vector<model::Vec2>& zone, const BodyOutline& body,
                               const std::vector<ZoneViewer>& viewers, double area_top);

}  // namespace rigdesign::deploy
