#pragma once
/// The slot poses `select` leaves out before the search (issue 52 item 1): those that put the
/// sensor's data origin inside the robot body (geometry/mount_placement.hpp). A rig with one of
/// them could not be bolted on, and its sensor would see nothing; the report says how many
/// were left out and why. (Sensors whose housing would cut into the body at a pose are left out
/// by the selection space, and recorded here too.)
#include <map>
#include <string>
#include <vector>

#include "rigdesign/model/catalog.hpp"

namespace rigdesign::select {

struct LeftOutPoses {
  std::string slot;
  model::SourceLocation where;  ///< the slot's entry
  std::size_t of = 0;           ///< poses the slot has
  /// Poses left out per reason ("inside the collision geometry of link 'chassis_link'
  /// (jackal.urdf.xacro:111)").
  std::map<std::string, std::size_t> reasons;
  /// Sensors left out at a pose that remains, per reason: the sensor's housing cuts into the
  /// body there ("realsense_d435 (its housing cuts 12 mm into ...)"); a count of poses.
  std::map<std::string, std::size_t> sensor_reasons;
  std::size_t count() const;
};

struct BuriedPoses {
  /// Per slot, per pose: true when the pose is left out.
  std::vector<std::vector<bool>> buried;
  /// The slots with any pose left out, in catalog order.
  std::vector<LeftOutPoses> left_out;
};

BuriedPoses find_buried_poses(const model::Catalog& catalog);

/// "top_scanner: 3 of 7 poses, 3 inside the collision geometry of link 'chassis_link' (...)".
std::string describe(const LeftOutPoses& left_out);

}  // namespace rigdesign::select
