#pragma once
/// A bundled scene as Gazebo (gz sim) loads it (issue 34): `world.sdf`, a world with the
/// Sensors system that renders gpu_lidar and depth_camera sensors, and the scene at t = 0 as one
/// static model whose visual and collision are the scene's triangles in `scene.obj` beside it.
/// The robot (its URDF with sensors.urdf.xacro and sensors.gazebo.xacro) is spawned into it
/// at the scene's start pose, which the file's comment gives.
#include <string>

#include "rigdesign/model/scene.hpp"

namespace rigdesign::deploy {

/// The scene's triangles (static objects and moving ones where they stand at t = 0) as a
/// Wavefront OBJ: one `v` line per vertex, one `f` line per triangle, world frame, metres.
std::string scene_obj_text(const model::Scene& scene, const std::string& header);

/// The world file; `mesh_file` is the OBJ's name, relative to the world file's folder.
std::string gazebo_world_text(const model::Scene& scene, const std::string& mesh_file,
                              const std::string& header);

}  // namespace rigdesign::deploy
