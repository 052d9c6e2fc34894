#include "rigdesign/geometry/mount_placement.hpp"

#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/winding_number.hpp"

namespace rigdesign::geometry {

std::string Burial::describe() const {
  if (link.empty()) return "inside the robot body (" + model::to_string(where) + ")";
  return "inside the collision geometry of link '" + link + "' (" + model::to_string(where) + ")";
}

std::optional<Burial> burial(const model::DescribedRobot& robot, const std::string& housing,
                             const model::Vec3& origin) {
  if (!robot.body.has_parts()) {
    // A cylinder or prism: its occluder bins nothing, so one per question costs little.
    if (!BodyOccluder(robot.body).contains(origin)) return std::nullopt;
    return Burial{"", robot.body.where};
  }
  for (const model::BodyPart& part : robot.body.parts) {
    if (!housing.empty() && part.link == housing) continue;
    if (inside_part(part, origin)) return Burial{part.link, part.where};
  }
  return std::nullopt;
}

}  // namespace rigdesign::geometry
