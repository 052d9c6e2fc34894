#pragma once
/// Synthetic scenes for sensor simulation (DESIGN.md section 6): triangle meshes in a world
/// frame (REP-103: z up, floor at z = 0), built by seeded generators, with moving parts
/// posed as functions of time.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/triangle_mesh.hpp"

namespace rigdesign::model {

struct SceneObject {
  std::string name;   ///< e.g. "floor", "table_2", "chair_1_leg_3", "cable"
  TriangleMesh mesh;  ///< world frame
};

struct MovingObject {
  std::string name;
  TriangleMesh mesh;                            ///< in the object's own frame
  std::function<Pose3(double)> T_world_object;  ///< pose at time t [s]
  /// [m] a person who lets a robot pass: the object stands still while the robot's centre is
  /// within this distance of its origin, so its own clock falls behind the scene's (the
  /// scenario runner keeps it); 0: it never waits (Scene::at uses scene time throughout).
  double gives_way_within = 0.0;
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  std::vector<MovingObject> moving;
  /// Where the robot frame (on the floor under the robot's centre) stands at the start.
  Pose3 T_world_robot = Pose3::Identity();

  /// Every triangle at time `t` [s], world frame.
  TriangleMesh at(double t) const;
};

}  // namespace rigdesign::model
