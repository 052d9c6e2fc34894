#pragma once
/// The robot body as closed triangles: what the 3D views draw and what a sensor's rays are
/// cast against to find where it sees its own robot (deploy::self_filters).
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::geometry {

/// The robot body as a closed prism from z = 0 to z = body.height [m]: the footprint polygon
/// when there is one (counter-clockwise; a clockwise one is accepted and reversed; simple
/// polygons only, convex or not), else a vertical cylinder of body.radius approximated by an
/// inscribed 64-sided polygon (0.16 % less area); a description's collision parts as they
/// are, their vertical cylinders as 64-sided prisms. Deterministic.
model::TriangleMesh body_mesh(const model::RobotBody& body);

}  // namespace rigdesign::geometry
