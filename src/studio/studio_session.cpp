#include "rigdesign/studio/studio_session.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <thread>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/rig_references.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/metrics/mount_placement_verdicts.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::studio {
namespace {

model::Pose3 pose_from(const MountPose& pose) {
  return model::pose_from_xyz_rpy(
      {pose.xyz[0], pose.xyz[1], pose.xyz[2]},
      {model::deg_to_rad(pose.rpy_deg[0]), model::deg_to_rad(pose.rpy_deg[1]),
       model::deg_to_rad(pose.rpy_deg[2])});
}

bool same_pose(const model::Pose3& a, const model::Pose3& b) {
  return a.matrix() == b.matrix();
}

bool same_request(const io::RobotDescriptionRequest& a, const io::RobotDescriptionRequest& b) {
  return a.path == b.path && a.args == b.args && a.environment == b.environment &&
         a.package_paths == b.package_paths && a.expander == b.expander &&
         a.load_meshes == b.load_meshes;
}

// A mount id for `sensor` the loader takes (io::ros_name: letters, digits and underscores, not
// starting with a digit): a sensor id such as `rplidar-a1m8` becomes `rplidar_a1m8`.
std::string mount_id_for(const std::string& sensor) {
  std::string id;
  for (const char c : sensor) id += std::isalnum(static_cast<unsigned char>(c)) != 0 ? c : '_';
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id.front())) != 0) id = "mount_" + id;
  return id;
}

}  // namespace

MountPose pose_of(const model::Mount& mount) {
  const model::Vec3 xyz = mount.T_robot_sensor.translation();
  const model::Vec3 rpy = model::rpy_from_rotation(mount.T_robot_sensor.linear());
  return {{xyz.x(), xyz.y(), xyz.z()},
          {model::rad_to_deg(rpy.x()), model::rad_to_deg(rpy.y()), model::rad_to_deg(rpy.z())}};
}

StudioSession::StudioSession(std::string rig_path, std::string sensors_path,
                             std::string requirements_path)
    : rig_path_(std::move(rig_path)),
      sensors_path_(std::move(sensors_path)),
      requirements_path_(std::move(requirements_path)) {
  reload();
}

void StudioSession::reload() {
  exact_numbers_.reset();
  raster_.reset();
  inputs_.reset();
  loaded_mounts_.clear();
  given_poses_.clear();
  diagnostics_.clear();
  descriptions_.clear();
  try {
    // Saves go to this file, and only while the path still leads to it (a rig swapped for a
    // symbolic link elsewhere after loading is not followed).
    std::error_code ignored;
    target_ = std::filesystem::weakly_canonical(rig_path_, ignored).string();
    io::RigInputs inputs = io::load_rig_inputs(rig_path_, sensors_path_, requirements_path_);
    loaded_text_ = io::read_file_bytes(rig_path_, "a rig file");
    // Every core: a dragged mount's sections are rasterised while the user waits.
    raster_.emplace(inputs.rig, inputs.library, metrics::CoverageSettings{},
                    static_cast<int>(std::max(1U, std::thread::hardware_concurrency())));
    loaded_mounts_ = inputs.rig.mounts;
    diagnostics_ = inputs.warnings;
    for (model::Diagnostic& warning : metrics::placement_warnings(inputs.rig, inputs.library))
      diagnostics_.push_back(std::move(warning));
    inputs_ = std::move(inputs);
  } catch (const model::InputError& error) {
    diagnostics_ = error.diagnostics();
  }
}

MountPose StudioSession::pose(const model::Mount& mount) const {
  const auto given = given_poses_.find(mount.id);
  return given != given_poses_.end() ? given->second : pose_of(mount);
}

StudioNumbers StudioSession::numbers(bool exact) const {
  if (exact && exact_numbers_) return *exact_numbers_;
  const auto start = std::chrono::steady_clock::now();
  const io::RigInputs& in = *inputs_;
  StudioNumbers numbers;
  numbers.resultant = metrics::compute_resultant(in.rig, in.library);
  const std::vector<model::SectorRequirement> sectors =
      in.requirements ? in.requirements->sectors : std::vector<model::SectorRequirement>{};
  numbers.coverage =
      exact ? metrics::compute_coverage(in.rig, in.library, sectors) : raster_->coverage(sectors);
  if (in.requirements) {
    numbers.requirements = metrics::evaluate_requirements(in.rig, numbers.resultant,
                                                          *in.requirements, &numbers.coverage);
  }
  numbers.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (exact) exact_numbers_ = numbers;
  return numbers;
}

std::size_t StudioSession::index_of(const std::string& mount_id) const {
  const std::vector<model::Mount>& mounts = inputs_->rig.mounts;
  for (std::size_t i = 0; i < mounts.size(); ++i)
    if (mounts[i].id == mount_id) return i;
  throw model::InputError(model::Diagnostic({rig_path_, 0, 0}, "mount",
                                            "'" + mount_id + "' is not a mount of the rig",
                                            "the id of one of the rig's mounts"));
}

// The references load_rig_inputs checks and check's B1, so an edit is refused with check's
// words.
void StudioSession::validate(const model::Rig& rig) const {
  model::Diagnostics found = io::check_rig_references(rig, inputs_->library);
  // A mount buried in the body: check's B1 verdict, in its words, refuses the edit.
  // (B2, a housing cutting into another, is shown, not refused: a drag passes through.)
  const std::vector<metrics::RequirementResult> placement =
      metrics::placement_verdicts(rig, inputs_->library);  // B1 one per mount, in order
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    if (placement[i].verdict == metrics::Verdict::fail)
      found.error(placement[i].where, "mounts[" + std::to_string(i) + "].pose",
                  placement[i].explanation + " (check: B1)", "a sensor origin outside the body");
  }
  found.throw_if_errors();
}

// The rig file as a save would write it now, read by the rig loader itself: an edit the text
// editor cannot place (a value shared through an anchor, a merge key, a tag) or one that gives a
// rig the loader refuses (a pose beyond +-1e8 m, an id that is no ROS name) is refused with
// their message, so a saved rig always loads. The text is small; a robot description it names
// is read once (descriptions_) and its body rebuilt each time, about a tenth of a pose edit's
// time on the TurtleBot 4, whose moved mount's rasters take half.
void StudioSession::check_saved_text() const {
  const std::vector<io::MountEdit> edits = pending_edits();
  if (edits.empty()) return;
  const io::DescriptionReader read_once = [this](const io::RobotDescriptionRequest& request) {
    for (const auto& [known, description] : descriptions_)
      if (same_request(known, request)) return description;
    descriptions_.emplace_back(request, io::load_robot_description(request));
    return descriptions_.back().second;
  };
  io::load_rig_text(io::edit_rig_text(loaded_text_, target_, edits), target_, read_once);
}

// Applies `change` to mount `index` in place (no copy of the rig and its body), checks the text
// a save would write and validates the rig, and puts the mount back as it was when either
// refuses.
template <typename Change>
void StudioSession::change_mount(std::size_t index, Change change) {
  model::Mount& mount = inputs_->rig.mounts[index];
  const model::Mount before = mount;
  change(mount);
  try {
    check_saved_text();
    validate(inputs_->rig);
  } catch (...) {
    mount = before;
    throw;
  }
  raster_->set_mount(index, mount);
  exact_numbers_.reset();
}

void StudioSession::set_pose(const std::string& mount_id, const MountPose& pose) {
  // The numbers typed are the ones a save writes, so the text check sees them.
  const auto given = given_poses_.find(mount_id);
  const std::optional<MountPose> given_before =
      given != given_poses_.end() ? std::optional<MountPose>(given->second) : std::nullopt;
  given_poses_[mount_id] = pose;
  try {
    change_mount(index_of(mount_id), [&](model::Mount& mount) {
      mount.T_robot_sensor = pose_from(pose);
      // Saved as numbers from now on: the description's link no longer places this sensor.
      mount.urdf_link.clear();
      mount.urdf_link_optical = false;
      // The sensor stays in its housing: the saved pose states it (`housing:`), as it loads.
    });
  } catch (...) {
    if (given_before)
      given_poses_[mount_id] = *given_before;
    else
      given_poses_.erase(mount_id);
    throw;
  }
}

void StudioSession::set_sensor(const std::string& mount_id, const std::string& sensor,
                               const std::string& mode) {
  change_mount(index_of(mount_id), [&](model::Mount& mount) {
    mount.sensor_id = sensor;
    mount.mode_id = mode;
  });
}

std::string StudioSession::add_mount(const std::string& sensor, const std::string& mode,
                                     const MountPose& pose) {
  const auto taken = [&](const std::string& id) {
    for (const model::Mount& m : inputs_->rig.mounts)
      if (m.id == id) return true;
    for (const model::Mount& m : loaded_mounts_)
      if (m.id == id) return true;  // a removed mount's id would make its save ambiguous
    return false;
  };
  const std::string base = mount_id_for(sensor);
  std::string id = base;
  for (int n = 2; taken(id); ++n) id = base + "_" + std::to_string(n);
  model::Mount mount;
  mount.id = id;
  mount.sensor_id = sensor;
  mount.mode_id = mode;
  mount.T_robot_sensor = pose_from(pose);
  mount.where = {rig_path_, 0, 0};
  std::vector<model::Mount>& mounts = inputs_->rig.mounts;
  mounts.push_back(mount);
  given_poses_[id] = pose;
  try {
    check_saved_text();
    validate(inputs_->rig);
  } catch (...) {
    mounts.pop_back();
    given_poses_.erase(id);
    throw;
  }
  raster_->add_mount(mount);
  exact_numbers_.reset();
  return id;
}

void StudioSession::remove_mount(const std::string& mount_id) {
  const std::size_t index = index_of(mount_id);
  if (inputs_->rig.mounts.size() == 1)
    throw model::InputError(model::Diagnostic(inputs_->rig.mounts.front().where, "mounts",
                                              "would be empty without '" + mount_id + "'",
                                              "at least one mount"));
  std::vector<model::Mount>& mounts = inputs_->rig.mounts;
  const auto at = mounts.begin() + static_cast<std::ptrdiff_t>(index);
  const model::Mount removed = *at;
  mounts.erase(at);
  try {
    check_saved_text();  // e.g. its lines hold an anchor another mount's alias uses
  } catch (...) {
    mounts.insert(mounts.begin() + static_cast<std::ptrdiff_t>(index), removed);
    throw;
  }
  raster_->remove_mount(index);
  exact_numbers_.reset();
  given_poses_.erase(mount_id);
}

std::vector<io::MountEdit> StudioSession::pending_edits() const {
  std::vector<io::MountEdit> edits;
  const std::vector<model::Mount>& now = inputs_->rig.mounts;
  const auto find = [](const std::vector<model::Mount>& list, const std::string& id) {
    for (const model::Mount& m : list)
      if (m.id == id) return &m;
    return static_cast<const model::Mount*>(nullptr);
  };
  for (const model::Mount& before : loaded_mounts_) {
    if (find(now, before.id) != nullptr) continue;
    io::MountEdit edit;
    edit.mount_id = before.id;
    edit.kind = io::MountEdit::Kind::remove;
    edits.push_back(std::move(edit));
  }
  for (const model::Mount& mount : now) {
    const model::Mount* before = find(loaded_mounts_, mount.id);
    io::MountEdit edit;
    edit.mount_id = mount.id;
    edit.kind = before != nullptr ? io::MountEdit::Kind::change : io::MountEdit::Kind::add;
    if (before == nullptr || before->sensor_id != mount.sensor_id) edit.sensor = mount.sensor_id;
    if (before == nullptr || before->mode_id != mount.mode_id) edit.mode = mount.mode_id;
    if (before == nullptr || !same_pose(before->T_robot_sensor, mount.T_robot_sensor)) {
      const MountPose pose = this->pose(mount);
      edit.xyz = pose.xyz;
      edit.rpy_deg = pose.rpy_deg;
      edit.housing = mount.housing_link;  // written only where the file's pose was urdf_link
    }
    if (edit.kind == io::MountEdit::Kind::add || edit.sensor || edit.mode || edit.xyz)
      edits.push_back(std::move(edit));
  }
  return edits;
}

bool StudioSession::dirty() const {
  return loaded() && !pending_edits().empty();
}

void StudioSession::save() {
  const std::vector<io::MountEdit> edits = pending_edits();
  std::error_code ignored;
  if (std::filesystem::weakly_canonical(rig_path_, ignored).string() != target_)
    throw model::InputError(model::Diagnostic(
        {rig_path_, 0, 0}, "file",
        "now leads to another file than the one loaded (" + target_ + "); not written",
        "the rig file the studio was started on"));
  // The file itself, so a rig reached through a symbolic link stays a link.
  io::save_rig_edits(target_, loaded_text_, edits);
  // Read back as `check` reads it: new lines for added mounts, the written text as baseline.
  reload();
}

}  // namespace rigdesign::studio
