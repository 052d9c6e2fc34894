// The keys a rig file and a candidate catalog share (issue 51 item 2: one loader for both,
// where each loader once had its own copy).
#include "io/config/placement_fields.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/robot/collision_body.hpp"

namespace rigdesign::io {

DescribedRobotFields read_described_robot(MapReader& top, const std::string& file,
                                          model::DescribedRobot& robot,
                                          const DescriptionReader& read_description) {
  DescribedRobotFields fields;
  fields.links = read_robot_links(top, file, read_description);
  const std::optional<RobotLinks>& links = fields.links;
  const bool has_geometry = links && !links->failed && links->description;
  if (links && !links->failed) {
    robot.base_link = links->base_link;
    robot.base_link_height = links->base_height;
    robot.link_poses = links->T_base_link;
    robot.link_where = links->link_where;
    robot.joint_where = links->joint_where;
    robot.parent_link = links->parent_link;
    if (links->description) robot.description_sensors = links->description->sensors;
    robot.robot = links->source;
  }
  // With a robot description the body is its collision geometry unless `body` is given.
  if (auto body =
          top.map("body", has_geometry || top.has("robot") ? Need::optional : Need::required,
                  "a map with height and radius or footprint")) {
    robot.body = read_body(*body);
  } else if (has_geometry) {
    robot.body =
        io::body_from_description(*links->description, links->base_link, links->base_height);
    fields.body_from_description = true;
    top.require(robot.body.has_parts(), "robot", "has no collision geometry",
                "links with <collision> elements, or a `body` (radius or footprint, height)");
  }
  if (top.has("area_height")) {
    robot.body.area_height = positive_length(top, "area_height", Need::required,
                                             "the top of the area to perceive in metres, > 0");
  }
  robot.distance_of_interest =
      positive_length(top, "distance_of_interest", Need::required,
                      "the distance of interest d in metres, > body radius");
  if (robot.distance_of_interest > 0 && robot.body.radius > 0) {
    top.require(robot.distance_of_interest > robot.body.radius, "distance_of_interest",
                "is not beyond the body radius", "d > r");
  }
  return fields;
}

}  // namespace rigdesign::io
