#pragma once
/// The exact path's input: what one sensor sees in a cross-section as simple polygons in
/// (rho, z), traced from exact column intervals. Columns are placed adaptively so that no
/// boundary point between two columns is farther than `tolerance` from the straight chord
/// joining them (curved range caps and cone sections are tessellated, straight FOV edges
/// cost nothing). Where the number of intervals changes, columns close in to `min_gap`.
#include <vector>

#include "rigdesign/geometry/cross_section.hpp"

namespace rigdesign::geometry {

struct TessellationSettings {
  double tolerance = 1e-3;     ///< [m] largest chord error of a curved boundary
  double initial_step = 0.02;  ///< [m] first column spacing before refinement
  double min_gap = 1e-4;       ///< [m] narrowest column spacing, at topology changes
};

using Polygon2 = std::vector<model::Vec2>;  ///< counter-clockwise vertices (rho, z)

std::vector<Polygon2> section_polygons(const MountedFov& fov, const SectionFrame& frame,
                                       const TessellationSettings& settings = {});

/// Area of the union of all polygons of all sensors, by CGAL's Boolean set operations on
/// exact-kernel polygons [m^2].
double union_area(const std::vector<std::vector<Polygon2>>& per_sensor);

}  // namespace rigdesign::geometry
