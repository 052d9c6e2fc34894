#include "rigdesign/model/sensor_housing.hpp"

#include <algorithm>
#include <set>

namespace rigdesign::model {
namespace {

bool has_collision(const DescribedRobot& robot, const std::string& link) {
  return std::any_of(robot.body.parts.begin(), robot.body.parts.end(),
                     [&](const BodyPart& part) { return part.link == link; });
}

// `link` and the links above it. Each step goes one joint up and a description has one parent
// per link, so the walk ends within as many steps as there are links (the bound guards a
// cycle).
std::set<std::string> link_and_ancestors(const DescribedRobot& robot, std::string link) {
  std::set<std::string> chain;
  for (std::size_t step = 0; step <= robot.parent_link.size() && !link.empty(); ++step) {
    if (!chain.insert(link).second) break;
    const auto parent = robot.parent_link.find(link);
    if (parent == robot.parent_link.end()) break;
    link = parent->second;
  }
  return chain;
}

// True when a collision part of a link other than `link` hangs below `link`.
bool holds_other_collision(const DescribedRobot& robot, const std::string& link) {
  return std::any_of(robot.body.parts.begin(), robot.body.parts.end(), [&](const BodyPart& part) {
    return part.link != link && link_and_ancestors(robot, part.link).count(link) > 0;
  });
}

}  // namespace

std::string housing_link(const DescribedRobot& robot, const std::string& urdf_link) {
  if (urdf_link.empty()) return "";
  const std::set<std::string> robot_frame_chain = link_and_ancestors(robot, robot.base_link);
  std::string link = urdf_link;
  for (std::size_t step = 0; step <= robot.parent_link.size() && !link.empty(); ++step) {
    if (robot_frame_chain.count(link) > 0) return "";
    if (has_collision(robot, link)) return holds_other_collision(robot, link) ? "" : link;
    const auto parent = robot.parent_link.find(link);
    if (parent == robot.parent_link.end()) return "";
    link = parent->second;
  }
  return "";
}

std::string housing_refusal(const DescribedRobot& robot, const std::string& link) {
  if (robot.parent_link.count(link) == 0 && link != robot.base_link)
    return "is not a link of the robot description";
  if (!has_collision(robot, link)) return "has no collision geometry";
  if (link_and_ancestors(robot, robot.base_link).count(link) > 0)
    return "carries the robot frame: it is the robot's body, not a sensor's housing";
  if (holds_other_collision(robot, link))
    return "has other links' collision geometry below it: it is the robot's body, not a "
           "sensor's housing";
  return "";
}

}  // namespace rigdesign::model
