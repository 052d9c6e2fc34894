// `rigdesign sensors [SENSOR] [--technology T,...] [--search TEXT] [--min-range M]
// [--max-price USD] [--min-rate HZ] [--min-fov-deg DEG] [--sort KEY] [--format text|json]
// [--sensors FILE]`: lists and searches the sensor library, or prints one sensor in full.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app.hpp"
#include "command.hpp"
#include "common_options.hpp"
#include "number_checks.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/model/closest_name.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/report/sensor_query.hpp"
#include "rigdesign/report/text_table.hpp"
#include "sensor_sheet.hpp"

namespace rigdesign::cli {
namespace {

struct SensorsOptions {
  std::string sensor;
  report::SensorQuery query;
  std::string sort = "id";
  std::string format = "text";
  std::string sensors;
};

double sort_key(const model::Sensor& sensor, const std::string& key) {
  double best = 0.0;
  for (const model::SensorMode& mode : sensor.modes) {
    best = std::max(best, key == "range" ? mode.max_range : mode.frequency);
  }
  return key == "price" ? sensor.price.usd : -best;  // range and rate: largest first
}

std::vector<const model::Sensor*> select_sensors(const model::SensorLibrary& library,
                                                 const SensorsOptions& options) {
  std::vector<const model::Sensor*> found;
  for (const model::Sensor& sensor : library.sensors) {
    if (report::sensor_matches(sensor, options.query)) found.push_back(&sensor);
  }
  std::stable_sort(found.begin(), found.end(), [&](const model::Sensor* a, const model::Sensor* b) {
    if (options.sort == "id") return a->id < b->id;
    return sort_key(*a, options.sort) < sort_key(*b, options.sort);
  });
  return found;
}

std::string span(double low, double high, int decimals) {
  return low == high ? report::fixed(low, decimals)
                     : report::fixed(low, decimals) + "-" + report::fixed(high, decimals);
}

void print_list(const std::vector<const model::Sensor*>& sensors, const SensorsOptions& options,
                const model::SensorLibrary& library, std::ostream& out) {
  out << "Sensor library " << library.file << ": " << sensors.size() << " of "
      << library.sensors.size() << " sensors match\n\n";
  report::TextTable table;
  table.add_column("id", report::TextTable::Align::left);
  table.add_column("technology", report::TextTable::Align::left);
  table.add_column("FOV h x v [deg]", report::TextTable::Align::right);
  table.add_column("max range [m]", report::TextTable::Align::right);
  table.add_column("rate [Hz]", report::TextTable::Align::right);
  table.add_column("modes", report::TextTable::Align::right);
  table.add_column("price [USD]", report::TextTable::Align::right);
  table.add_column("name", report::TextTable::Align::left);
  for (const model::Sensor* sensor : sensors) {
    const std::vector<const model::SensorMode*> modes =
        report::matching_modes(*sensor, options.query);
    double range_low = 1e300, range_high = 0, rate_low = 1e300, rate_high = 0;
    for (const model::SensorMode* mode : modes) {
      range_low = std::min(range_low, mode->max_range);
      range_high = std::max(range_high, mode->max_range);
      rate_low = std::min(rate_low, mode->frequency);
      rate_high = std::max(rate_high, mode->frequency);
    }
    table.add_row({sensor->id, model::to_string(sensor->technology),
                   modes.front()->fov.shape().summary_deg(), span(range_low, range_high, 1),
                   span(rate_low, rate_high, 1),
                   std::to_string(modes.size()) + "/" + std::to_string(sensor->modes.size()),
                   report::fixed(sensor->price.usd, 0) +
                       (sensor->price.basis == model::Basis::estimate ? "*" : " "),
                   sensor->name});
  }
  table.print(out, "  ");
  out << "\n  modes: those meeting --min-range/--min-rate/--min-fov-deg, of all; "
         "FOV of the first; * price is an estimate.\n"
         "  `rigdesign sensors ID` prints one sensor in full.\n";
}

int run_sensors(const SensorsOptions& options, std::ostream& out) {
  const model::SensorLibrary library = io::load_sensor_library(
      options.sensors.empty() ? io::bundled_sensor_library() : options.sensors);
  for (const std::string& technology : options.query.technologies) {
    const std::vector<std::string> names = model::names_of(model::kTechnologyNames);
    require_option(std::find(names.begin(), names.end(), technology) != names.end(), "--technology",
                   "unknown technology '" + technology + "'", "one of " + model::join(names));
  }
  if (!options.sensor.empty()) {
    const model::Sensor* sensor = library.find(options.sensor);
    if (sensor == nullptr) {
      std::vector<std::string> ids;
      for (const model::Sensor& candidate : library.sensors) ids.push_back(candidate.id);
      const std::string closest = model::closest_name(options.sensor, ids);
      require_option(false, "sensor",
                     "no sensor '" + options.sensor + "' in " + library.file +
                         (closest.empty() ? "" : " (did you mean '" + closest + "'?)"),
                     "a sensor id from `rigdesign sensors`");
    }
    if (options.format == "json") {
      out << sensor_json(*sensor, library).dump(2) << '\n';
    } else {
      print_sensor_sheet(*sensor, library, out);
    }
    return kOk;
  }
  const std::vector<const model::Sensor*> sensors = select_sensors(library, options);
  if (options.format == "json") {
    nlohmann::json list = nlohmann::json::array();
    for (const model::Sensor* sensor : sensors) list.push_back(sensor_json(*sensor, library));
    out << nlohmann::json{{"library", library.file}, {"sensors", list}}.dump(2) << '\n';
  } else {
    print_list(sensors, options, library, out);
  }
  return kOk;
}

}  // namespace

Command setup_sensors(CLI::App& parent) {
  auto options = std::make_shared<SensorsOptions>();
  CLI::App* app = parent.add_subcommand(
      "sensors", "List and search the sensor library, or print one sensor in full");
  app->add_option("sensor", options->sensor, "A sensor id: print its datasheet values and modes");
  app->add_option("--technology", options->query.technologies,
                  "Only these technologies (repeatable, or comma-separated)")
      ->delimiter(',');
  app->add_option("--search", options->query.search,
                  "Only sensors whose id or name contains this text (any case)");
  app->add_option("--min-range", options->query.min_range,
                  "Only sensors with a mode reaching at least this far [m]")
      ->check(finite_in(0.0, 1e6, "metres, >= 0"));
  app->add_option("--max-price", options->query.max_price,
                  "Only sensors costing at most this [USD]")
      ->check(positive_up_to(1e9, "a price in USD, > 0"));
  app->add_option("--min-rate", options->query.min_rate,
                  "Only sensors with a mode at least this fast [Hz]")
      ->check(finite_in(0.0, 1e6, "a rate in Hz, >= 0"));
  app->add_option("--min-fov-deg", options->query.min_fov_deg,
                  "Only sensors with a mode at least this wide horizontally [deg]")
      ->check(finite_in(0.0, 360.0, "degrees in [0, 360]"));
  app->add_option("--sort", options->sort, "Order of the list (range and rate: largest first)")
      ->check(CLI::IsMember({"id", "price", "range", "rate"}))
      ->capture_default_str();
  app->add_option("--format", options->format, "Output format")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  add_sensors_option(*app, options->sensors);
  return {app, [options](std::ostream& out, std::ostream&) { return run_sensors(*options, out); }};
}

}  // namespace rigdesign::cli
