// Each mount's horizontal field of view as a wedge on the floor, for the costmap frames: the
// geometry of a wedge, apart from how a frame draws it.
#include <algorithm>
#include <cmath>

#include "rigdesign/render/costmap_frame.hpp"

namespace rigdesign::render {

std::vector<FovWedge> fov_wedges(const model::Rig& rig, const model::SensorLibrary& library,
                                 const costmap::Pose2& pose,
                                 std::span<const double> marking_ranges) {
  std::vector<FovWedge> wedges;
  const Eigen::Rotation2Dd R_world_robot(pose.yaw);
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::SensorMode& mode = *library.find(mount.sensor_id)->find_mode(mount.mode_id);
    const model::Vec3 axis = mount.T_robot_sensor.linear().col(0);
    const model::Vec2 offset = mount.T_robot_sensor.translation().head<2>();
    FovWedge wedge;
    wedge.apex = pose.position + R_world_robot * offset;
    wedge.yaw = pose.yaw + std::atan2(axis.y(), axis.x());
    wedge.half_angle = mode.fov.horizontal() / 2;
    wedge.range = std::min(mode.max_range, marking_ranges[i]);
    wedge.colour = i;
    wedge.label = mount.id + ": " + mount.sensor_id;
    wedges.push_back(wedge);
  }
  return wedges;
}

}  // namespace rigdesign::render
