#pragma once
// One generator per named scene (DESIGN.md section 6); make_scene() in scene_library.cpp
// dispatches on the name. Private to sim.
#include <cstdint>
#include <string>
#include <utility>

#include "rigdesign/model/scene.hpp"

namespace rigdesign::sim {

/// An 8 x 6 m office with seeded tables, chairs, boxes and a hanging cable.
model::Scene make_office_scene(std::uint64_t seed);
/// A 15 m corridor, 2 m wide, with two door recesses and a box.
model::Scene make_corridor_scene();
/// A floor with a stairwell going down 1 m and a pit.
model::Scene make_stairs_scene();
/// A wall on the robot's left and a low table whose foam top overhangs into the path.
model::Scene make_wall_following_scene();
/// Paper 3's 4 x 4 m cell: a plate in the centre and a person walking an ellipse around it.
model::Scene make_cell_scene();

/// A 1.75 m adult standing on the floor at its frame's origin, facing +x, about 0.5 m across
/// the arms; every part is symmetric about the body's vertical axis.
model::TriangleMesh person_mesh();

/// Adds a static object to `scene`.
inline void add_object(model::Scene& scene, std::string name, model::TriangleMesh mesh) {
  scene.objects.push_back({std::move(name), std::move(mesh)});
}

/// A pose standing on the floor (z = 0) at (x, y) [m], turned by `yaw` [rad] about +z: for
/// the robot and for furniture.
model::Pose3 floor_pose(double x, double y, double yaw);

}  // namespace rigdesign::sim
