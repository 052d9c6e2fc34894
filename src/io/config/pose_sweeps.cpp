// Catalog slots whose position sweeps a path (issue 55 item 4): a segment, a horizontal arc,
// or a face or edge of a description link's collision box, so "anywhere on the top plate's
// front edge" is one line of a catalog instead of a list of poses.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "io/config/placement_fields.hpp"
#include "rigdesign/model/catalog.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

// Spacings within this share of a step of a whole number of steps count as whole.
constexpr double kStepSlack = 1e-9;
// [m] how far proud of a link's face its positions sit: on the face itself a point counts as
// inside the body (select would leave every pose out); a housing seated there (seat: bottom
// or back) then rests on the face.
constexpr double kProudOfFace = 0.001;

// A face of an axis-aligned box in the robot frame (REP-103: x forward, y left, z up).
struct BoxFace {
  const char* name;
  int axis;   // 0 x, 1 y, 2 z
  bool high;  // the face at the box's largest value on that axis
};
constexpr std::array<BoxFace, 6> kBoxFaces = {{{"front", 0, true},
                                               {"back", 0, false},
                                               {"left", 1, true},
                                               {"right", 1, false},
                                               {"top", 2, true},
                                               {"bottom", 2, false}}};

struct SweptPosition {
  model::Vec3 p_robot = model::Vec3::Zero();
  double yaw = 0.0;  // [rad] added to rpy_deg's yaw (an arc facing outward)
  std::string label;
};

std::string position_label(const model::Vec3& p) {
  return "(" + model::format_number(p.x(), 4) + ", " + model::format_number(p.y(), 4) + ", " +
         model::format_number(p.z(), 4) + ") m";
}

std::optional<model::Vec3> read_point(MapReader& map, const std::string& key) {
  const auto values = map.numbers(key, Need::required, 3, 3, "[x, y, z] in metres");
  if (!values) return std::nullopt;
  return model::Vec3((*values)[0], (*values)[1], (*values)[2]);
}

// How many values `step` apart fit in [0, length] (the first at 0); nothing (with an error)
// beyond kMaxSlotPoses, or when `divides` asks the last to fall on `length` and it does not.
std::optional<std::size_t> values_in(MapReader& map, const std::string& key, double length,
                                     double step, bool divides) {
  const double steps = length / step;
  if (!(steps + 1 <= static_cast<double>(kMaxSlotPoses))) {
    map.require(false, key,
                "gives " + model::format_number(steps + 1, 3) + " positions over " +
                    model::format_number(length, 4),
                "at most " + std::to_string(kMaxSlotPoses) + " poses per slot (a coarser step)");
    return std::nullopt;
  }
  const double whole = std::floor(steps + kStepSlack * std::max(1.0, steps));
  if (divides && std::abs(steps - whole) > kStepSlack * std::max(1.0, steps)) {
    map.require(false, key,
                model::format_number(step) + " does not divide " + model::format_number(length, 6),
                "a step that divides the path, so that its end is one of the positions");
    return std::nullopt;
  }
  return static_cast<std::size_t>(whole) + 1;
}

std::vector<SweptPosition> along_positions(MapReader& pose) {
  std::optional<MapReader> along = pose.map("along", Need::required, "{from, to, step}");
  if (!along) return {};
  const auto from = read_point(*along, "from");
  const auto to = read_point(*along, "to");
  const auto step = along->number("step", Need::required, "metres between positions, > 0");
  along->reject_unknown_keys();
  if (!from || !to || !step) return {};
  if (!(*step > 0)) {
    along->require(false, "step", "is not positive", "metres between positions, > 0");
    return {};
  }
  const double length = (*to - *from).norm();
  const auto count = values_in(*along, "step", length, *step, true);
  if (!count) return {};
  std::vector<SweptPosition> positions;
  for (std::size_t i = 0; i < *count; ++i) {
    const double share =
        *count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(*count - 1);
    const model::Vec3 p = *from + share * (*to - *from);
    positions.push_back({p, 0.0, position_label(p)});
  }
  return positions;
}

std::vector<SweptPosition> arc_positions(MapReader& pose, bool& face_outward) {
  std::optional<MapReader> arc =
      pose.map("arc", Need::required, "{centre, radius, from_deg, to_deg, step_deg}");
  if (!arc) return {};
  const auto centre = read_point(*arc, "centre");
  const auto radius = arc->number("radius", Need::required, "metres, > 0");
  const auto from = arc->number("from_deg", Need::required, "the first azimuth, degrees");
  const auto to = arc->number("to_deg", Need::required, "the last azimuth, degrees");
  const auto step = arc->number("step_deg", Need::required, "degrees between positions, > 0");
  if (arc->has("face_outward"))
    face_outward = arc->boolean("face_outward", Need::required).value_or(true);
  arc->reject_unknown_keys();
  if (!centre || !radius || !from || !to || !step) return {};
  arc->require(*radius > 0, "radius", "is not positive", "metres, > 0");
  arc->require(*step > 0, "step_deg", "is not positive", "degrees between positions, > 0");
  arc->require(*from <= *to && *to - *from <= 360, "to_deg", "is not within 360 deg after from_deg",
               "from_deg <= to_deg <= from_deg + 360");
  if (!(*radius > 0) || !(*step > 0) || !(*from <= *to && *to - *from <= 360)) return {};
  const auto count = values_in(*arc, "step_deg", *to - *from, *step, true);
  if (!count) return {};
  std::vector<SweptPosition> positions;
  for (std::size_t i = 0; i < *count; ++i) {
    const double azimuth = model::deg_to_rad(*from + static_cast<double>(i) * *step);
    const model::Vec3 p =
        *centre + *radius * model::Vec3(std::cos(azimuth), std::sin(azimuth), 0.0);
    positions.push_back({p, azimuth,
                         "azimuth " +
                             model::format_number(*from + static_cast<double>(i) * *step, 6) +
                             " deg, " + position_label(p)});
  }
  return positions;
}

// The box bounding a link's collision geometry in the robot frame; false when it has none.
bool link_box(const std::vector<model::BodyPart>& parts, const std::string& link, model::Vec3& low,
              model::Vec3& high) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  low = model::Vec3::Constant(kNone);
  high = model::Vec3::Constant(-kNone);
  for (const model::BodyPart& part : parts) {
    if (part.link != link) continue;
    if (part.cylinder) {
      const model::VerticalCylinder& c = *part.cylinder;
      low = low.cwiseMin(model::Vec3(c.centre.x() - c.radius, c.centre.y() - c.radius, c.z_min));
      high = high.cwiseMax(model::Vec3(c.centre.x() + c.radius, c.centre.y() + c.radius, c.z_max));
    }
    for (const model::Vec3& v : part.triangles.vertices) {
      low = low.cwiseMin(v);
      high = high.cwiseMax(v);
    }
  }
  return (low.array() <= high.array()).all();
}

std::optional<std::size_t> face_named(MapReader& map, const std::string& key) {
  std::vector<std::string> names;
  for (const BoxFace& face : kBoxFaces) names.emplace_back(face.name);
  return map.choice(key, Need::required, names);
}

std::string links_with_geometry(const std::vector<model::BodyPart>& parts) {
  std::set<std::string> links;
  for (const model::BodyPart& part : parts) links.insert(part.link);
  std::vector<std::string> names(links.begin(), links.end());
  return names.empty() ? std::string("none: the catalog names no robot description")
                       : model::join(names);
}

std::vector<SweptPosition> link_positions(MapReader& pose,
                                          const std::vector<model::BodyPart>& parts) {
  std::optional<MapReader> on = pose.map("on_link", Need::required, "{link, face, step}");
  if (!on) return {};
  const auto link = on->text("link", Need::required, "a link of the robot description");
  const auto face = face_named(*on, "face");
  std::optional<std::size_t> edge;
  if (on->has("edge")) edge = face_named(*on, "edge");
  const auto step = on->number("step", Need::required, "metres between positions, > 0");
  const double inset =
      on->has("inset") ? on->number("inset", Need::required, "metres, >= 0").value_or(0.0) : 0.0;
  on->reject_unknown_keys();
  if (!link || !face || !step || (on->has("edge") && !edge)) return {};
  model::Vec3 low;
  model::Vec3 high;
  if (!link_box(parts, *link, low, high)) {
    on->require(false, "link", "'" + *link + "' has no collision geometry",
                "a link with collision geometry: " + links_with_geometry(parts));
    return {};
  }
  const BoxFace& on_face = kBoxFaces[*face];
  on->require(*step > 0, "step", "is not positive", "metres between positions, > 0");
  on->require(inset >= 0, "inset", "is negative", "metres, >= 0");
  on->require(!edge || kBoxFaces[*edge].axis != on_face.axis, "edge",
              "is on the same axis as the face",
              "a face next to it (front/back, left/right, top/bottom)");
  if (!(*step > 0) || !(inset >= 0) || (edge && kBoxFaces[*edge].axis == on_face.axis)) return {};
  // The position's three axes: the face's (fixed), the edge's (fixed), the rest swept.
  model::Vec3 fixed = low;
  fixed[on_face.axis] =
      on_face.high ? high[on_face.axis] + kProudOfFace : low[on_face.axis] - kProudOfFace;
  std::vector<int> swept;
  for (int axis = 0; axis < 3; ++axis) {
    if (axis == on_face.axis) continue;
    if (edge && axis == kBoxFaces[*edge].axis) {
      fixed[axis] = kBoxFaces[*edge].high ? high[axis] - inset : low[axis] + inset;
      continue;
    }
    swept.push_back(axis);
  }
  std::vector<std::vector<double>> values(3);
  for (const int axis : swept) {
    const double span = high[axis] - low[axis] - 2 * inset;
    if (!(span >= 0)) {
      on->require(false, "inset", "leaves nothing of the face", "less than half the face's width");
      return {};
    }
    const auto count = values_in(*on, "step", span, *step, false);
    if (!count) return {};
    for (std::size_t i = 0; i < *count; ++i)
      values[axis].push_back(low[axis] + inset + static_cast<double>(i) * *step);
  }
  std::vector<SweptPosition> positions;
  const std::vector<double> only = {0.0};
  const auto& first = swept.empty() ? only : values[swept[0]];
  const auto& second = swept.size() < 2 ? only : values[swept[1]];
  if (first.size() * second.size() > kMaxSlotPoses) {
    on->require(false, "step",
                std::to_string(first.size() * second.size()) + " positions on the face",
                "at most " + std::to_string(kMaxSlotPoses) + " (a coarser step, or an edge)");
    return {};
  }
  for (const double u : first) {
    for (const double v : second) {
      model::Vec3 p = fixed;
      if (!swept.empty()) p[swept[0]] = u;
      if (swept.size() > 1) p[swept[1]] = v;
      positions.push_back({p, 0.0, position_label(p)});
    }
  }
  return positions;
}

}  // namespace

std::vector<model::SlotPose> read_pose_sweep(MapReader& pose,
                                             const std::vector<model::BodyPart>& parts,
                                             std::vector<model::PoseAxisRange>& ranges) {
  const int paths = static_cast<int>(pose.has("along")) + static_cast<int>(pose.has("arc")) +
                    static_cast<int>(pose.has("on_link"));
  pose.require(paths == 1, "along", "names more than one path", "one of along, arc or on_link");
  pose.require(!pose.has("xyz"), "xyz", "is given together with a swept position",
               "xyz or one of along, arc, on_link");
  pose.require(!pose.has("urdf_link"), "urdf_link", "is given together with a swept position",
               "either urdf_link or a position");
  pose.require(!pose.has("frame"), "frame", "is not supported with a swept position",
               "an x-forward pose (frame: body, the default)");
  bool face_outward = true;
  const std::vector<SweptPosition> positions = pose.has("along") ? along_positions(pose)
                                               : pose.has("arc") ? arc_positions(pose, face_outward)
                                                                 : link_positions(pose, parts);
  std::array<PoseAxisValues, 3> rpy;
  for (auto& axis : rpy) axis.values = {0.0};
  if (const YAML::Node node = pose.node("rpy_deg"); node.IsDefined() && !node.IsNull()) {
    if (!node.IsSequence() || node.size() != 3) {
      pose.require(false, "rpy_deg", "is not a list of three values", "[roll, pitch, yaw] in deg");
      return {model::SlotPose{}};
    }
    for (int i = 0; i < 3; ++i)
      rpy[i] = read_pose_axis(pose, node[i], pose.field("rpy_deg") + "[" + std::to_string(i) + "]");
  }
  pose.require(!(pose.has("arc") && face_outward && rpy[2].varies), "rpy_deg",
               "gives a yaw range for an arc facing outward",
               "a fixed yaw offset, or face_outward: false");
  pose.reject_unknown_keys();
  const bool valid =
      std::all_of(rpy.begin(), rpy.end(), [](const auto& a) { return !a.values.empty(); });
  if (positions.empty() || !valid || (pose.has("arc") && face_outward && rpy[2].varies))
    return {model::SlotPose{}};
  const double count =
      static_cast<double>(positions.size()) * static_cast<double>(rpy[0].values.size()) *
      static_cast<double>(rpy[1].values.size()) * static_cast<double>(rpy[2].values.size());
  if (count > static_cast<double>(kMaxSlotPoses)) {
    pose.require(false, "rpy_deg", model::format_number(count, 3) + " poses in one slot",
                 "at most " + std::to_string(kMaxSlotPoses) + " (coarser steps, or more slots)");
    return {model::SlotPose{}};
  }
  for (int i = 0; i < 3; ++i) {
    if (!rpy[i].varies) continue;
    const std::vector<double>& v = rpy[i].values;
    ranges.push_back({3 + i, model::deg_to_rad(v.front()), model::deg_to_rad(v.back()),
                      model::deg_to_rad(v[1] - v[0])});
  }
  std::vector<model::SlotPose> poses;
  for (const SweptPosition& at : positions) {
    for (const double roll : rpy[0].values) {
      for (const double pitch : rpy[1].values) {
        for (const double yaw : rpy[2].values) {
          const std::array<double, 6> values = {
              at.p_robot.x(),           at.p_robot.y(),
              at.p_robot.z(),           model::deg_to_rad(roll),
              model::deg_to_rad(pitch), (face_outward ? at.yaw : 0.0) + model::deg_to_rad(yaw)};
          std::string label = at.label;
          const double degrees[3] = {roll, pitch, yaw};
          for (int i = 0; i < 3; ++i) {
            if (rpy[i].varies)
              label += ", " + std::string(model::kPoseAxisNames[3 + i]) + " " +
                       model::format_number(degrees[i], 6) + " deg";
          }
          poses.push_back(
              {model::pose_from_xyz_rpy(at.p_robot, model::Vec3(values[3], values[4], values[5])),
               label, values, "", false, ""});
        }
      }
    }
  }
  return poses;
}

}  // namespace rigdesign::io
