#include "rigdesign/localize/gas_detection.hpp"

#include <catch2/catch.hpp>
#include <filesystem>

#include "rigdesign/io/logs/co2_log_reader.hpp"
#include "rigdesign/io/logs/ground_truth_files.hpp"

using namespace rigdesign;

namespace {

// One reading per second and per metre along x; `ppm(i)` gives reading i's concentration.
template <typename Ppm>
localize::Co2Log straight_log(int readings, Ppm ppm) {
  localize::Co2Log log;
  log.source = "test";
  for (int i = 0; i < readings; ++i)
    log.readings.push_back({static_cast<double>(i), {static_cast<double>(i), 0, 0}, ppm(i)});
  return log;
}

std::vector<double> xs(const std::vector<localize::GasDetection>& detections) {
  std::vector<double> x;
  for (const localize::GasDetection& d : detections) x.push_back(d.position.x());
  return x;
}

std::string subt(const std::string& name) {
  return std::string(RIGDESIGN_SOURCE_DIR) + "/../shared/data/real/subt_urban/" + name;
}

}  // namespace

TEST_CASE("CO2: moving average of 5 against 1800 ppm, refined to the strongest reading in the area",
          "[localize]") {
  // Plumes of 3000 ppm at x = 10..16 and 30..36 over 400 ppm. The average of 5 first reaches
  // 1800 at x = 12 ((2 x 400 + 3 x 3000) / 5 = 1960) and 3000 at x = 14.
  const localize::Co2Log log = straight_log(
      50, [](int i) { return (i >= 10 && i <= 16) || (i >= 30 && i <= 36) ? 3000.0 : 400.0; });
  localize::GasDetectionParams params;
  const auto refined = localize::detect_gas(log, localize::GasThreshold::fixed, params);
  CHECK(xs(refined) == std::vector<double>{14, 34});
  CHECK(refined[0].trigger_index == 12);
  CHECK(refined[0].ppm == Approx(3000));
  // Unrefined, the trailing average's tail (x = 18: (3 x 3000 + 2 x 400) / 5 = 1960) lies 6 m
  // from the trigger at x = 12 and counts again: the lag the refinement hides.
  params.refine_strongest = false;
  CHECK(xs(localize::detect_gas(log, localize::GasThreshold::fixed, params)) ==
        std::vector<double>{12, 18, 32, 38});
}

TEST_CASE("CO2: one detection per 5 m along a long plume", "[localize]") {
  // 3000 ppm from x = 10 to 30: the first detection is refined to x = 14 (average 3000); the
  // next may not lie within 5 m of it (x = 19), then each leaves the 5 m area of its trigger.
  const localize::Co2Log log =
      straight_log(45, [](int i) { return i >= 10 && i <= 30 ? 3000.0 : 400.0; });
  const auto detections = localize::detect_gas(log, localize::GasThreshold::fixed);
  CHECK(xs(detections) == std::vector<double>{14, 19, 25, 31});
  for (std::size_t i = 1; i < detections.size(); ++i) {
    CHECK(detections[i].position.x() - detections[i - 1].position.x() >= 5.0);
  }
}

TEST_CASE(
    "CO2: a threshold relative to the running baseline finds a weak plume; the lag moves it back",
    "[localize]") {
  // Ambient 489-491 ppm, a plume of 700 ppm at x = 40..45: far below 1800 ppm.
  const localize::Co2Log log =
      straight_log(80, [](int i) { return i >= 40 && i <= 45 ? 700.0 : 489.0 + i % 3; });
  CHECK(localize::detect_gas(log, localize::GasThreshold::fixed).empty());
  localize::GasDetectionParams params;
  const auto detections = localize::detect_gas(log, localize::GasThreshold::relative, params);
  REQUIRE(detections.size() == 1);
  // Median 490, MAD 1 ppm: threshold 490 + max(6 x 1.4826, 50) = 540. The average passes it
  // with two plume readings in (x = 41: (3 x ~490 + 2 x 700) / 5 = 574; one gives 532) and
  // is strongest (700) at x = 44; the tail (x = 47, 616 ppm) lies within 5 m of it.
  CHECK(detections[0].trigger_index == 41);
  CHECK(detections[0].position.x() == 44);
  CHECK(detections[0].threshold_ppm == Approx(540));
  // Lag: the SCD30's 20 s time constant + 2 readings of the trailing average at 1 s each =
  // 22 s = 22 m back at 1 m per reading; with an assumed 5 s sensor, 7 s = 7 m.
  CHECK(localize::detection_lag(log, params) == Approx(22.0));
  CHECK(detections[0].lag_corrected.x() == Approx(44.0 - 22.0));
  params.time_constant = 5.0;
  CHECK(localize::detection_lag(log, params) == Approx(7.0));
  CHECK(localize::detect_gas(log, localize::GasThreshold::relative, params)[0].lag_corrected.x() ==
        Approx(37.0));
}

TEST_CASE(
    "CO2 on the DARPA SubT Urban trace: the fixed threshold misses, the relative one finds gas 67",
    "[localize]") {
  if (!std::filesystem::exists(subt("gas_data_spot2_urban_beta2.txt"))) {
    WARN("shared/data/real/subt_urban is absent: skipped");
    return;
  }
  const localize::Co2Log log = io::read_co2_log(subt("gas_data_spot2_urban_beta2.txt"));
  REQUIRE(log.readings.size() == 1030);  // SOURCES.md
  const std::vector<localize::Artifact> artifacts = io::read_artifacts(subt("gt_beta2.json"));
  // SOURCES.md: the trace peaks near 720 ppm, far below 1800.
  CHECK(localize::detect_gas(log, localize::GasThreshold::fixed).empty());
  const auto detections = localize::detect_gas(log, localize::GasThreshold::relative);
  for (const bool lagged : {false, true}) {
    const localize::GasScore score = localize::score_gas(log, detections, artifacts, lagged);
    REQUIRE(score.artifacts.size() == 3);  // gas 57, 67, 74
    for (const localize::GasArtifactResult& a : score.artifacts) {
      if (a.artifact.id == 67) CHECK(a.found);
    }
  }
}
