#pragma once
/// Inside or outside a triangle mesh that need not be closed (issue 52 item 1). Collision
/// meshes of real robot descriptions often have holes (a public vehicle model: 2,315 boundary
/// edges), where counting the crossings of one ray calls points outside "inside" whenever the
/// ray leaves through a hole. The generalized winding number (Jacobson, Kavan and
/// Sorkine-Hornung, "Robust Inside-Outside Segmentation using Generalized Winding Numbers",
/// SIGGRAPH 2013) is the sum of the solid angles the triangles subtend at the point over 4 pi:
/// exactly 1 inside and 0 outside a closed, consistently oriented mesh, and a smooth value in
/// between near holes, which degrades gracefully where the parity test flips.
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::geometry {

/// The generalized winding number of `mesh` at `point`: sum of the triangles' signed solid
/// angles (Van Oosterom and Strackee, IEEE Trans. Biomed. Eng. 30(2), 1983) over 4 pi.
/// Positive inside a mesh whose triangles wind counter-clockwise seen from outside.
double winding_number(const model::TriangleMesh& mesh, const model::Vec3& point);

/// Whether `point` is inside `mesh`: |winding number| >= 1/2, so either orientation works.
bool inside_mesh(const model::TriangleMesh& mesh, const model::Vec3& point);

/// True when `point` is strictly inside a body part: a vertical cylinder, or a mesh by its
/// winding number.
bool inside_part(const model::BodyPart& part, const model::Vec3& point);

}  // namespace rigdesign::geometry
