#include "rigdesign/deploy/ros/self_filters/self_filters_reader.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rigdesign/deploy/sensor_frames.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/optical_frame.hpp"

namespace rigdesign::deploy {
namespace {

constexpr double kFilterPi = std::numbers::pi;
constexpr const char* kAngle = "an angle in radians in [-pi, pi]";
constexpr const char* kMetres = "metres";

// laser_filters reads its bounds in radians; beyond a full turn either way no scan angle lies,
// so such a value is degrees typed into a radians field (-135.1 for -2.358).
void refuse_degrees(io::MapReader& params, const std::string& key, double value) {
  params.require(std::abs(value) <= 2 * kFilterPi, key,
                 "looks like degrees: " + model::format_number(value, 6) + " is beyond +-2 pi",
                 std::string(kAngle) + " (" + model::format_number(value, 6) + " deg is " +
                     model::format_number(value * kFilterPi / 180, 4) + " rad)");
}

// The mount a node filters, from its name: the longest mount id it equals or starts with
// followed by '_'; empty when none.
std::string mount_of(const std::string& node, const model::Rig& rig) {
  std::string best;
  for (const model::Mount& mount : rig.mounts) {
    const std::string& id = mount.id;
    const bool named =
        node == id ||
        (node.size() > id.size() && node.compare(0, id.size(), id) == 0 && node[id.size()] == '_');
    if (named && id.size() > best.size()) best = id;
  }
  return best;
}

// A frame's pose in the robot frame: the robot's own frames, or a mount's exported frames.
std::optional<model::Pose3> frame_pose(const model::Rig& rig, const std::string& frame) {
  if (const std::optional<model::Pose3> pose = deploy::robot_frame_pose(rig, frame)) return pose;
  for (const model::Mount& mount : rig.mounts) {
    if (frame == deploy::sensor_link_name(mount.id)) return mount.T_robot_sensor;
    if (frame == deploy::optical_frame_name(mount.id)) {
      return mount.T_robot_sensor * model::T_sensor_optical();
    }
  }
  return std::nullopt;
}

std::vector<std::string> frame_names(const model::Rig& rig) {
  std::vector<std::string> names = {"base_footprint"};
  for (const auto& [name, pose] : rig.link_poses) names.push_back(name);
  for (const model::Mount& mount : rig.mounts) names.push_back(deploy::sensor_link_name(mount.id));
  return names;
}

// A box from min_x .. max_z in `frame_key`'s frame; nothing after recording an error.
std::optional<model::OrientedBox> read_box(io::MapReader& m, const std::string& frame_key,
                                           const std::string& default_frame,
                                           const model::Rig& rig) {
  model::OrientedBox box;
  bool ok = true;
  const char* axes[3] = {"x", "y", "z"};
  for (int axis = 0; axis < 3; ++axis) {
    const auto low = m.number(std::string("min_") + axes[axis], io::Need::required, kMetres);
    const auto high = m.number(std::string("max_") + axes[axis], io::Need::required, kMetres);
    ok = ok && low && high;
    if (low && high) {
      m.require(*low <= *high, std::string("min_") + axes[axis],
                "is above max_" + std::string(axes[axis]), "min <= max");
      box.min[axis] = *low;
      box.max[axis] = *high;
    }
  }
  const std::string frame = m.text(frame_key, io::Need::optional).value_or(default_frame);
  const std::optional<model::Pose3> pose = frame_pose(rig, frame);
  m.require(pose.has_value(), frame_key, "names no frame of " + rig.file + ": '" + frame + "'",
            "one of: " + model::join(frame_names(rig)));
  if (!ok || !pose) return std::nullopt;
  box.T_robot_box = *pose;
  return box;
}

std::string band_text(double lower, double upper) {
  return "(" + model::format_number(lower, 4) + ", " + model::format_number(upper, 4) + ") rad";
}

// One laser_filters entry (filterN: {name, type, params}) into `filters`.
void read_laser_filter(io::MapReader& entry, const std::string& mount, const model::Rig& rig,
                       std::vector<deploy::DeployedFilter>& filters) {
  const std::string name = entry.text("name", io::Need::optional).value_or("");
  const std::string type = entry
                               .text("type", io::Need::required,
                                     "a laser_filters type, e.g. "
                                     "laser_filters/LaserScanAngularBoundsFilterInPlace")
                               .value_or("");
  auto params = entry.map("params", io::Need::optional);
  entry.reject_unknown_keys();
  deploy::DeployedFilter filter;
  filter.mount_id = mount;
  filter.setting.where = entry.location();
  const std::string label = mount + " " + (name.empty() ? type : name);
  if (type == "laser_filters/LaserScanAngularBoundsFilterInPlace" ||
      type == "laser_filters/LaserScanAngularBoundsFilter") {
    if (!params) {
      entry.require(false, "params", "is missing", "lower_angle and upper_angle");
      return;
    }
    const auto lower = params->number("lower_angle", io::Need::required, kAngle);
    const auto upper = params->number("upper_angle", io::Need::required, kAngle);
    params->boolean("replace_with_nan", io::Need::optional);
    params->boolean("wrap_angle", io::Need::optional);
    params->reject_unknown_keys();
    for (const auto& [key, value] : {std::pair{"lower_angle", lower}, {"upper_angle", upper}}) {
      if (value) refuse_degrees(*params, key, *value);
    }
    if (!lower || !upper) return;
    const bool in_place = type.ends_with("InPlace");
    std::vector<model::AzimuthBand>& bands = filter.limits.excluded_azimuths;
    if (in_place) {
      // laser_filters' in-place filter drops the rays strictly between lower and upper, with
      // no wrap through +-pi (angular_bounds_filter_in_place.h, ros2 branch): lower >= upper
      // drops nothing.
      if (*lower < *upper) bands.push_back({*lower, *upper});
    } else {  // keeps [lower, upper], drops the rest
      if (*lower > -kFilterPi) bands.push_back({-kFilterPi, *lower});
      if (*upper < kFilterPi) bands.push_back({*upper, kFilterPi});
    }
    filter.setting.what =
        label +
        (in_place ? (bands.empty() ? " drops nothing (lower >= upper) " : " drops ")
                  : " keeps only ") +
        band_text(*lower, *upper);
  } else if (type == "laser_filters/LaserScanRangeFilter") {
    if (!params) return;
    const auto lower = params->number("lower_threshold", io::Need::optional, kMetres);
    const auto upper = params->number("upper_threshold", io::Need::optional, kMetres);
    for (const char* key :
         {"use_message_range_limits", "lower_replacement_value", "upper_replacement_value"})
      params->has(key);
    params->reject_unknown_keys();
    if (lower) filter.limits.min_range = *lower;
    if (upper && std::isfinite(*upper)) filter.limits.max_range = *upper;
    filter.setting.what = label + " keeps " + model::format_number(lower.value_or(0.0), 4) + ".." +
                          (upper ? model::format_number(*upper, 4) : std::string("inf")) + " m";
  } else if (type == "laser_filters/LaserScanBoxFilter") {
    if (!params) return;
    const bool invert = params->boolean("invert", io::Need::optional).value_or(false);
    params->require(!invert, "invert", "is true (keep only the inside)",
                    "false: rigdesign models boxes that drop their inside");
    const std::optional<model::OrientedBox> box =
        read_box(*params, "box_frame", deploy::sensor_link_name(mount), rig);
    params->reject_unknown_keys();
    if (!box || invert) return;
    filter.limits.excluded_boxes.push_back(*box);
    filter.setting.what = label + " drops a box";
  } else {
    return;  // speckle, intensity, median, ...: no fixed region dropped
  }
  if (!filter.limits.empty()) filters.push_back(std::move(filter));
}

}  // namespace

std::vector<deploy::DeployedFilter> load_self_filters(const std::string& path,
                                                      const std::string& mount,
                                                      const model::Rig& rig) {
  const YAML::Node root = io::load_yaml_file(path);
  model::Diagnostics diagnostics;
  std::vector<deploy::DeployedFilter> filters;
  if (root.IsMap()) {
    for (const auto& entry : root) {
      const std::string node = entry.first.as<std::string>("");
      const model::SourceLocation at = io::location_of(entry.first, path);
      const std::string owner = mount.empty() ? mount_of(node, rig) : mount;
      if (owner.empty()) {
        diagnostics.error(at, node, "names no mount of " + rig.file,
                          "a node named <mount id>_self_filter... for a mount of the rig: " +
                              model::join(rig.mount_ids()));
        continue;
      }
      const YAML::Node& body = entry.second;
      YAML::Node parameters;
      parameters.reset(body.IsMap() && body["ros__parameters"].IsDefined() ? body["ros__parameters"]
                                                                           : body);
      io::MapReader m(parameters, node, path, diagnostics, at);
      if (!m.valid()) {
        m.require(false, "ros__parameters", "is not a map", "the node's parameters");
        continue;
      }
      const bool crop_box = m.has("min_x") || m.has("max_x");
      if (crop_box) {
        const bool negative = m.boolean("negative", io::Need::optional).value_or(false);
        m.require(negative, "negative", "is false (keep only the inside)",
                  "true: a self-filter crop box drops its inside");
        const std::optional<model::OrientedBox> box =
            read_box(m, "input_frame", deploy::sensor_link_name(owner), rig);
        for (const char* key : {"keep_organized", "output_frame", "use_indices", "approximate_sync",
                                "max_queue_size"})
          m.has(key);
        m.reject_unknown_keys();
        if (box && negative) {
          deploy::DeployedFilter filter;
          filter.mount_id = owner;
          filter.limits.excluded_boxes.push_back(*box);
          filter.setting = {owner + " crop box " + node, at};
          filters.push_back(std::move(filter));
        }
        continue;
      }
      for (const auto& item : parameters) {
        const std::string key = item.first.as<std::string>("");
        if (!item.second.IsMap()) {  // a node's own settings (use_sim_time, ...)
          m.has(key);
          continue;
        }
        if (auto entry_map =
                m.map(key, io::Need::required, "a laser_filters entry: name, type, params")) {
          read_laser_filter(*entry_map, owner, rig, filters);
        }
      }
    }
  } else {
    diagnostics.error({path, 1, 1}, "(document)", "is not a map",
                      "ROS 2 parameters: <node name>: {ros__parameters: {...}}");
  }
  diagnostics.throw_if_errors();
  return filters;
}

}  // namespace rigdesign::deploy
