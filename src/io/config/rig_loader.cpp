#include "rigdesign/io/config/rig_loader.hpp"

#include <cmath>
#include <set>

#include "io/config/placement_fields.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::io {
namespace {

using io::MapReader;
using io::Need;
using io::read_body;
using io::read_pose;
using io::read_robot_links;
using io::RobotLinks;

model::Mount read_mount(MapReader& reader, const std::optional<RobotLinks>& robot,
                        const model::DescribedRobot& described) {
  model::Mount mount;
  mount.where = reader.location();
  mount.id = io::ros_name(reader, "id", "a mount id, unique in the rig");
  mount.sensor_id =
      reader.text("sensor", Need::required, "a sensor id from sensors.yaml").value_or("");
  mount.sensor_where = reader.location("sensor");
  mount.mode_id = reader.text("mode", Need::required, "a mode id of that sensor").value_or("");
  mount.mode_where = reader.location("mode");
  mount.pose_where = reader.location("pose");
  if (auto pose = reader.map("pose", Need::required, "a map with xyz and rpy_deg, or urdf_link")) {
    io::MountLink link;
    mount.T_robot_sensor = read_pose(*pose, robot, &link);
    mount.urdf_link = link.name;
    mount.urdf_link_optical = link.optical;
    mount.housing_link = io::read_housing(*pose, link, described, robot && !robot->failed);
  }
  if (reader.has("distance_of_interest")) {
    mount.distance_of_interest =
        io::positive_length(reader, "distance_of_interest", Need::required, "metres, > 0");
  }
  if (reader.has("recessed"))
    mount.recessed = reader.boolean("recessed", Need::required).value_or(false);
  if (reader.has("throttle_hz")) {
    mount.throttle_where = reader.location("throttle_hz");
    mount.throttle_hz = io::positive(reader, "throttle_hz", Need::required,
                                     "frames per second the stack passes on [Hz], > 0");
  }
  if (auto ros = reader.map("ros", Need::optional, "a map with namespace, topic, frame")) {
    if (ros->has("namespace"))
      mount.ros_namespace = io::ros_name(*ros, "namespace", "the driver's namespace");
    mount.ros_topic =
        io::topic_name(*ros, "topic", Need::optional, "the data's topic, e.g. /front/points");
    ros->require(mount.ros_topic.empty() || mount.ros_topic.front() == '/', "topic", "is relative",
                 "an absolute topic, starting with '/'");
    mount.ros_frame =
        io::frame_id(*ros, "frame", Need::optional, "the frame the data is stamped with");
    ros->reject_unknown_keys();
  }
  if (auto tolerance = reader.map("tolerance", Need::optional,
                                  "a map with xyz [m] and rpy_deg [deg] half-widths"))
    mount.tolerance = io::pose_tolerance(*tolerance);
  if (auto crosstalk = reader.map("crosstalk", Need::optional,
                                  "a map with sync (a group name), delay_us, channel")) {
    model::CrosstalkMitigation mitigation;
    mitigation.where = crosstalk->location();
    mitigation.sync_group =
        crosstalk->text("sync", Need::optional, "a sync group's name").value_or("");
    if (const auto delay = crosstalk->number("delay_us", Need::optional,
                                             "the capture offset in microseconds, >= 0")) {
      crosstalk->require(*delay >= 0 && *delay <= 1e6, "delay_us", "is outside 0..1e6",
                         "the capture offset in microseconds, 0..1e6");
      crosstalk->require(!mitigation.sync_group.empty(), "delay_us", "is given without sync",
                         "a delay within a sync group: give `sync` too");
      mitigation.delay = *delay * 1e-6;
    }
    mitigation.channel =
        crosstalk->integer("channel", Need::optional, "a modulation channel number");
    crosstalk->require(!mitigation.sync_group.empty() || mitigation.channel.has_value(), "sync",
                       "is missing, and so is channel", "sync (with delay_us) or channel");
    crosstalk->reject_unknown_keys();
    mount.crosstalk = mitigation;
  }
  reader.text("note", Need::optional);
  reader.reject_unknown_keys();
  return mount;
}

// `{id, shape: box, size, pose}` or `{id, shape: cylinder, radius, height, pose}`, with an
// optional `price_usd`: a mast, bracket or plate holding sensors (issue 52 item 3), centred on
// its pose.
model::RigSupport read_support(MapReader& reader) {
  const std::string id = io::ros_name(reader, "id", "a support id");
  model::RigSupport support = io::support_solid(reader);
  support.id = id;
  reader.reject_unknown_keys();
  return support;
}

constexpr const char* kRigDocument = "a rig: a map with name, body, distance_of_interest, mounts";

model::Rig read_rig(MapReader& top, const std::string& path, model::Diagnostics& diagnostics,
                    const DescriptionReader& read_description) {
  model::Rig rig;
  rig.file = path;
  rig.where = top.location();
  rig.name = top.text("name", Need::required, "the rig's name").value_or("");
  rig.sensor_library = top.text("sensor_library", Need::optional).value_or("");
  rig.sensor_library_where = top.location("sensor_library");
  rig.requirements = top.text("requirements", Need::optional).value_or("");
  rig.requirements_where = top.location("requirements");
  const DescribedRobotFields described = read_described_robot(top, path, rig, read_description);
  const std::optional<RobotLinks>& robot = described.links;
  if (top.has("body")) {
    rig.body.where = top.location("body");
  } else if (described.body_from_description) {
    rig.body.where = top.location("robot");
  }
  if (auto tolerance =
          top.map("tolerance", Need::optional, "a map with xyz [m] and rpy_deg [deg] half-widths"))
    rig.tolerance = io::pose_tolerance(*tolerance);
  for (MapReader& reader : top.maps("supports", Need::optional,
                                    "a list of {id, shape, size | radius and height, pose}")) {
    rig.supports.push_back(read_support(reader));
  }
  std::set<std::string> ids;
  for (MapReader& reader : top.maps("mounts", Need::required, "a list of mounts")) {
    model::Mount mount = read_mount(reader, robot, rig);
    if (!mount.id.empty() && !ids.insert(mount.id).second) {
      reader.require(false, "id", "duplicate mount id '" + mount.id + "'", "unique mount ids");
    }
    rig.mounts.push_back(std::move(mount));
  }
  top.require(!rig.mounts.empty() || !top.has("mounts"), "mounts", "is empty",
              "at least one mounted sensor");
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  for (const model::Diagnostic& diagnostic : diagnostics.items()) {
    if (diagnostic.severity == model::Severity::warning) rig.load_warnings.push_back(diagnostic);
  }
  return rig;
}

}  // namespace

model::Rig load_rig(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(path, diagnostics, kRigDocument);
  return read_rig(top, path, diagnostics, {});
}

model::Rig load_rig_text(const std::string& text, const std::string& path,
                         const DescriptionReader& read_description) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(parse_yaml_text(text, path), path, diagnostics, kRigDocument);
  return read_rig(top, path, diagnostics, read_description);
}

}  // namespace rigdesign::io
