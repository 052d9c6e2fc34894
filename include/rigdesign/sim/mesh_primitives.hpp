#pragma once
// Closed solids and floor planes the scene generators assemble scenes from. Solids are wound
// counter-clockwise seen from outside (outward normals), so a ray caster can tell front from
// back faces and a mesh's signed volume is positive. Private to sim.
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::sim {

/// Facets around a cylinder: 16 keeps the widest scene cylinder (a 5 cm office-chair column)
/// within 0.2 mm of round (sagitta r (1 - cos(pi / 16))), far below any lidar's noise.
constexpr int kCylinderSegments = 16;

/// An axis-aligned rectangle in the xy plane [m].
struct Rect2 {
  model::Vec2 low;
  model::Vec2 high;
};

/// A closed box with edge lengths `size` [m] along its own axes, centred on its frame's
/// origin, placed by `T_world_box`: 8 vertices, 12 triangles.
model::TriangleMesh box_mesh(const model::Vec3& size,
                             const model::Pose3& T_world_box = model::Pose3::Identity());

/// A closed world-aligned box between the corners `low` and `high` [m].
model::TriangleMesh aligned_box(const model::Vec3& low, const model::Vec3& high);

/// A closed cylinder of `radius` [m] whose axis runs along its frame's z from z = 0 to
/// z = `height` [m], placed by `T_world_cylinder`.
model::TriangleMesh cylinder_mesh(double radius, double height,
                                  const model::Pose3& T_world_cylinder = model::Pose3::Identity());

/// A closed cylinder of `radius` [m] whose axis runs from `start` to `end` [m]
/// (precondition: the two differ).
model::TriangleMesh cylinder_between(const model::Vec3& start, const model::Vec3& end,
                                     double radius);

/// A single-sided horizontal rectangle at height `z` [m], facing up (+z).
model::TriangleMesh floor_rectangle(const Rect2& area, double z);

/// A single-sided floor at height `z` [m] over `area` with rectangular `openings` left
/// open: no triangle covers any point inside an opening. Built as the cells of the grid the
/// rectangles' edges span, keeping the cells outside every opening.
model::TriangleMesh floor_with_openings(const Rect2& area, const std::vector<Rect2>& openings,
                                        double z);

}  // namespace rigdesign::sim
