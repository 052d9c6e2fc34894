#pragma once
/// What `select` chooses from (paper 1, section 2, Fig. 1): candidate sensor modes, mounting
/// slots with the sensors each accepts, transfer hardware and CPUs with their prices.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/housing_solid.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::model {

struct CandidateSensor {
  std::string sensor_id;
  std::vector<std::string> mode_ids;
  /// Filtering load U_f per delivered point [core-seconds], overriding the catalog's: given
  /// on the candidate, or measured for its sensor in the catalog's `filtering_loads` file.
  std::optional<double> filtering_seconds_per_point;
  SourceLocation where;
};

/// One pose a slot offers. `label` names the values a pose range varies ("z 0.5 m, pitch 25
/// deg"); empty for a fixed pose.
struct SlotPose {
  Pose3 T_robot_sensor = Pose3::Identity();
  std::string label;
  /// x, y, z [m], roll, pitch, yaw [rad] (REP-103 fixed axes) of a pose range's pose.
  std::array<double, 6> values{};
  /// The description link the pose is (`urdf_link`), empty for numbers; and whether it was
  /// taken as a camera's optical frame. The chosen rig keeps it.
  std::string urdf_link;
  bool urdf_link_optical = false;
  std::string housing_link;  ///< as model::Mount::housing_link
};

/// The names of a pose's six axes, indexed as PoseAxisRange::axis and SlotPose::values, as
/// pose-range labels and `select`'s reports spell them.
inline constexpr std::array<const char*, 6> kPoseAxisNames = {"x",    "y",     "z",
                                                              "roll", "pitch", "yaw"};

/// One axis a slot's pose range varies (issue 15), SI: low, low + step, ..., high.
struct PoseAxisRange {
  int axis = 0;  ///< 0-2: x, y, z; 3-5: roll, pitch, yaw (kPoseAxisNames)
  double low = 0.0;
  double high = 0.0;
  double step = 0.0;
};

struct MountingSlot {
  std::string id;
  /// The poses to choose from: one for a fixed pose, a pose range's grid otherwise (values
  /// that would put the sensor inside the body left out).
  std::vector<SlotPose> poses;
  std::vector<PoseAxisRange> ranges;  ///< the axes its pose range varies; none for a fixed pose
  std::vector<std::string> allowed_sensors;
  std::optional<double> distance_of_interest;  ///< [m] as a mount's
  /// What the poses place: each sensor's data origin, or its housing's bottom or back face
  /// (then each sensor's origin follows from its housing: model::HousingSolid::seat).
  HousingSeat seat = HousingSeat::origin;
  /// The shell has a pocket here (model::Mount::recessed): housings may sit inside the body.
  bool recessed = false;
  /// The mast, bracket or plate the slot needs (issue 52 item 3), bought with whichever sensor
  /// is chosen here: its price counts in every option of the slot, and the chosen rig declares
  /// it (id `<slot id>_support` unless given).
  std::optional<RigSupport> support;
  SourceLocation where;
};

/// A transfer component or CPU: of each kind, the cheapest one whose capacity exceeds the
/// rig's load is bought (paper 1, eqs. 3, 4 and 6): a CPU, and per transfer kind (cable,
/// switch, interface ...) one component, the transfer cost being their sum. A kind bought per
/// sensor (a cable, a port: `per_sensor: true`) is bought once for every sensor, each the
/// cheapest component that carries that sensor's own bandwidth.
struct PricedCapacity {
  std::string id;
  double capacity = 0.0;  ///< transfer: [bit/s]; CPU: [core-equivalents]
  double price = 0.0;     ///< [USD]
  SourceLocation where;
  /// The component kind (`transfer:` grouped by kind); empty: the one kind of a flat list.
  /// Items of one kind are contiguous.
  std::string kind;
  /// One per sensor, carrying that sensor's bandwidth alone (every item of the kind agrees).
  bool per_sensor = false;
};

/// The robot (as a rig describes it, so that the chosen rig stands on the same robot) and
/// what may be mounted on it.
struct Catalog : DescribedRobot {
  std::string name;
  std::string sensor_library;  ///< as written, relative to the catalog file
  SourceLocation sensor_library_where;
  std::vector<CandidateSensor> sensors;
  std::vector<MountingSlot> slots;
  std::vector<PricedCapacity> transfer;
  std::vector<PricedCapacity> cpus;
  /// Filtering load per delivered point [core-seconds] of sensors no measurement covers.
  double filtering_seconds_per_point = 0.0;
  std::string reference_machine;  ///< what a CPU's core-equivalent means
  std::string file;
  SourceLocation where;
};

}  // namespace rigdesign::model
