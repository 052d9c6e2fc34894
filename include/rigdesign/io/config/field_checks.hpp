#pragma once
// Range-checked reads shared by the loaders: each reads one field and records a finding
// when it is outside its allowed range. They return a harmless value (0) when the field is
// absent or invalid so that loading carries on and reports every problem at once.
#include <optional>
#include <string>
#include <vector>

#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/eigen_types.hpp"
#include "rigdesign/model/housing_solid.hpp"
#include "rigdesign/model/rig.hpp"
#include "rigdesign/model/sensor.hpp"

namespace rigdesign::io {

/// A number > 0.
/// Sets `value` from `key` when the file has it; leaves the caller's default otherwise.
void read_if_present(MapReader& reader, const std::string& key, double& value,
                     const std::string& expected);
void read_if_present(MapReader& reader, const std::string& key, int& value,
                     const std::string& expected);
void read_if_present(MapReader& reader, const std::string& key, bool& value);

double positive(MapReader& reader, const std::string& key, Need need, const std::string& expected);
/// A length in metres: positive and within the +-1e8 m every coordinate keeps (a body of
/// 1e300 m would overflow every area computed with it). 0 after recording an error.
double positive_length(MapReader& reader, const std::string& key, Need need,
                       const std::string& expected);
/// A number >= 0.
double non_negative(MapReader& reader, const std::string& key, Need need,
                    const std::string& expected);
/// A number in [low, high] (or (low, high] / (low, high) as `high_inclusive` says; low excluded).
double angle_in(MapReader& reader, const std::string& key, double low, double high,
                bool high_inclusive, const std::string& expected);
/// An elevation angle in degrees in [-90, 90].
double elevation(MapReader& reader, const std::string& key, const std::string& expected);
/// A share in [0, 1].
std::optional<double> share(MapReader& reader, const std::string& key, Need need,
                            const std::string& expected);
/// A name every exported format can carry unquoted and unescaped (URDF link and joint names,
/// nav2 source keys, ROS node names): a ROS name token, letters, digits and underscores, not
/// starting with a digit. Records an error at `key` otherwise; "" when absent.
std::string ros_name(MapReader& reader, const std::string& key, const std::string& what);
/// A ROS topic name (model::is_topic_name) or a TF frame id (model::is_frame_id); records an
/// error at `key` otherwise; "" when absent or bad.
std::string topic_name(MapReader& reader, const std::string& key, Need need,
                       const std::string& what);
std::string frame_id(MapReader& reader, const std::string& key, Need need, const std::string& what);
/// The transform a pose map's `xyz` [m] and `rpy_deg` [deg] give (URDF's roll-pitch-yaw);
/// `xyz_need` says whether xyz may be left out (then [0, 0, 0]); rpy_deg always may. Other
/// keys are left for the caller to read or reject.
model::Pose3 xyz_rpy_deg_pose(MapReader& pose, Need xyz_need);
/// Warns at `key` (a list of angles in degrees) when the values look like radians typed into
/// a degrees field: all within +-pi and some not a whole number of degrees. A warning, not an
/// error: a tilt of 2.5 deg is possible, just rare beside whole-degree mounts.
void warn_if_radians(MapReader& reader, const std::string& key, const std::vector<double>& degrees);
/// A mounting tolerance map, `{xyz: [m, m, m], rpy_deg: [deg, deg, deg]}` (half-widths >= 0,
/// either may be left out). Warns where a value is probably in another unit: a translation over
/// 0.1 m (millimetres typed as metres?) or a rotation over 10 deg (not a mounting error).
model::PoseTolerance pose_tolerance(MapReader& tolerance);
/// A simple solid's shape and size: `shape: box` with `size: [x, y, z]`, or `shape: cylinder`
/// with `radius` and `height` (axis z), metres; the centre is left at 0 for the caller. Warns
/// when it is over `largest` [m] (millimetres typed as metres?).
model::HousingSolid solid_shape(MapReader& reader, double largest);
/// A support (issue 52 item 3) after its id: `shape` with its size (solid_shape), `pose`
/// (xyz, rpy_deg: the solid's centre) and an optional `price_usd`; warns above 5 m.
model::RigSupport support_solid(MapReader& reader);
/// `basis: datasheet | measured | estimate`.
model::Basis basis(MapReader& reader, Need need);

/// A scalar that must be one of `table`'s names; its value.
template <typename Enum, std::size_t N>
std::optional<Enum> named_value(MapReader& reader, const std::string& key, Need need,
                                const model::NameTable<Enum, N>& table) {
  const auto index = reader.choice(key, need, model::names_of(table));
  return index ? std::optional<Enum>(table[*index].first) : std::nullopt;
}

}  // namespace rigdesign::io
