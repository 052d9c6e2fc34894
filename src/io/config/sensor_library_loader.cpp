#include "rigdesign/io/config/sensor_library_loader.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "io/config/fov_readers.hpp"
#include "rigdesign/io/config/field_checks.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::io {
namespace {

using io::MapReader;
using io::Need;

const std::vector<std::string> kModeKeys = {"id",
                                            "fov",
                                            "range",
                                            "frequency",
                                            "pixels",
                                            "angular_resolution_deg",
                                            "points_per_frame",
                                            "bytes_per_frame",
                                            "bytes_per_point",
                                            "bytes_per_second",
                                            "noise",
                                            "light",
                                            "driver_cpu",
                                            "emitter",
                                            "fov_spread_deg",
                                            "depth_matching",
                                            "note"};

const std::vector<std::string> kMitigations = {"sync", "delay", "phase_lock", "channels",
                                               "emitter_off"};

// A mode's field comes from the mode itself, else from the sensor's `mode_defaults`.
MapReader& source_of(const std::string& key, MapReader& mode, std::optional<MapReader>& defaults) {
  if (mode.has(key) || !defaults || !defaults->has(key)) return mode;
  return *defaults;
}

// Angular resolution and points per frame: from a pixel grid, or given for scanners.
void read_sampling(model::SensorMode& mode, MapReader& reader, std::optional<MapReader>& defaults) {
  const bool planar = mode.fov.shape().is_planar_scan();
  MapReader& pixels_from = source_of("pixels", reader, defaults);
  MapReader& resolution_from = source_of("angular_resolution_deg", reader, defaults);
  const bool has_pixels = pixels_from.has("pixels");
  const bool has_resolution = resolution_from.has("angular_resolution_deg");
  if (has_pixels && has_resolution) {
    reader.require(false, "angular_resolution_deg", "given together with pixels",
                   "either pixels (resolution derived as FOV / pixels) or "
                   "angular_resolution_deg, not both");
  }
  if (has_pixels && !planar) {
    const auto grid = pixels_from.numbers("pixels", Need::required, 2, 2,
                                          "[width, height] in pixels, both positive");
    if (grid && (*grid)[0] >= 1 && (*grid)[1] >= 1) {
      mode.angular_resolution_h = mode.fov.horizontal() / (*grid)[0];
      mode.angular_resolution_v = mode.fov.vertical() / (*grid)[1];
      mode.points_per_frame = (*grid)[0] * (*grid)[1];
    } else if (grid) {
      pixels_from.require(false, "pixels", "has a count below 1",
                          "[width, height] in pixels, both positive");
    }
  } else {
    const std::size_t count = planar ? 1 : 2;
    const std::string expected =
        planar ? "[horizontal] in degrees, positive (a 2D scanner has one row)"
               : "[horizontal, vertical] in degrees, both positive";
    const auto resolution =
        resolution_from.numbers("angular_resolution_deg", Need::required, count, count, expected);
    if (resolution) {
      const bool positive = (*resolution)[0] > 0 && (count == 1 || (*resolution)[1] > 0);
      resolution_from.require(positive, "angular_resolution_deg", "has a value <= 0", expected);
      mode.angular_resolution_h = model::deg_to_rad((*resolution)[0]);
      if (count == 2) mode.angular_resolution_v = model::deg_to_rad((*resolution)[1]);
    }
  }
  MapReader& points_from = source_of("points_per_frame", reader, defaults);
  if (has_pixels && !planar) {
    reader.require(!points_from.has("points_per_frame"), "points_per_frame",
                   "given together with pixels", "points_per_frame only for scanners");
    return;
  }
  mode.points_per_frame = io::positive(points_from, "points_per_frame", Need::required,
                                       "a positive number of points per frame");
}

void read_bytes(model::SensorMode& mode, MapReader& reader, std::optional<MapReader>& defaults) {
  const std::vector<std::string> keys = {"bytes_per_frame", "bytes_per_point", "bytes_per_second"};
  const std::string expected = "exactly one of bytes_per_frame, bytes_per_point, bytes_per_second";
  int given = 0;
  for (const std::string& key : keys) given += source_of(key, reader, defaults).has(key) ? 1 : 0;
  if (given != 1) {
    reader.require(false, "bytes_per_frame", given == 0 ? "missing" : "data size given twice",
                   expected);
    return;
  }
  MapReader& frame = source_of("bytes_per_frame", reader, defaults);
  MapReader& point = source_of("bytes_per_point", reader, defaults);
  MapReader& second = source_of("bytes_per_second", reader, defaults);
  if (frame.has("bytes_per_frame")) {
    mode.bytes_per_frame = io::positive(frame, "bytes_per_frame", Need::required, "bytes, > 0");
  } else if (point.has("bytes_per_point")) {
    mode.bytes_per_frame = io::positive(point, "bytes_per_point", Need::required, "bytes, > 0") *
                           mode.points_per_frame;
  } else if (mode.frequency > 0) {
    mode.bytes_per_frame =
        io::positive(second, "bytes_per_second", Need::required, "bytes per second, > 0") /
        mode.frequency;
  }
}

model::NoiseModel read_noise(MapReader& noise) {
  model::NoiseModel model;
  const std::string expected = "sigma(d) = a + b*d + c*d^2 with a [m], b [-], c [1/m], each >= 0";
  model.a = io::non_negative(noise, "a", Need::optional, expected);
  model.b = io::non_negative(noise, "b", Need::optional, expected);
  model.c = io::non_negative(noise, "c", Need::optional, expected);
  noise.require(noise.has("a") || noise.has("b") || noise.has("c"), "a", "no coefficient given",
                expected);
  noise.text("basis", Need::optional);
  noise.text("note", Need::optional);
  noise.reject_unknown_keys();
  return model;
}

model::LightImmunity read_light(MapReader& light) {
  model::LightImmunity immunity;
  immunity.dark = light.boolean("dark", Need::required).value_or(false);
  immunity.indoor = light.boolean("indoor", Need::required).value_or(false);
  immunity.sunlight = light.boolean("sunlight", Need::required).value_or(false);
  light.text("note", Need::optional);
  light.reject_unknown_keys();
  return immunity;
}

model::DriverCpuLoad read_driver_cpu(MapReader& cpu) {
  model::DriverCpuLoad load;
  load.cores = io::non_negative(cpu, "cores", Need::required,
                                "core-equivalents of the reference machine, >= 0");
  load.seconds_per_point = io::non_negative(cpu, "seconds_per_point", Need::optional,
                                            "core-seconds per delivered point, >= 0");
  load.basis = io::basis(cpu, Need::required);
  load.note = cpu.text("note", Need::optional).value_or("");
  cpu.reject_unknown_keys();
  return load;
}

// `emitter: none` (a passive sensor) or its light and crosstalk facts (issue 38).
std::optional<model::Emitter> read_emitter(MapReader& reader) {
  const YAML::Node node = reader.node("emitter");
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  const std::string expected =
      "`none`, or a map {wavelength_nm, modulation, interferes: true|false|unknown, mitigation: "
      "[sync, delay, phase_lock, channels, emitter_off], min_delay_us, source}";
  if (node.IsScalar()) {
    reader.require(node.Scalar() == "none", "emitter", "is not `none` or a map", expected);
    return std::nullopt;
  }
  auto map = reader.map("emitter", Need::required, expected);
  if (!map) return std::nullopt;
  model::Emitter emitter;
  emitter.where = map->location();
  if (const auto nm = map->number("wavelength_nm", Need::optional, "nanometres, 300..2000")) {
    map->require(*nm >= 300 && *nm <= 2000, "wavelength_nm", "is outside 300..2000",
                 "nanometres, 300..2000 (a near-infrared emitter is 780..1600)");
    emitter.wavelength = *nm * 1e-9;
  }
  emitter.modulation = map->text("modulation", Need::required,
                                 "how the light is sent: pulsed ToF, AMCW ToF, dot pattern ...")
                           .value_or("");
  if (const auto crosstalk =
          map->choice("interferes", Need::required, {"unknown", "true", "false"})) {
    emitter.crosstalk = *crosstalk == 1   ? model::Crosstalk::interferes
                        : *crosstalk == 2 ? model::Crosstalk::immune
                                          : model::Crosstalk::unknown;
  }
  const YAML::Node list = map->node("mitigation");
  if (list.IsDefined() && !list.IsNull()) {
    const bool ok =
        list.IsSequence() && std::all_of(list.begin(), list.end(), [](const YAML::Node& n) {
          return n.IsScalar() && std::find(kMitigations.begin(), kMitigations.end(), n.Scalar()) !=
                                     kMitigations.end();
        });
    map->require(ok, "mitigation", "is not a list of known measures",
                 "a list of sync, delay, phase_lock, channels, emitter_off");
    if (ok)
      for (const YAML::Node& item : list) emitter.mitigation.push_back(item.Scalar());
  }
  if (const auto delay = map->number("min_delay_us", Need::optional, "microseconds, > 0")) {
    map->require(*delay > 0, "min_delay_us", "is not above 0", "microseconds, > 0");
    emitter.min_delay = *delay * 1e-6;
  }
  emitter.source = map->text("source", Need::required, "where the facts come from").value_or("");
  map->text("note", Need::optional);
  map->reject_unknown_keys();
  return emitter;
}

// `depth_matching: {window_px, image_width_px, baseline_m, source}` of a camera (issue 54).
std::optional<model::DepthMatching> read_depth_matching(MapReader& reader,
                                                        const model::SensorMode& mode) {
  const std::string expected =
      "a map {window_px: the matching window's side in pixels, 1..64; image_width_px: the image "
      "it is counted in, 16..10000; baseline_m: projector or second camera to the depth camera, "
      "metres; source}";
  auto map = reader.map("depth_matching", Need::optional, expected);
  if (!map) return std::nullopt;
  reader.require(mode.fov.shape().is_camera(), "depth_matching", "is given for a scanner",
                 "depth_matching only on a camera's mode");
  const auto window = map->integer("window_px", Need::required, "pixels, 1..64");
  map->require(!window || (*window >= 1 && *window <= 64), "window_px", "is outside 1..64",
               "pixels, 1..64");
  const auto width = map->integer("image_width_px", Need::required, "pixels, 16..10000");
  map->require(!width || (*width >= 16 && *width <= 10000), "image_width_px",
               "is outside 16..10000", "pixels, 16..10000");
  const double baseline = io::positive_length(*map, "baseline_m", Need::required, "metres, > 0");
  model::DepthMatching matching;
  matching.where = map->location();
  matching.source = map->text("source", Need::required, "where the facts come from").value_or("");
  map->reject_unknown_keys();
  if (!window || !width || !(*window >= 1 && *window <= 64) || !(*width >= 16 && *width <= 10000))
    return std::nullopt;
  matching.window_px = static_cast<int>(*window);
  const double h = mode.fov.horizontal();
  matching.window_angle = *window * h / static_cast<double>(*width);
  // A pinhole image: focal length [px] = half the width over tan(half the angle).
  matching.baseline_focal = baseline * (0.5 * static_cast<double>(*width)) / std::tan(0.5 * h);
  return matching;
}

model::SensorMode read_mode(MapReader& reader, std::optional<MapReader>& defaults) {
  model::SensorMode mode;
  mode.where = reader.location();
  mode.id = reader.text("id", Need::required, "a mode id").value_or("");
  if (auto fov = source_of("fov", reader, defaults).map("fov", Need::required)) {
    mode.fov = read_fov(*fov);
  }
  if (auto range = source_of("range", reader, defaults).map("range", Need::required)) {
    mode.min_range = io::non_negative(*range, "min", Need::required, "metres, >= 0");
    mode.max_range = io::positive_length(*range, "max", Need::required, "metres, > min");
    range->require(mode.min_range < mode.max_range, "min", "is not below max",
                   "0 <= min < max, in metres");
    range->reject_unknown_keys();
  }
  MapReader& frequency_from = source_of("frequency", reader, defaults);
  mode.frequency =
      io::positive(frequency_from, "frequency", Need::required, "frames per second [Hz], > 0");
  // Periods become counts (frames held, timing steps): a rate no sensor has is refused here.
  constexpr double kMaxFrequency = 1e4;
  frequency_from.require(!(mode.frequency > kMaxFrequency), "frequency", "is above 10 kHz",
                         "frames per second [Hz], > 0 and at most 10000");
  read_sampling(mode, reader, defaults);
  read_bytes(mode, reader, defaults);
  if (auto noise = source_of("noise", reader, defaults).map("noise", Need::required)) {
    mode.noise = read_noise(*noise);
  }
  if (auto light = source_of("light", reader, defaults).map("light", Need::required)) {
    mode.light = read_light(*light);
  }
  if (auto cpu = source_of("driver_cpu", reader, defaults).map("driver_cpu", Need::required)) {
    mode.driver_cpu = read_driver_cpu(*cpu);
  }
  mode.emitter = read_emitter(source_of("emitter", reader, defaults));
  MapReader& spread_from = source_of("fov_spread_deg", reader, defaults);
  if (const auto spread = spread_from.numbers(
          "fov_spread_deg", Need::optional, 2, 2,
          "[horizontal, vertical]: degrees a unit's full angles may fall short, >= 0")) {
    const bool camera = mode.fov.shape().is_camera();
    const bool fits = (*spread)[0] >= 0 && (*spread)[1] >= 0 &&
                      model::deg_to_rad((*spread)[0]) < mode.fov.horizontal() &&
                      model::deg_to_rad((*spread)[1]) < mode.fov.vertical();
    spread_from.require(
        camera && fits, "fov_spread_deg",
        camera ? "is negative or not below the FOV's angles" : "is given for a scanner",
        "[horizontal, vertical] in degrees, >= 0 and below the FOV's angles, "
        "for a camera");
    if (camera && fits)
      mode.fov_spread =
          std::array<double, 2>{model::deg_to_rad((*spread)[0]), model::deg_to_rad((*spread)[1])};
  }
  mode.depth_matching = read_depth_matching(source_of("depth_matching", reader, defaults), mode);
  source_of("note", reader, defaults).text("note", Need::optional);
  reader.reject_keys_other_than(kModeKeys);
  return mode;
}

model::Price read_price(MapReader& reader) {
  model::Price price;
  price.usd = io::positive(reader, "usd", Need::required, "US dollars, > 0");
  const auto year = reader.integer("year", Need::required, "a year such as 2019");
  reader.require(!year || (*year >= 1990 && *year <= 2100), "year", "is out of range",
                 "a year in [1990, 2100]");
  price.year = year.value_or(0);
  price.basis = io::basis(reader, Need::required);
  price.source = reader.text("source", Need::required, "where the price comes from").value_or("");
  reader.reject_unknown_keys();
  return price;
}

// The largest housing dimension that is plausibly metres: above it, millimetres typed as metres.
constexpr double kLargestHousing = 1.0;  // [m] the largest bundled sensor is about 0.15 m
// [m] how far outside its housing a data origin may lie (a lens standing proud of the front).
constexpr double kOriginOutside = 0.01;

// `housing: {shape: box, size: [x, y, z], center: [x, y, z], source}` or
// `{shape: cylinder, radius, height, center, source}`, all in metres in the sensor frame.
model::HousingSolid read_housing(MapReader& reader) {
  model::HousingSolid housing = io::solid_shape(reader, kLargestHousing);
  const auto center = reader.numbers("center", Need::required, 3, 3,
                                     "[x, y, z]: the solid's centre in the sensor frame [m]");
  if (center) housing.center = model::Vec3((*center)[0], (*center)[1], (*center)[2]);
  // The data origin lies in or on its housing: a centre farther off is a sign or axis slip.
  const model::Vec3 slack = (housing.center.cwiseAbs() - 0.5 * housing.size).cwiseMax(0.0);
  reader.require(slack.norm() <= kOriginOutside, "center",
                 "puts the data origin " +
                     model::format_number(std::round(10000 * slack.norm()) / 10) +
                     " mm outside the housing",
                 "a centre within half the size of the data origin (x forward, y left, z up)");
  housing.source =
      reader.text("source", Need::required, "where the dimensions come from").value_or("");
  reader.reject_unknown_keys();
  return housing;
}

std::vector<std::string> read_frame_names(MapReader& reader, const std::string& key) {
  std::vector<std::string> names;
  const YAML::Node list = reader.node(key);
  if (!list.IsDefined() || list.IsNull()) return names;
  if (!list.IsSequence()) {
    reader.require(false, key, "is not a list", "a list of frame names, the root first");
    return names;
  }
  for (const YAML::Node& item : list) {
    if (item.IsScalar()) names.push_back(item.Scalar());
  }
  return names;
}

// `data_frame_pose: {xyz, rpy_deg, axes: optical | body, source}`: where the driver's own
// static transforms put the data frame in their root (issue 52 item 4).
// (Not xyz_rpy_deg_pose: a driver's small calibrated tilt, the ZED 2's 2.8648 deg, is no sign
// of radians typed as degrees.)
void read_data_frame_pose(MapReader& reader, model::RosDriver& driver) {
  const auto xyz = reader.numbers("xyz", Need::required, 3, 3, "[x, y, z] in metres, finite");
  const auto rpy =
      reader.numbers("rpy_deg", Need::required, 3, 3, "[roll, pitch, yaw] in degrees, finite");
  const bool near = xyz && std::all_of(xyz->begin(), xyz->end(),
                                       [](double v) { return std::abs(v) <= kLargestHousing; });
  reader.require(!xyz || near, "xyz", "is over 1 m from the driver's root frame",
                 "metres within a sensor's housing, e.g. [0, 0, 0.03618]");
  if (xyz && rpy && near) {
    driver.T_root_data = model::pose_from_xyz_rpy(
        model::Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]),
        model::Vec3(model::deg_to_rad((*rpy)[0]), model::deg_to_rad((*rpy)[1]),
                    model::deg_to_rad((*rpy)[2])));
  }
  driver.data_frame_optical =
      reader.choice("axes", Need::required, {"body", "optical"}).value_or(0) == 1;
  reader.text("source", Need::required, "where the transforms are recorded");
  reader.reject_unknown_keys();
}

// The `ros2` map: a driver's facts, or `driver: none`.
model::RosDriver read_ros_driver(MapReader& reader) {
  model::RosDriver driver;
  driver.where = reader.location();
  driver.source =
      reader.text("source", Need::required, "where the facts are recorded").value_or("");
  driver.note = reader.text("note", Need::optional).value_or("");
  if (reader.has("driver")) {
    reader.require(reader.text("driver", Need::required).value_or("") == "none", "driver",
                   "is not `none`", "`driver: none`, or the driver's package, topic and frame");
    reader.reject_unknown_keys();
    return driver;
  }
  driver.exists = true;
  driver.package = reader.text("package", Need::required, "the ROS 2 package").value_or("");
  driver.launch = reader.text("launch", Need::required, "the launch command").value_or("");
  for (const std::string& distro : read_frame_names(reader, "distros")) {
    reader.require(distro == "humble" || distro == "jazzy", "distros", "names '" + distro + "'",
                   "humble and/or jazzy");
    driver.distros.push_back(distro);
  }
  driver.topic =
      io::topic_name(reader, "topic", Need::required, "the data's topic, e.g. /velodyne_points");
  driver.message_type = reader.choice("type", Need::required,
                                      {"sensor_msgs/msg/PointCloud2", "sensor_msgs/msg/LaserScan"})
                                .has_value()
                            ? reader.node("type").Scalar()
                            : "";
  driver.frame_id =
      io::frame_id(reader, "frame_id", Need::required, "the data's frame, e.g. velodyne");
  driver.driver_frames = read_frame_names(reader, "driver_frames");
  if (auto pose = reader.map("data_frame_pose", Need::optional,
                             "{xyz, rpy_deg, axes, source}: frame_id's pose in the root frame")) {
    read_data_frame_pose(*pose, driver);
    reader.require(!driver.driver_frames.empty(), "data_frame_pose",
                   "is given without driver_frames",
                   "driver_frames, the root first, whose root the pose is in");
  }
  driver.frame_parameter =
      reader.text("frame_parameter", Need::required, "how to rename the frame").value_or("");
  reader.reject_unknown_keys();
  return driver;
}

model::Sensor read_sensor(MapReader& reader) {
  model::Sensor sensor;
  sensor.where = reader.location();
  sensor.id = reader.text("id", Need::required, "a sensor id").value_or("");
  sensor.name = reader.text("name", Need::required, "the product name").value_or("");
  if (const auto technology =
          named_value(reader, "technology", Need::required, model::kTechnologyNames)) {
    sensor.technology = *technology;
  }
  sensor.source =
      reader.text("source", Need::required, "the datasheet document or URL").value_or("");
  if (auto price = reader.map("price", Need::required)) sensor.price = read_price(*price);
  if (auto ros2 = reader.map("ros2", Need::optional, "the ROS 2 driver's facts"))
    sensor.ros2 = read_ros_driver(*ros2);
  if (auto housing = reader.map("housing", Need::optional, "the datasheet housing"))
    sensor.housing = read_housing(*housing);
  reader.text("note", Need::optional);
  std::optional<MapReader> defaults = reader.map("mode_defaults", Need::optional);
  if (defaults) defaults->reject_keys_other_than(kModeKeys);
  std::set<std::string> mode_ids;
  for (MapReader& mode_reader : reader.maps("modes", Need::required, "a list of modes")) {
    model::SensorMode mode = read_mode(mode_reader, defaults);
    if (!mode.id.empty() && !mode_ids.insert(mode.id).second) {
      mode_reader.require(false, "id", "duplicate mode id '" + mode.id + "'",
                          "mode ids unique within a sensor");
    }
    sensor.modes.push_back(std::move(mode));
  }
  reader.require(!sensor.modes.empty() || !reader.has("modes"), "modes", "is empty",
                 "at least one mode");
  reader.reject_unknown_keys();
  return sensor;
}

}  // namespace

model::SensorLibrary load_sensor_library(const std::string& path) {
  model::Diagnostics diagnostics;
  MapReader top =
      read_document_map(path, diagnostics, "a map with `reference_machine` and `sensors`");
  model::SensorLibrary library;
  library.file = path;
  library.reference_machine = top.text("reference_machine", Need::required,
                                       "the machine a driver core-equivalent refers to")
                                  .value_or("");
  std::set<std::string> sensor_ids;
  for (MapReader& reader : top.maps("sensors", Need::required, "a list of sensors")) {
    model::Sensor sensor = read_sensor(reader);
    if (!sensor.id.empty() && !sensor_ids.insert(sensor.id).second) {
      reader.require(false, "id", "duplicate sensor id '" + sensor.id + "'", "unique sensor ids");
    }
    library.sensors.push_back(std::move(sensor));
  }
  top.require(!library.sensors.empty() || !top.has("sensors"), "sensors", "is empty",
              "at least one sensor");
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();
  return library;
}

}  // namespace rigdesign::io
