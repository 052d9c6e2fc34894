#include "rigdesign/select/buried_poses.hpp"

#include "rigdesign/geometry/mount_placement.hpp"

namespace rigdesign::select {

std::size_t LeftOutPoses::count() const {
  std::size_t total = 0;
  for (const auto& reason : reasons) total += reason.second;
  return total;
}

BuriedPoses find_buried_poses(const model::Catalog& catalog) {
  BuriedPoses found;
  for (const model::MountingSlot& slot : catalog.slots) {
    std::vector<bool>& buried = found.buried.emplace_back(slot.poses.size(), false);
    LeftOutPoses left_out{slot.id, slot.where, slot.poses.size(), {}, {}};
    for (std::size_t p = 0; p < slot.poses.size(); ++p) {
      const model::SlotPose& pose = slot.poses[p];
      const std::optional<geometry::Burial> burial =
          geometry::burial(catalog, pose.housing_link, pose.T_robot_sensor.translation());
      if (!burial) continue;
      buried[p] = true;
      ++left_out.reasons[burial->describe()];
    }
    if (!left_out.reasons.empty()) found.left_out.push_back(std::move(left_out));
  }
  return found;
}

std::string describe(const LeftOutPoses& left_out) {
  const std::string of =
      " of " + std::to_string(left_out.of) + (left_out.of == 1 ? " pose" : " poses");
  std::string text = left_out.slot + ":";
  if (!left_out.reasons.empty()) text += " " + std::to_string(left_out.count()) + of;
  for (const auto& [reason, count] : left_out.reasons)
    text += ", " + std::to_string(count) + " " + reason;
  bool first = left_out.reasons.empty();
  for (const auto& [reason, count] : left_out.sensor_reasons) {
    text += (first ? " " : "; ") + reason + " (at " + std::to_string(count) + of + ")";
    first = false;
  }
  return text;
}

}  // namespace rigdesign::select
