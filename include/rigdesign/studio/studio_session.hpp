#pragma once
/// The rig as `rigdesign serve` edits it (issue 37): loaded with the checks `check` makes,
/// changed mount by mount, judged after every change (the raster path while a pose is being
/// dragged, the exact path when the drag ends), and saved back into the rig file's own text.
/// An edit that would make the rig invalid is refused with the message `check` would give and
/// the last valid state is kept; a rig that fails to load is kept as its errors, so the page
/// can show them while the server stays up.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/io/config/rig_inputs.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_text_editor.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/raster_coverage.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"

namespace rigdesign::studio {

/// The rig's numbers as `metrics` computes them, on the path `coverage.exact` names.
struct StudioNumbers {
  metrics::ResultantMetrics resultant;
  metrics::RigCoverage coverage;
  std::vector<metrics::RequirementResult> requirements;
  double seconds = 0.0;  ///< wall time of the computation (when it was made, for kept ones)
};

/// A mount's pose as the rig file writes it: xyz [m] and rpy [deg] of the sensor frame (x
/// along the optical axis) in the robot frame.
struct MountPose {
  std::array<double, 3> xyz{};
  std::array<double, 3> rpy_deg{};
};
MountPose pose_of(const model::Mount& mount);

class StudioSession {
 public:
  /// Loads the rig; load errors are kept (loaded() is false), not thrown.
  StudioSession(std::string rig_path, std::string sensors_path, std::string requirements_path);

  /// Reads the files again, dropping unsaved edits.
  void reload();
  bool loaded() const { return inputs_.has_value(); }
  /// Why the rig did not load (file:line:col messages), or the load's warnings.
  const std::vector<model::Diagnostic>& diagnostics() const { return diagnostics_; }
  /// Precondition for the accessors and edits below: loaded().
  const io::RigInputs& inputs() const { return *inputs_; }
  const std::string& rig_path() const { return rig_path_; }

  /// A mount's pose as a save writes it: as typed or dragged when edited, else read from its
  /// transform. Precondition: the mount exists.
  MountPose pose(const model::Mount& mount) const;

  /// The numbers for the rig as it stands: exact (CGAL) or raster. The exact ones are kept
  /// until the rig changes (an edit, a reload, a save): the page asks for them with every
  /// state, and under a sanitizer one exact cut of a two-scanner cart takes seconds.
  StudioNumbers numbers(bool exact) const;

  /// Edits. Each throws model::InputError when the rig would become invalid (the message
  /// `check` gives for it), when the rig file's text cannot take it (a value shared through a
  /// YAML anchor or merge key, or one whose text is not its value alone: the editor's message
  /// with its line and column), or when the file a save would write is one the rig loader
  /// refuses (its message), and then changes nothing.
  void set_pose(const std::string& mount_id, const MountPose& pose);
  void set_sensor(const std::string& mount_id, const std::string& sensor, const std::string& mode);
  /// A new mount with a fresh id (the sensor's id with every character but letters, digits and
  /// underscores made `_`, so that it is a ROS name; numbered when taken); returns the id.
  std::string add_mount(const std::string& sensor, const std::string& mode, const MountPose& pose);
  void remove_mount(const std::string& mount_id);

  /// Unsaved edits, as the text editor applies them.
  std::vector<io::MountEdit> pending_edits() const;
  bool dirty() const;
  /// Writes the edits into the rig file (only the edited values change; its mode, owner, group
  /// and hard links kept: io::replace_file_keeping_identity) and takes the written text as the
  /// new baseline. Throws InputError when the file changed on disk since it was loaded, an edit
  /// cannot be placed in its text, or the rig loader refuses the text (nothing written).
  void save();

 private:
  std::string rig_path_;
  std::string sensors_path_;
  std::string requirements_path_;
  std::string target_;       // the rig file's canonical path when loaded: the one file saved
  std::string loaded_text_;  // the rig file as read: what a save checks the disk against
  std::optional<io::RigInputs> inputs_;
  std::vector<model::Mount> loaded_mounts_;  // as in the file at loaded_text_
  std::optional<metrics::RasterCoverage> raster_;
  // Poses as typed or dragged (the numbers a save writes, not read back from a rotation).
  std::map<std::string, MountPose> given_poses_;
  std::vector<model::Diagnostic> diagnostics_;
  mutable std::optional<StudioNumbers> exact_numbers_;  // for the rig as it stands
  // The robot description as read for each request: every edit's text is read by the rig
  // loader, which would otherwise expand and load it again (seconds for the TurtleBot 4).
  mutable std::vector<std::pair<io::RobotDescriptionRequest, model::RobotDescription>>
      descriptions_;

  std::size_t index_of(const std::string& mount_id) const;
  void validate(const model::Rig& rig) const;
  void check_saved_text() const;
  template <typename Change>
  void change_mount(std::size_t index, Change change);
};

}  // namespace rigdesign::studio
