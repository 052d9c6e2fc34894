#include "rigdesign/geometry/mount_placement.hpp"

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::geometry {

model::Diagnostics check_mount_placement(const model::Rig& rig) {
  return check_mount_placement(rig, BodyOccluder(rig.body));
}

model::Diagnostics check_mount_placement(const model::Rig& rig, const BodyOccluder& body) {
  model::Diagnostics diagnostics;
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    const model::Vec3 origin = mount.T_robot_sensor.translation();
    if (!body.contains(origin)) continue;
    diagnostics.error(
        mount.pose_where, "mounts[" + std::to_string(i) + "].pose",
        "puts the sensor origin (" + model::format_number(origin.x(), 4) + ", " +
            model::format_number(origin.y(), 4) + ", " + model::format_number(origin.z(), 4) +
            ") m inside the robot body, where it sees nothing",
        "a sensor origin on or outside the body (radius " + model::format_number(rig.body.radius) +
            " m, height " + model::format_number(rig.body.height) + " m)");
  }
  return diagnostics;
}

}  // namespace rigdesign::geometry
