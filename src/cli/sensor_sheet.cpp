#include "sensor_sheet.hpp"

#include <nlohmann/json.hpp>
#include <ostream>

#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/report/text_table.hpp"

namespace rigdesign::cli {
namespace {

std::string resolution_text(const model::SensorMode& mode) {
  std::string text = model::format_number(model::rad_to_deg(mode.angular_resolution_h), 3);
  if (mode.angular_resolution_v) {
    text += " x " + model::format_number(model::rad_to_deg(*mode.angular_resolution_v), 3);
  }
  return text;
}

std::string light_text(const model::LightImmunity& light) {
  std::string text;
  for (const model::LightCondition condition : model::kLightConditions) {
    if (light.immune_to(condition)) text += (text.empty() ? "" : ",") + model::to_string(condition);
  }
  return text.empty() ? "none" : text;
}

std::string noise_text(const model::NoiseModel& noise) {
  std::string text;
  auto term = [&text](double value, const std::string& unit) {
    if (value == 0.0) return;
    text += (text.empty() ? "" : " + ") + model::format_number(value, 4) + unit;
  };
  term(noise.a, " m");
  term(noise.b, " d");
  term(noise.c, " d^2/m");
  return text.empty() ? "0" : text;
}

std::string where_text(const model::SourceLocation& where) {
  return model::to_string(where);
}

// The sensor's ROS 2 driver as the export uses it (sensors.yaml `ros2`).
void print_ros_driver(const model::Sensor& sensor, std::ostream& out) {
  if (!sensor.ros2) return;
  const model::RosDriver& driver = *sensor.ros2;
  if (!driver.exists) {
    out << "  ROS 2       no maintained driver (" << driver.note << "; " << driver.source << ")\n";
    return;
  }
  std::string distros;
  for (const std::string& distro : driver.distros)
    distros += (distros.empty() ? "" : ", ") + distro;
  out << "  ROS 2       " << driver.package << " (" << distros << "): " << driver.topic << " ("
      << driver.message_type << ") in " << driver.frame_id << "\n"
      << "              " << driver.launch << "\n";
  if (!driver.driver_frames.empty()) {
    std::string frames;
    for (const std::string& frame : driver.driver_frames)
      frames += (frames.empty() ? "" : ", ") + frame;
    out << "              broadcasts " << frames << " itself (the URDF gives the first)\n";
  }
  if (!driver.note.empty()) out << "              " << driver.note << "\n";
}

nlohmann::json ros_driver_json(const model::Sensor& sensor) {
  if (!sensor.ros2) return nullptr;
  const model::RosDriver& d = *sensor.ros2;
  if (!d.exists) return {{"driver", "none"}, {"note", d.note}, {"source", d.source}};
  return {{"package", d.package},
          {"launch", d.launch},
          {"distros", d.distros},
          {"topic", d.topic},
          {"type", d.message_type},
          {"frame_id", d.frame_id},
          {"driver_frames", d.driver_frames},
          {"frame_parameter", d.frame_parameter},
          {"note", d.note},
          {"source", d.source}};
}

}  // namespace

void print_sensor_sheet(const model::Sensor& sensor, const model::SensorLibrary& library,
                        std::ostream& out) {
  out << sensor.id << ": " << sensor.name << "\n"
      << "  technology  " << model::to_string(sensor.technology) << "\n"
      << "  price       " << model::format_number(sensor.price.usd, 8) << " USD ("
      << sensor.price.year << ", " << model::to_string(sensor.price.basis) << ": "
      << sensor.price.source << ")\n"
      << "  source      " << sensor.source << "\n";
  print_ros_driver(sensor, out);
  out << "  defined at  " << where_text(sensor.where) << " (library " << library.file << ")\n\n";
  report::TextTable table;
  table.add_column("mode", report::TextTable::Align::left);
  table.add_column("FOV [deg]", report::TextTable::Align::right);
  table.add_column("range [m]", report::TextTable::Align::right);
  table.add_column("rate [Hz]", report::TextTable::Align::right);
  table.add_column("step [deg]", report::TextTable::Align::right);
  table.add_column("points/frame", report::TextTable::Align::right);
  table.add_column("Mpoints/s", report::TextTable::Align::right);
  table.add_column("MB/s", report::TextTable::Align::right);
  table.add_column("sigma 1 m / max [mm]", report::TextTable::Align::right);
  table.add_column("works in", report::TextTable::Align::left);
  table.add_column("driver [cores]", report::TextTable::Align::right);
  for (const model::SensorMode& mode : sensor.modes) {
    const double points_per_second = mode.points_per_frame * mode.frequency;
    table.add_row(
        {mode.id, mode.fov.shape().summary_deg(),
         model::format_number(mode.min_range, 3) + "-" + model::format_number(mode.max_range, 4),
         model::format_number(mode.frequency, 4), resolution_text(mode),
         report::fixed(mode.points_per_frame, 0), report::fixed(points_per_second / 1e6, 3),
         report::fixed(mode.bytes_per_frame * mode.frequency / 1e6, 2),
         report::fixed(1e3 * mode.noise.sigma(1.0), 1) + " / " +
             report::fixed(1e3 * mode.noise.sigma(mode.max_range), 1),
         light_text(mode.light),
         report::fixed(mode.driver_cpu.load(points_per_second), 3) +
             (mode.driver_cpu.basis == model::Basis::estimate ? "*" : " ")});
  }
  table.print(out, "  ");
  out << "\n  noise sigma(d) per mode: ";
  std::string previous;
  for (const model::SensorMode& mode : sensor.modes) {
    const std::string text = noise_text(mode.noise);
    if (text != previous) out << (previous.empty() ? "" : "; ") << mode.id << " " << text;
    previous = text;
  }
  out << "\n  * driver load is an estimate (no vendor publishes it; sensors.yaml header)\n";
  for (const model::SensorMode& mode : sensor.modes) {
    if (!mode.driver_cpu.note.empty()) {
      out << "  driver note: " << mode.driver_cpu.note << "\n";
      break;
    }
  }
}

nlohmann::json sensor_json(const model::Sensor& sensor, const model::SensorLibrary& library) {
  nlohmann::json modes = nlohmann::json::array();
  for (const model::SensorMode& mode : sensor.modes) {
    nlohmann::json fov{{"shape", mode.fov.shape().name()}};
    for (const model::NamedAngle& angle : mode.fov.shape().report_angles()) {
      fov[std::string(angle.key)] = model::rad_to_deg(angle.radians);
    }
    nlohmann::json resolution{model::rad_to_deg(mode.angular_resolution_h)};
    if (mode.angular_resolution_v)
      resolution.push_back(model::rad_to_deg(*mode.angular_resolution_v));
    modes.push_back({{"id", mode.id},
                     {"fov", fov},
                     {"range", {{"min", mode.min_range}, {"max", mode.max_range}}},
                     {"frequency", mode.frequency},
                     {"angular_resolution_deg", resolution},
                     {"points_per_frame", mode.points_per_frame},
                     {"points_per_second", mode.points_per_frame * mode.frequency},
                     {"bytes_per_second", mode.bytes_per_frame * mode.frequency},
                     {"noise", {{"a", mode.noise.a}, {"b", mode.noise.b}, {"c", mode.noise.c}}},
                     {"light",
                      {{"dark", mode.light.dark},
                       {"indoor", mode.light.indoor},
                       {"sunlight", mode.light.sunlight}}},
                     {"driver_cpu",
                      {{"cores", mode.driver_cpu.cores},
                       {"seconds_per_point", mode.driver_cpu.seconds_per_point},
                       {"basis", model::to_string(mode.driver_cpu.basis)}}}});
  }
  return {{"id", sensor.id},
          {"name", sensor.name},
          {"technology", model::to_string(sensor.technology)},
          {"source", sensor.source},
          {"price",
           {{"usd", sensor.price.usd},
            {"year", sensor.price.year},
            {"basis", model::to_string(sensor.price.basis)},
            {"source", sensor.price.source}}},
          {"defined_at", where_text(sensor.where)},
          {"library", library.file},
          {"ros2", ros_driver_json(sensor)},
          {"modes", modes}};
}

}  // namespace rigdesign::cli
