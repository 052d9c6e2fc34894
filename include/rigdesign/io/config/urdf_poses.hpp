#pragma once
/// Mount poses from a robot description: where each URDF link sits relative to the robot
/// frame link, with every joint at its zero position. A team points at its URDF instead of
/// copying numbers into the rig file.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/source_location.hpp"

namespace rigdesign::io {

class UrdfPoses {
 public:
  /// Parses `path`. `base_link` is the robot frame (on the floor under the robot's centre,
  /// REP-103); empty means the URDF's root link. Throws InputError at `named_at` (the rig's
  /// `urdf.file`) when the file cannot be read or parsed, and at `base_named_at` when the
  /// base link does not exist.
  static UrdfPoses load(const std::string& path, const std::string& base_link,
                        const model::SourceLocation& named_at,
                        const model::SourceLocation& base_named_at);

  /// T_base_link, or nothing when the URDF has no such link.
  std::optional<model::Pose3> T_base(const std::string& link) const;
  std::vector<std::string> link_names() const;
  const std::string& base_link() const { return base_link_; }

 private:
  std::map<std::string, model::Pose3> T_root_;  // every link's pose in the root link's frame
  std::string base_link_;
};

}  // namespace rigdesign::io
