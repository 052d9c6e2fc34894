#include "rigdesign/io/config/catalog_loader.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "io/config/placement_fields.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/filtering_loads_io.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"

namespace rigdesign::io {
namespace {

using io::MapReader;
using io::Need;

std::vector<std::string> read_names(MapReader& reader, const std::string& key,
                                    const std::string& expected) {
  std::vector<std::string> names;
  const YAML::Node list = reader.node(key);
  if (!list.IsSequence() || list.size() == 0) {
    reader.require(false, key, list.IsSequence() ? "is empty" : "is not a list", expected);
    return names;
  }
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].IsScalar()) {
      reader.diagnostics().error(io::location_of(list[i], reader.file()),
                                 reader.field(key) + "[" + std::to_string(i) + "]", "is not a name",
                                 expected);
      continue;
    }
    names.push_back(list[i].Scalar());
  }
  return names;
}

model::PricedCapacity read_priced(MapReader& reader, const std::string& capacity_key,
                                  const std::string& capacity_expected) {
  model::PricedCapacity item;
  item.where = reader.location();
  item.id = reader.text("id", Need::required, "an id").value_or("");
  item.capacity = io::positive(reader, capacity_key, Need::required, capacity_expected);
  item.price = io::non_negative(reader, "price_usd", Need::required, "US dollars, >= 0");
  reader.text("note", Need::optional);
  reader.reject_unknown_keys();
  return item;
}

/// The components of one transfer kind: a list (one bought for the rig), or a map
/// `{per_sensor: true, components: [...]}` for a kind every sensor needs its own of (eq. 4's
/// cables and ports: one per sensor, each carrying that sensor's bandwidth).
void read_transfer_kind(MapReader& kinds, const std::string& kind, const YAML::Node& value,
                        model::Catalog& catalog) {
  const std::string list_expected = "a list of " + kind + " components";
  std::vector<MapReader> items;
  bool per_sensor = false;
  if (value.IsMap()) {
    auto form = kinds.map(kind, Need::required,
                          "{per_sensor: true or false, components: " + list_expected + "}");
    if (!form) return;
    per_sensor = form->boolean("per_sensor", Need::required).value_or(false);
    items = form->maps("components", Need::required, list_expected);
    form->require(!items.empty(), "components", "is empty", "at least one component of the kind");
    form->reject_unknown_keys();
  } else {
    items = kinds.maps(kind, Need::required, list_expected);
    kinds.require(!items.empty(), kind, "is empty", "at least one component of the kind");
  }
  for (MapReader reader : items) {
    model::PricedCapacity item = read_priced(reader, "capacity_bps", "bits per second, > 0");
    item.kind = kind;
    item.per_sensor = per_sensor;
    catalog.transfer.push_back(std::move(item));
  }
}

/// `transfer:` as paper 1's eq. 4 has it, a map of component kinds (cable, switch, interface
/// ...) each with its items, one of each bought (or one per sensor); or a flat list, read as
/// one kind.
void read_transfer(MapReader& top, model::Catalog& catalog) {
  const std::string expected =
      "a list of transfer hardware, or a map from component kind (cable, switch, interface) "
      "to such a list";
  const YAML::Node node = top.node("transfer");
  if (node.IsMap()) {
    auto kinds = top.map("transfer", Need::required, expected);
    if (!kinds) return;
    for (const auto& entry : node)
      read_transfer_kind(*kinds, entry.first.Scalar(), entry.second, catalog);
    return;
  }
  for (MapReader& reader : top.maps("transfer", Need::required, expected))
    catalog.transfer.push_back(read_priced(reader, "capacity_bps", "bits per second, > 0"));
}

/// The measured loads file named by `filtering_loads` (relative to the catalog), if any.
std::optional<model::FilteringLoads> read_measured_loads(MapReader& top,
                                                         const std::string& catalog_path) {
  const std::optional<std::string> name = top.text("filtering_loads", Need::optional);
  if (!name) return std::nullopt;
  const std::filesystem::path resolved = std::filesystem::path(catalog_path).parent_path() / *name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(resolved, error)) {
    throw model::InputError(model::Diagnostic{
        top.location("filtering_loads"), top.field("filtering_loads"),
        "'" + resolved.string() + "' does not exist",
        "a file written by `rigdesign filter --write-loads`, relative to the catalog"});
  }
  return load_filtering_loads(resolved.string());
}

}  // namespace

model::Catalog load_catalog(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top = read_document_map(path, diagnostics,
                                    "a catalog: name, body, distance_of_interest, sensors, slots, "
                                    "transfer, cpus");
  model::Catalog catalog;
  catalog.file = path;
  catalog.where = top.location();
  catalog.name = top.text("name", Need::required, "the catalog's name").value_or("");
  catalog.sensor_library = top.text("sensor_library", Need::optional).value_or("");
  catalog.sensor_library_where = top.location("sensor_library");
  // As a rig: with a robot description the body is its collision geometry unless `body` is
  // given, and the search sees the same shadows check and export see.
  const std::optional<RobotLinks> urdf = read_described_robot(top, path, catalog).links;
  catalog.reference_machine =
      top.text("reference_machine", Need::required, "what a CPU core-equivalent means")
          .value_or("");
  catalog.filtering_seconds_per_point =
      io::non_negative(top, "filtering_seconds_per_point", Need::required,
                       "core-seconds of point filtering per delivered point, >= 0");
  const std::optional<model::FilteringLoads> measured = read_measured_loads(top, path);

  std::set<std::string> seen;
  for (MapReader& reader : top.maps("sensors", Need::required, "a list of candidate sensors")) {
    model::CandidateSensor candidate;
    candidate.where = reader.location();
    candidate.sensor_id = reader.text("sensor", Need::required, "a sensor id").value_or("");
    candidate.mode_ids = read_names(reader, "modes", "a non-empty list of mode ids");
    if (reader.has("filtering_seconds_per_point")) {
      candidate.filtering_seconds_per_point = io::non_negative(
          reader, "filtering_seconds_per_point", Need::required, "core-seconds per point, >= 0");
    }
    const model::FilteringLoad* load = measured ? measured->find(candidate.sensor_id) : nullptr;
    if (!candidate.filtering_seconds_per_point && load != nullptr) {
      candidate.filtering_seconds_per_point = load->seconds_per_point;
    }
    reader.reject_unknown_keys();
    if (!candidate.sensor_id.empty() && !seen.insert(candidate.sensor_id).second) {
      reader.require(false, "sensor", "lists '" + candidate.sensor_id + "' twice",
                     "each candidate sensor once, with all its modes");
    }
    catalog.sensors.push_back(std::move(candidate));
  }
  top.require(!catalog.sensors.empty() || !top.has("sensors"), "sensors", "is empty",
              "at least one candidate sensor");

  std::set<std::string> slot_ids;
  for (MapReader& reader : top.maps("slots", Need::required, "a list of mounting slots")) {
    model::MountingSlot slot;
    slot.where = reader.location();
    slot.id = io::ros_name(reader, "id", "a slot id (the chosen rig's mount id)");
    if (auto pose = reader.map("pose", Need::required,
                               "a map with xyz and rpy_deg (numbers or ranges), or urdf_link")) {
      slot.poses = io::read_pose_set(*pose, urdf, catalog.body.parts, slot.ranges);
      for (model::SlotPose& candidate : slot.poses) {
        const io::MountLink link{candidate.urdf_link, candidate.urdf_link_optical,
                                 candidate.housing_link};
        candidate.housing_link = io::read_housing(*pose, link, catalog, urdf && !urdf->failed);
      }
    }
    slot.allowed_sensors = read_names(reader, "allows", "a non-empty list of candidate sensor ids");
    if (reader.has("distance_of_interest")) {
      slot.distance_of_interest =
          io::positive(reader, "distance_of_interest", Need::required, "metres, > 0");
    }
    if (const auto seat = named_value(reader, "seat", Need::optional, model::kHousingSeatNames))
      slot.seat = *seat;
    if (reader.has("recessed"))
      slot.recessed = reader.boolean("recessed", Need::required).value_or(false);
    if (auto support = reader.map("support", Need::optional,
                                  "a map with shape, size | radius and height, pose, price_usd")) {
      const std::string id =
          support->has("id") ? io::ros_name(*support, "id", "a support id") : slot.id + "_support";
      slot.support = io::support_solid(*support);
      slot.support->id = id;
      support->reject_unknown_keys();
    }
    reader.text("note", Need::optional);
    reader.reject_unknown_keys();
    if (!slot.id.empty() && !slot_ids.insert(slot.id).second) {
      reader.require(false, "id", "duplicate slot id '" + slot.id + "'", "unique slot ids");
    }
    catalog.slots.push_back(std::move(slot));
  }
  top.require(!catalog.slots.empty() || !top.has("slots"), "slots", "is empty",
              "at least one mounting slot");
  read_transfer(top, catalog);
  for (MapReader& reader : top.maps("cpus", Need::required, "a list of CPUs")) {
    catalog.cpus.push_back(
        read_priced(reader, "cores", "core-equivalents of the reference machine, > 0"));
  }
  top.require(!catalog.transfer.empty() || !top.has("transfer"), "transfer", "is empty",
              "at least one transfer option");
  top.require(!catalog.cpus.empty() || !top.has("cpus"), "cpus", "is empty", "at least one CPU");
  top.text("note", Need::optional);
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return catalog;
}

model::Diagnostics check_catalog_references(const model::Catalog& catalog,
                                            const model::SensorLibrary& library) {
  model::Diagnostics diagnostics;
  std::set<std::string> candidates;
  for (std::size_t i = 0; i < catalog.sensors.size(); ++i) {
    const model::CandidateSensor& candidate = catalog.sensors[i];
    const std::string field = "sensors[" + std::to_string(i) + "]";
    const model::Sensor* sensor = library.find(candidate.sensor_id);
    if (sensor == nullptr) {
      diagnostics.error(candidate.where, field + ".sensor",
                        "unknown sensor '" + candidate.sensor_id + "' in " + library.file,
                        "a sensor id of the library");
      continue;
    }
    candidates.insert(candidate.sensor_id);
    for (const std::string& mode : candidate.mode_ids) {
      if (sensor->find_mode(mode) == nullptr) {
        std::string modes;
        for (const model::SensorMode& m : sensor->modes)
          modes += (modes.empty() ? "" : ", ") + m.id;
        diagnostics.error(candidate.where, field + ".modes",
                          "unknown mode '" + mode + "' of sensor '" + sensor->id + "'",
                          "one of: " + modes);
      }
    }
  }
  for (std::size_t i = 0; i < catalog.slots.size(); ++i) {
    const model::MountingSlot& slot = catalog.slots[i];
    const std::string field = "slots[" + std::to_string(i) + "].allows";
    bool allows_any = false;
    for (const std::string& sensor : slot.allowed_sensors) {
      if (candidates.count(sensor) != 0) {
        allows_any = true;
      } else if (library.find(sensor) != nullptr) {
        diagnostics.error(slot.where, field, "names '" + sensor + "', which is not a candidate",
                          "sensor ids listed under the catalog's `sensors`");
      } else {
        diagnostics.error(slot.where, field, "names unknown sensor '" + sensor + "'",
                          "sensor ids listed under the catalog's `sensors`");
      }
    }
    if (!allows_any && !slot.allowed_sensors.empty()) {
      diagnostics.error(slot.where, field, "slot '" + slot.id + "' allows no candidate sensor",
                        "at least one candidate sensor id");
    }
  }
  return diagnostics;
}

}  // namespace rigdesign::io
