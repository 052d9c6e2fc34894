#pragma once
// Scene geometry for tests, written apart from the simulator's own primitives so tests do not
// check the library against itself.
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::test {

/// An axis-aligned box [low, high] as 12 triangles, faces wound outwards.
model::TriangleMesh box_mesh(const model::Vec3& low, const model::Vec3& high);

/// The summed area of a mesh's triangles [m^2].
double surface_area(const model::TriangleMesh& mesh);

}  // namespace rigdesign::test
