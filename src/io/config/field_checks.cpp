#include "rigdesign/io/config/field_checks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/ros_names.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {

void read_if_present(MapReader& reader, const std::string& key, double& value,
                     const std::string& expected) {
  if (const auto v = reader.number(key, Need::optional, expected)) value = *v;
}

void read_if_present(MapReader& reader, const std::string& key, int& value,
                     const std::string& expected) {
  if (const auto v = reader.integer(key, Need::optional, expected)) value = *v;
}

void read_if_present(MapReader& reader, const std::string& key, bool& value) {
  if (const auto v = reader.boolean(key, Need::optional)) value = *v;
}

double positive(MapReader& reader, const std::string& key, Need need, const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return 0.0;
  reader.require(*value > 0, key, "must be > 0, got " + model::format_number(*value), expected);
  return *value;
}

double positive_length(MapReader& reader, const std::string& key, Need need,
                       const std::string& expected) {
  const double value = positive(reader, key, need, expected);
  if (value > model::kMaxCoordinate) {
    reader.require(false, key, "is " + model::format_number(value) + " m, beyond 1e8 m", expected);
    return 0.0;
  }
  return value;
}

double non_negative(MapReader& reader, const std::string& key, Need need,
                    const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return 0.0;
  reader.require(*value >= 0, key, "must be >= 0, got " + model::format_number(*value), expected);
  return *value;
}

double angle_in(MapReader& reader, const std::string& key, double low, double high,
                bool high_inclusive, const std::string& expected) {
  const auto value = reader.number(key, Need::required, expected);
  if (!value) return 0.0;
  const bool ok = *value > low && (high_inclusive ? *value <= high : *value < high);
  reader.require(ok, key, "is out of range: " + model::format_number(*value), expected);
  return *value;
}

double elevation(MapReader& reader, const std::string& key, const std::string& expected) {
  const auto value = reader.number(key, Need::required, expected);
  if (!value) return 0.0;
  reader.require(*value >= -90 && *value <= 90, key,
                 "is out of range: " + model::format_number(*value), expected);
  return *value;
}

std::optional<double> share(MapReader& reader, const std::string& key, Need need,
                            const std::string& expected) {
  const auto value = reader.number(key, need, expected);
  if (!value) return std::nullopt;
  const bool ok = *value >= 0 && *value <= 1;
  reader.require(ok, key, "is out of range: " + model::format_number(*value), expected);
  return ok ? value : std::nullopt;
}

model::Basis basis(MapReader& reader, Need need) {
  return named_value(reader, "basis", need, model::kBasisNames).value_or(model::Basis::estimate);
}

std::string ros_name(MapReader& reader, const std::string& key, const std::string& what) {
  const std::string expected =
      what +
      ": letters, digits and underscores, not starting with a digit (a ROS name, so "
      "that URDF links, nav2 sources and filter nodes can be named after it)";
  const std::optional<std::string> text = reader.text(key, Need::required, expected);
  if (!text) return "";  // missing or not a scalar: text() reported it
  const std::string& name = *text;
  const bool valid = !name.empty() && !std::isdigit(static_cast<unsigned char>(name.front())) &&
                     std::all_of(name.begin(), name.end(), [](char c) {
                       return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                     });
  reader.require(valid, key, "'" + name + "' is not a ROS name", expected);
  return name;
}

std::string topic_name(MapReader& reader, const std::string& key, Need need,
                       const std::string& what) {
  const std::string expected =
      what + ": a ROS topic, tokens of letters, digits and underscores joined by '/'";
  const std::optional<std::string> text = reader.text(key, need, expected);
  if (!text) return "";
  const bool valid = model::is_topic_name(*text);
  reader.require(valid, key, "'" + *text + "' is not a ROS topic name", expected);
  return valid ? *text : "";
}

std::string frame_id(MapReader& reader, const std::string& key, Need need,
                     const std::string& what) {
  const std::string expected =
      what + ": a TF frame id, printable ASCII without spaces or quotes, not starting with '/'";
  const std::optional<std::string> text = reader.text(key, need, expected);
  if (!text) return "";
  const bool valid = model::is_frame_id(*text);
  reader.require(valid, key, "'" + *text + "' is not a TF frame id", expected);
  return valid ? *text : "";
}

model::Pose3 xyz_rpy_deg_pose(MapReader& pose, Need xyz_need) {
  const std::string metres = "[x, y, z] in metres, finite";
  const auto xyz = pose.numbers(
      "xyz", xyz_need, 3, 3, xyz_need == Need::required ? metres : metres + " (default [0, 0, 0])");
  const auto rpy = pose.numbers("rpy_deg", Need::optional, 3, 3,
                                "[roll, pitch, yaw] in degrees, finite (default [0, 0, 0])");
  const model::Vec3 position =
      xyz ? model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]) : model::Vec3::Zero();
  pose.require(position.cwiseAbs().maxCoeff() <= model::kMaxCoordinate, "xyz",
               "places the sensor beyond +-1e8 m", metres + ", within +-1e8 m");
  if (rpy) warn_if_radians(pose, "rpy_deg", *rpy);
  model::Vec3 angles = model::Vec3::Zero();
  if (rpy) {
    angles = model::Vec3(model::deg_to_rad((*rpy)[0]), model::deg_to_rad((*rpy)[1]),
                         model::deg_to_rad((*rpy)[2]));
  }
  return model::pose_from_xyz_rpy(position, angles);
}

void warn_if_radians(MapReader& reader, const std::string& key,
                     const std::vector<double>& degrees) {
  constexpr double kHalfTurnRad = 3.141592653589793;
  const bool within_half_turn = std::all_of(degrees.begin(), degrees.end(),
                                            [&](double v) { return std::abs(v) <= kHalfTurnRad; });
  const bool fractional =
      std::any_of(degrees.begin(), degrees.end(), [](double v) { return v != std::round(v); });
  if (!within_half_turn || !fractional) return;
  std::string in_degrees;
  for (const double v : degrees) {
    in_degrees += (in_degrees.empty() ? "[" : ", ") + model::format_number(model::rad_to_deg(v), 4);
  }
  reader.diagnostics().warning(
      reader.location(key), reader.field(key),
      "looks like radians: every angle lies within +-pi and not all are whole degrees",
      "degrees (read as radians these would be " + in_degrees + "] deg)");
}

model::PoseTolerance pose_tolerance(MapReader& tolerance) {
  model::PoseTolerance result;
  result.where = tolerance.location();
  const auto half_widths = [&](const std::string& key, const std::string& unit) {
    const auto values = tolerance.numbers(key, Need::optional, 3, 3,
                                          "three half-widths in " + unit + ", >= 0, finite");
    if (values) {
      tolerance.require(
          std::all_of(values->begin(), values->end(), [](double v) { return v >= 0; }), key,
          "has a negative half-width", "half-widths >= 0 (the box is +-)");
    }
    return values;
  };
  if (const auto xyz = half_widths("xyz", "metres")) {
    result.xyz = model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
    if (result.xyz.maxCoeff() > 0.1) {
      tolerance.diagnostics().warning(
          tolerance.location("xyz"), tolerance.field("xyz"),
          "allows a mount to sit more than 0.1 m from its pose: millimetres typed as metres?",
          "metres (5 mm is 0.005)");
    }
  }
  if (const auto rpy = half_widths("rpy_deg", "degrees")) {
    if (*std::max_element(rpy->begin(), rpy->end()) > 10.0) {
      tolerance.diagnostics().warning(tolerance.location("rpy_deg"), tolerance.field("rpy_deg"),
                                      "allows more than 10 deg of rotation: not a mounting error",
                                      "degrees of bracket or calibration error, e.g. [1, 1, 1]");
    }
    result.rpy = model::Vec3(model::deg_to_rad((*rpy)[0]), model::deg_to_rad((*rpy)[1]),
                             model::deg_to_rad((*rpy)[2]));
  }
  tolerance.reject_unknown_keys();
  return result;
}

model::RigSupport support_solid(MapReader& reader) {
  // [m] the largest support that is plausibly metres: a mast as tall as a room.
  constexpr double kLargestSupport = 5.0;
  model::RigSupport support;
  support.where = reader.location();
  support.solid = solid_shape(reader, kLargestSupport);
  if (auto pose = reader.map("pose", Need::required, "a map with xyz and rpy_deg")) {
    support.T_robot_support = xyz_rpy_deg_pose(*pose, Need::required);
    pose->reject_unknown_keys();
  }
  if (reader.has("price_usd"))
    support.price = non_negative(reader, "price_usd", Need::required, "US dollars, >= 0");
  reader.text("note", Need::optional);
  return support;
}

model::HousingSolid solid_shape(MapReader& reader, double largest) {
  model::HousingSolid solid;
  solid.where = reader.location();
  if (const auto shape = named_value(reader, "shape", Need::required, model::kHousingShapeNames))
    solid.shape = *shape;
  if (solid.shape == model::HousingShape::box) {
    const auto size =
        reader.numbers("size", Need::required, 3, 3, "[x, y, z] full lengths in metres, each > 0");
    const bool positive = size && std::all_of(size->begin(), size->end(), [](double v) {
                            return v > 0.0 && v <= model::kMaxCoordinate;
                          });
    reader.require(!size || positive, "size", "has a length that is not positive",
                   "[x, y, z] full lengths in metres, each > 0");
    if (size && positive) solid.size = model::Vec3((*size)[0], (*size)[1], (*size)[2]);
  } else {
    const double radius = positive_length(reader, "radius", Need::required, "metres, > 0");
    const double height = positive_length(reader, "height", Need::required, "metres, > 0");
    solid.size = model::Vec3(2 * radius, 2 * radius, height);
  }
  if (solid.size.maxCoeff() > largest) {
    const std::string key = solid.shape == model::HousingShape::box ? "size" : "radius";
    reader.diagnostics().warning(reader.location(key), reader.field(key),
                                 "makes the solid over " + model::format_number(largest) +
                                     " m: millimetres typed as metres?",
                                 "metres (a D435 is [0.025, 0.09, 0.025])");
  }
  return solid;
}

}  // namespace rigdesign::io
