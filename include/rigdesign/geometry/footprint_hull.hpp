#pragma once
/// The body's horizontal outline as a navigation stack takes it: nav2's footprint is one
/// polygon (or a radius), so a body made of several parts is given by the convex hull of their
/// projection onto the floor.
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/rig.hpp"

namespace rigdesign::geometry {

/// Counter-clockwise convex hull of the body's projection onto the floor: of the footprint
/// polygon, of a cylinder's 64-sided inscribed polygon, or of every part's vertices (vertical
/// cylinders as 64-sided polygons). Collinear corners are dropped.
std::vector<model::Vec2> footprint_hull(const model::RobotBody& body);

/// Counter-clockwise convex hull of `points` (collinear points dropped).
std::vector<model::Vec2> convex_hull(const std::vector<model::Vec2>& points);

}  // namespace rigdesign::geometry
