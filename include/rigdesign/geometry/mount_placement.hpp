#pragma once
/// Whether a sensor's data origin lies inside the robot body (issue 52 item 1): inside a
/// cylinder or prism body, or inside a description's collision part other than the sensor's
/// own housing (model/sensor_housing.hpp). A sensor there sees nothing through that part: on a
/// real robot it cannot be bolted there. On the surface is allowed.
#include <optional>
#include <string>

#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::geometry {

/// What holds a buried origin: the collision part's link and its <collision> element in the
/// description, or the cylinder or prism body (link empty) and the rig's `body`.
struct Burial {
  std::string link;
  model::SourceLocation where;
  /// "inside the collision geometry of link 'chassis_link' (jackal.urdf.xacro:111)".
  std::string describe() const;
};

/// Null when a sensor at `origin` whose housing is `housing` (empty: none) is outside the body.
std::optional<Burial> burial(const model::DescribedRobot& robot, const std::string& housing,
                             const model::Vec3& origin);

}  // namespace rigdesign::geometry
