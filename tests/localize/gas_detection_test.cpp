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

TEST_CASE("CO2 as paper 4's ground robot: the first reading over 1800 ppm, one per 5 m",
          "[localize]") {
  // Plumes of 3000 ppm at x = 10..16 and 30..36 over 400 ppm. The first reading over 1800 is
  // x = 10; readings within 5 m of it (x <= 15) belong to it; x = 16 lies 6 m from it and is
  // over the threshold again: a second detection. Likewise x = 30 and 36.
  const localize::Co2Log log = straight_log(
      50, [](int i) { return (i >= 10 && i <= 16) || (i >= 30 && i <= 36) ? 3000.0 : 400.0; });
  const auto detections = localize::detect_gas(log, localize::GasThreshold::fixed);
  CHECK(xs(detections) == std::vector<double>{10, 16, 30, 36});
  CHECK(detections[0].trigger_index == 10);
  CHECK(detections[0].ppm == 3000);
  // "Over" the threshold: a reading of exactly 1800 ppm is not a detection, 1801 is.
  const localize::Co2Log edge = straight_log(20, [](int i) {
    return i == 5 ? 1800.0 : i == 12 ? 1801.0 : 400.0;
  });
  CHECK(xs(localize::detect_gas(edge, localize::GasThreshold::fixed)) == std::vector<double>{12});
}

TEST_CASE("CO2 options that are not the thesis's ground-robot method: average of 5, strongest",
          "[localize]") {
  // The same plumes. The average of 5 (the thesis's UAVs) first reaches 1800 at x = 12
  // ((2 x 400 + 3 x 3000) / 5 = 1960) and 3000 at x = 14; the strongest reading in the area
  // (the thesis's future work) moves the detection there.
  const localize::Co2Log log = straight_log(
      50, [](int i) { return (i >= 10 && i <= 16) || (i >= 30 && i <= 36) ? 3000.0 : 400.0; });
  localize::GasDetectionParams params;
  params.moving_average = 5;
  params.refine_strongest = true;
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
  // 3000 ppm from x = 10 to 30: detections at the first reading over 1800 (x = 10), then at
  // the first reading more than 5 m from the running detection's trigger: 16, 22 and 28.
  const localize::Co2Log log =
      straight_log(45, [](int i) { return i >= 10 && i <= 30 ? 3000.0 : 400.0; });
  const auto detections = localize::detect_gas(log, localize::GasThreshold::fixed);
  CHECK(xs(detections) == std::vector<double>{10, 16, 22, 28});
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
  // Readings 0-39: 14 of 489, 13 of 490, 13 of 491: median 490, MAD 1 ppm, threshold
  // 490 + max(6 x 1.4826, 50) = 540. The first reading over it is the plume's first, x = 40.
  CHECK(detections[0].trigger_index == 40);
  CHECK(detections[0].position.x() == 40);
  CHECK(detections[0].threshold_ppm == Approx(540));
  // Lag: the SCD30's 20 s time constant, no average: 20 s = 20 m back at 1 m per reading;
  // with an assumed 5 s sensor, 5 m.
  CHECK(localize::detection_lag(log, params) == Approx(20.0));
  CHECK(detections[0].lag_corrected.x() == Approx(40.0 - 20.0));
  params.time_constant = 5.0;
  CHECK(localize::detection_lag(log, params) == Approx(5.0));
  CHECK(localize::detect_gas(log, localize::GasThreshold::relative, params)[0].lag_corrected.x() ==
        Approx(35.0));
  // With the UAVs' average of 5 the trailing window adds (5 - 1) / 2 readings: 7 s.
  params.moving_average = 5;
  CHECK(localize::detection_lag(log, params) == Approx(7.0));
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
