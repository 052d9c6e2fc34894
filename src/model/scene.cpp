#include "rigdesign/model/scene.hpp"

namespace rigdesign::model {

TriangleMesh Scene::at(double t) const {
  TriangleMesh all;
  for (const SceneObject& object : objects) all.append(object.mesh);
  for (const MovingObject& object : moving) all.append(object.mesh, object.T_world_object(t));
  return all;
}

}  // namespace rigdesign::model
