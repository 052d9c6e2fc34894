#include "scene_generators.hpp"

#include <stdexcept>

namespace rigdesign {

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"office", "corridor", "stairs", "wall_following",
                                              "cell"};
  return names;
}

Scene make_scene(const std::string& name, std::uint64_t seed) {
  // Only the office places anything at random; the other scenes are fixed test set-ups.
  if (name == "office") return sim::make_office_scene(seed);
  if (name == "corridor") return sim::make_corridor_scene();
  if (name == "stairs") return sim::make_stairs_scene();
  if (name == "wall_following") return sim::make_wall_following_scene();
  if (name == "cell") return sim::make_cell_scene();
  throw std::invalid_argument("unknown scene '" + name + "'");
}

namespace sim {

Pose3 floor_pose(double x, double y, double yaw) {
  Pose3 T_world_frame = Pose3::Identity();
  T_world_frame.linear() = Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
  T_world_frame.translation() = Vec3(x, y, 0.0);
  return T_world_frame;
}

}  // namespace sim
}  // namespace rigdesign
