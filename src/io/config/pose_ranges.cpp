// Pose ranges of catalog slots (issue 15): xyz and rpy_deg elements that are ranges.
#include <cmath>
#include <string>

#include "io/config/placement_fields.hpp"
#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kRange =
    "a number, or a range {min: a, max: b, step: s} with s > 0 dividing b - a";

}  // namespace

PoseAxisValues read_pose_axis(MapReader& pose, const YAML::Node& element,
                              const std::string& field) {
  PoseAxisValues axis;
  const model::SourceLocation at = location_of(element, pose.file());
  if (element.IsScalar()) {
    double value = 0.0;
    if (YAML::convert<double>::decode(element, value) && std::isfinite(value)) {
      axis.values = {value};
    } else {
      pose.diagnostics().error(at, field, "is not a finite number", kRange);
    }
    return axis;
  }
  if (!element.IsMap()) {
    pose.diagnostics().error(at, field, "is neither a number nor a range", kRange);
    return axis;
  }
  MapReader range(element, field, pose.file(), pose.diagnostics(), at);
  const auto low = range.number("min", Need::required, "the range's first value");
  const auto high = range.number("max", Need::required, "the range's last value");
  const auto step = range.number("step", Need::required, "the spacing of its values, > 0");
  range.reject_unknown_keys();
  if (!low || !high || !step) return axis;
  if (*low > *high) {
    range.require(false, "min", "is above max", "min <= max");
    return axis;
  }
  if (!(*step > 0.0)) {
    range.require(false, "step", "is not positive", "a spacing > 0");
    return axis;
  }
  const double steps = (*high - *low) / *step;
  const double whole = std::round(steps);
  if (std::abs(steps - whole) > 1e-9 * std::max(1.0, steps)) {
    range.require(false, "step",
                  model::format_number(*step) +
                      " does not divide max - min = " + model::format_number(*high - *low),
                  "a step that divides the range, so that max is one of the values");
    return axis;
  }
  // Bounded before the values are made: a step of 0.05 over 7.8e8 m would name 1.6e10 of
  // them (found by fuzzing: the count overflowed int).
  if (whole + 1 > static_cast<double>(kMaxSlotPoses)) {
    range.require(false, "step",
                  "gives " + model::format_number(whole + 1, 3) + " values from " +
                      model::format_number(*low) + " to " + model::format_number(*high),
                  "at most " + std::to_string(kMaxSlotPoses) + " poses per slot (a coarser step)");
    return axis;
  }
  for (int i = 0; i <= static_cast<int>(whole); ++i) axis.values.push_back(*low + i * *step);
  axis.varies = axis.values.size() > 1;
  return axis;
}

namespace {

bool holds_range(const YAML::Node& list) {
  if (!list.IsSequence()) return false;
  for (const YAML::Node& element : list) {
    if (element.IsMap()) return true;
  }
  return false;
}

}  // namespace

std::vector<model::SlotPose> read_pose_set(MapReader& pose, const std::optional<RobotLinks>& robot,
                                           const std::vector<model::BodyPart>& parts,
                                           std::vector<model::PoseAxisRange>& ranges) {
  if (pose.has("along") || pose.has("arc") || pose.has("on_link"))
    return read_pose_sweep(pose, parts, ranges);
  const YAML::Node xyz = pose.node("xyz");
  const YAML::Node rpy = pose.node("rpy_deg");
  if (!holds_range(xyz) && !holds_range(rpy)) {
    MountLink link;
    model::SlotPose single{
        read_pose(pose, robot, &link), "", {}, link.name, link.optical, link.housing};
    return {single};
  }
  std::vector<PoseAxisValues> axes(6);
  bool valid = true;
  for (const auto& [key, node, first] :
       {std::tuple{"xyz", xyz, 0}, std::tuple{"rpy_deg", rpy, 3}}) {
    if (!node.IsDefined() || node.IsNull()) {
      for (int i = 0; i < 3; ++i) axes[first + i].values = {0.0};  // rpy_deg defaults to 0
      if (first == 0) {
        pose.require(false, key, "is missing", "[x, y, z] in metres");
        valid = false;
      }
      continue;
    }
    if (!node.IsSequence() || node.size() != 3) {
      pose.require(false, key, "is not a list of three values", kRange);
      valid = false;
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      axes[first + i] =
          read_pose_axis(pose, node[i], pose.field(key) + "[" + std::to_string(i) + "]");
      valid = valid && !axes[first + i].values.empty();
    }
  }
  pose.require(!pose.has("urdf_link"), "urdf_link", "given together with a pose range",
               "either urdf_link or xyz/rpy_deg");
  pose.require(!pose.has("frame"), "frame", "is not supported with a pose range",
               "an x-forward pose (frame: body, the default)");
  pose.reject_unknown_keys();
  if (!valid) return {model::SlotPose{}};
  double poses_named = 1.0;  // at most 400^6 = 4.1e15 (axes are bounded above): exact in double
  for (const PoseAxisValues& axis : axes) poses_named *= static_cast<double>(axis.values.size());
  if (poses_named > static_cast<double>(kMaxSlotPoses)) {
    pose.require(false, "xyz", model::format_number(poses_named, 3) + " poses in one slot",
                 "at most " + std::to_string(kMaxSlotPoses) + " (coarser steps, or more slots)");
    return {model::SlotPose{}};
  }
  const auto count = static_cast<std::size_t>(poses_named);
  // Angles in radians from here on (SI in code).
  const auto si = [](int axis, double value) {
    return axis < 3 ? value : model::deg_to_rad(value);
  };
  for (int i = 0; i < 6; ++i) {
    if (!axes[i].varies) continue;
    const std::vector<double>& values = axes[i].values;
    ranges.push_back(
        {i, si(i, values.front()), si(i, values.back()), si(i, values[1]) - si(i, values[0])});
  }
  std::vector<model::SlotPose> poses;
  std::vector<std::size_t> index(6, 0);
  for (std::size_t n = 0; n < count; ++n) {
    double v[6];
    std::string label;
    for (int i = 0; i < 6; ++i) {
      v[i] = axes[i].values[index[i]];
      if (axes[i].varies) {
        label += (label.empty() ? "" : ", ") + std::string(model::kPoseAxisNames[i]) + " " +
                 model::format_number(v[i], 6) + (i < 3 ? " m" : " deg");
      }
    }
    std::array<double, 6> values{};
    for (int i = 0; i < 6; ++i) values[i] = si(i, v[i]);
    poses.push_back({model::pose_from_xyz_rpy(model::Vec3(values[0], values[1], values[2]),
                                              model::Vec3(values[3], values[4], values[5])),
                     label, values, "", false, ""});
    for (int i = 5; i >= 0; --i) {  // the last axis varies fastest
      if (++index[i] < axes[i].values.size()) break;
      index[i] = 0;
    }
  }
  return poses;
}

}  // namespace rigdesign::io
