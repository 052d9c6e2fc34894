#include "rigdesign/sim/scene_library.hpp"

#include <stdexcept>

#include "scene_generators.hpp"

namespace rigdesign::sim {

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"office", "corridor", "stairs", "wall_following",
                                              "cell"};
  return names;
}

model::Scene make_scene(const std::string& name, std::uint64_t seed) {
  // Only the office places anything at random; the other scenes are fixed test set-ups.
  if (name == "office") return make_office_scene(seed);
  if (name == "corridor") return make_corridor_scene();
  if (name == "stairs") return make_stairs_scene();
  if (name == "wall_following") return make_wall_following_scene();
  if (name == "cell") return make_cell_scene();
  throw std::invalid_argument("unknown scene '" + name + "'");
}

model::Pose3 floor_pose(double x, double y, double yaw) {
  model::Pose3 T_world_frame = model::Pose3::Identity();
  T_world_frame.linear() = Eigen::AngleAxisd(yaw, model::Vec3::UnitZ()).toRotationMatrix();
  T_world_frame.translation() = model::Vec3(x, y, 0.0);
  return T_world_frame;
}

}  // namespace rigdesign::sim
