// Issue 53 items 3 and 6 for scenarios, occupancy and localize: counts computed from input are
// judged against their caps before they become loops or allocations, and fits that are
// singular or not physical are refused. Every input here is made by hand so that why it is
// refused can be read off it: one position, a constant reading, a gap of 1e8 s.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/io/config/sensor_library_locator.hpp"
#include "rigdesign/io/logs/rssi_csv.hpp"
#include "rigdesign/localize/emitter_localizer.hpp"
#include "rigdesign/localize/path_loss_calibration.hpp"
#include "rigdesign/localize/scan_series.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "rigdesign/scenarios/sensor_timing.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
using Catch::Matchers::Contains;

namespace {

constexpr const char* kBssid = "aa:bb:cc:dd:ee:01";

// An RSSI log: one line per (t, x, y, rssi), antenna at 0.4 m.
struct LogLine {
  double t, x, y, rssi;
};

std::string rssi_log(const std::vector<LogLine>& lines) {
  std::ostringstream text;
  text.precision(17);
  text << "t,x,y,z,bssid,rssi\n";
  for (const LogLine& l : lines)
    text << l.t << "," << l.x << "," << l.y << ",0.4," << kBssid << "," << l.rssi << "\n";
  return text.str();
}

std::string truth_at_origin(const TempFolder& folder) {
  return folder.write("truth.csv", std::string("bssid,x,y,z\n") + kBssid + ",0,0,0.4\n");
}

CliResult calibrate(const TempFolder& folder, const std::vector<LogLine>& lines) {
  const std::string log = folder.write("log.csv", rssi_log(lines));
  return run_cli({"localize", "--calibrate", "--log", log, "--truth", truth_at_origin(folder)});
}

// `text` with its first `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("calibration: every reading at one position is a singular fit, refused",
          "[localize][issue53]") {
  // 30 readings 5 m from the emitter: one distance tells no exponent.
  TempFolder folder;
  std::vector<LogLine> lines;
  for (int i = 0; i < 30; ++i) lines.push_back({0.1 * i, 3.0, 4.0, -60.0 - (i % 3)});
  const CliResult result = calibrate(folder, lines);
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("rssi: emitter aa:bb:cc:dd:ee:01") && Contains("singular"));
  CHECK(result.out.empty());  // nothing suggested
}

TEST_CASE("calibration: a reading that does not fall with distance is no path loss, refused",
          "[localize][issue53]") {
  // -60 dBm at 2 to 31 m: the fit's exponent is 0 and its sigma 0, neither physical.
  std::vector<LogLine> lines;
  for (int i = 0; i < 30; ++i) lines.push_back({0.1 * i, 2.0 + i, 0.0, -60.0});
  localize::RssiLog log = io::parse_rssi_csv(rssi_log(lines), "flat.csv");
  const auto fit =
      localize::calibrate_path_loss(localize::scan_series(log, 0), model::Vec3(0.0, 0.0, 0.4));
  REQUIRE(fit);
  CHECK_THAT(localize::calibration_problem(*fit), Contains("exponent"));
  TempFolder folder;
  const CliResult result = calibrate(folder, lines);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("rssi:") && Contains("is not a path loss"));

  // The same path with -40 - 25 log10(d) +- 1 dB is a usable fit.
  for (std::size_t i = 0; i < lines.size(); ++i)
    lines[i].rssi = -40.0 - 25.0 * std::log10(lines[i].x) + (i % 2 ? 1.0 : -1.0);
  log = io::parse_rssi_csv(rssi_log(lines), "good.csv");
  const auto good =
      localize::calibrate_path_loss(localize::scan_series(log, 0), model::Vec3(0.0, 0.0, 0.4));
  REQUIRE(good);
  CHECK(localize::calibration_problem(*good).empty());
  CHECK(good->exponent == Approx(2.5).margin(0.1));
}

TEST_CASE("localize: a gap of 1e8 scan periods is refused before its scans are placed",
          "[localize][issue53]") {
  // Standing still, 0.1 s scans, then the same place 1e8 s later: 1e9 unheard scans to place.
  TempFolder folder;
  std::vector<LogLine> lines;
  for (int i = 0; i < 10; ++i) lines.push_back({0.1 * i, 3.0, 4.0, -60.0});
  for (int i = 0; i < 10; ++i) lines.push_back({1e8 + 0.1 * i, 3.0, 4.0, -60.0});
  const std::string log = folder.write("gap.csv", rssi_log(lines));
  CliResult result = run_cli({"localize", "--log", log, "--method", "nls"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("gap.csv: t: the gap from t = "));
  // A scan period of 1e-300 s on a 0.1 s log: the same refusal, not an overflowed count.
  lines.resize(10);
  const std::string short_log = folder.write("short.csv", rssi_log(lines));
  result = run_cli({"localize", "--log", short_log, "--method", "nls", "--scan-period", "1e-300"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("short.csv: t:") && Contains("--scan-period"));
}

TEST_CASE("localize: a path across +-1e8 m is refused before the range fit's grid",
          "[localize][issue53]") {
  TempFolder folder;
  std::vector<LogLine> lines;
  for (int i = 0; i < 20; ++i)
    lines.push_back({0.1 * i, i % 2 ? 1e8 : -1e8, (i / 2) % 2 ? 1e8 : -1e8, -70.0});
  const std::string log = folder.write("far.csv", rssi_log(lines));
  const CliResult result = run_cli({"localize", "--log", log, "--method", "nls"});
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("far.csv: x, y:") && Contains("2e+08"));
}

TEST_CASE("costmap: an update rate of 1e-300 Hz and an inflation of 1e300 m are refused",
          "[scenario][issue53]") {
  TempFolder folder;
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  CliResult result = run_cli({"costmap", rig, "--scenario", "stationary", "--update-rate", "1e-300",
                              "--out", folder.path() + "/slow"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("--update-rate") && Contains("1e-300") && Contains("0.0167"));
  const std::string params = folder.write(
      "params.yaml", replaced(file_text(source_path("rigs/costmap/ur_cleaner_local_costmap.yaml")),
                              "inflation_radius: 0.55", "inflation_radius: 1e300"));
  result = run_cli({"costmap", rig, "--scenario", "stationary", "--params", params, "--out",
                    folder.path() + "/wide"});
  CHECK(result.exit_code == 2);
  // At the file's key (ur_cleaner_local_costmap.yaml line 52), not on the command line.
  CHECK_THAT(result.err, Contains("params.yaml:52:") && Contains("inflation_radius: is 1e+300"));
  CHECK(folder.entries() == 1);  // the parameter file: no output folder
}

TEST_CASE("costmap scenario file: a wait longer than a day is refused at its line",
          "[scenario][issue53]") {
  TempFolder folder;
  const std::string scenario = folder.write(
      "waits.scenario.yaml", "name: waits\nscene: " + source_path("rigs/scenes/lab/lab.yaml") +
                                 "\nroute:\n  - {xy: [2.3, -1.4], wait: 1e300}\n");
  const CliResult result = run_cli({"costmap", source_path("rigs/ur_cleaner.yaml"), "--scenario",
                                    scenario, "--out", folder.path() + "/out"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("waits.scenario.yaml:4:") && Contains("route[0].wait") &&
                             Contains("at most 86400"));
}

TEST_CASE("scenario inputs: a mount recording more than 1000 frames a second is refused",
          "[scenario][issue53]") {
  const model::Rig rig = io::load_rig(source_path("rigs/ur_cleaner.yaml"));
  model::SensorLibrary library = io::load_sensor_library(io::locate_sensor_library(rig, ""));
  const model::Mount& first = rig.mounts.front();
  for (model::Sensor& sensor : library.sensors)
    for (model::SensorMode& mode : sensor.modes)
      if (sensor.id == first.sensor_id && mode.id == first.mode_id) mode.frequency = 1e300;
  try {
    scenarios::check_scenario_inputs(rig, library, scenarios::ScenarioParams{});
    FAIL("expected an InputError");
  } catch (const model::InputError& error) {
    CHECK_THAT(error.what(), Contains("mounts." + first.id + ": records 1e+300 frames"));
  }
}

TEST_CASE("sensor timing: frames already passed on are not listed again", "[scenario][issue53]") {
  // 8 Hz from t = 0, no latency, a persistence longer than the run: at t = 100 s every frame
  // since the start is held (0 to 800), but after frame 795 only the five newer ones.
  scenarios::MountTiming timing;
  timing.period = 0.125;
  CHECK(scenarios::frames_held(timing, 100.0, 1e300).size() == 801);
  CHECK(scenarios::frames_held(timing, 100.0, 1e300, 795) ==
        std::vector<long>{796, 797, 798, 799, 800});
}

TEST_CASE("occupancy: a run shorter than one frame is refused, not run as one",
          "[occupancy][issue53]") {
  const CliResult result =
      run_cli({"occupancy", source_path("rigs/cell.yaml"), "--duration", "1", "--rate", "1e-300",
               "--voxels", "0.2", "--persistence", "none"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("--duration, --rate: 1 s at 1e-300 Hz"));
}
