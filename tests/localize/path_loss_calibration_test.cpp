#include "rigdesign/localize/path_loss_calibration.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace rigdesign;

namespace {

// Scans along the x axis at the given distances from an emitter at the origin (antenna and
// emitter at one height), all heard.
localize::ScanSeries scans_at(const std::vector<double>& distances, const std::vector<double>& rssi,
                              double floor_dbm = -120.0) {
  localize::ScanSeries series;
  series.floor_dbm = floor_dbm;
  for (std::size_t i = 0; i < distances.size(); ++i) {
    localize::Scan scan;
    scan.t = static_cast<double>(i);
    scan.position = model::Vec3(distances[i], 0.0, 0.0);
    scan.rssi_dbm = rssi[i];
    scan.heard = rssi[i] >= floor_dbm;
    series.scans.push_back(scan);
    series.heard += scan.heard ? 1 : 0;
  }
  return series;
}

}  // namespace

TEST_CASE("calibration: readings +-1 dB about a known line give its level and exponent, sigma 1",
          "[localize]") {
  // a = -50 dBm, n = 3: rssi = -50 - 30 log10 d, each distance read once 1 dB high and once
  // 1 dB low. All heard, so the likelihood is least squares: the line exactly, and the maximum-
  // likelihood sigma is the rms residual, 1 dB.
  std::vector<double> d, rssi;
  for (const double distance : {2.0, 4.0, 8.0, 16.0, 32.0}) {
    for (const double e : {1.0, -1.0}) {
      d.push_back(distance);
      rssi.push_back(-50.0 - 30.0 * std::log10(distance) + e);
    }
  }
  const auto c = localize::calibrate_path_loss(scans_at(d, rssi), model::Vec3::Zero());
  REQUIRE(c);
  CHECK(c->rssi_at_1m_dbm == Approx(-50.0).margin(1e-3));
  CHECK(c->exponent == Approx(3.0).margin(1e-4));
  CHECK(c->sigma_db == Approx(1.0).margin(1e-4));
  CHECK(c->heard == 10);
  CHECK(c->unheard == 0);
  CHECK(c->nearest_m == Approx(2.0));
  CHECK(c->farthest_m == Approx(32.0));
  // Ordinary least squares' standard error of the slope, by hand: sigma^2 / Sxx with x = -10
  // log10 d (Sxx = 2 * sum (x - mean x)^2 = 2 * 100 * (log10 2)^2 * 10) and the maximum-
  // likelihood sigma 1; sigma's own uncertainty is independent of the line's when all is heard.
  const double sxx = 2.0 * 100.0 * std::pow(std::log10(2.0), 2) * 10.0;
  CHECK(c->exponent_sd == Approx(std::sqrt(1.0 / sxx)).epsilon(1e-3));
}

TEST_CASE("calibration: unheard scans below the floor correct the flattening a floor causes",
          "[localize]") {
  // Readings of a = -40 dBm, n = 2.5 with 6 dB Gaussian noise at 2-60 m, a -80 dBm floor: far
  // away only the luckiest readings are heard, so a line through the heard ones alone is too
  // flat. The censored fit knows the rest were below the floor.
  std::mt19937 rng(33);
  std::normal_distribution<double> noise(0.0, 6.0);
  std::vector<double> d, rssi;
  for (int i = 0; i < 2000; ++i) {
    const double distance = 2.0 + 58.0 * i / 1999.0;
    d.push_back(distance);
    rssi.push_back(-40.0 - 25.0 * std::log10(distance) + noise(rng));
  }
  const localize::ScanSeries series = scans_at(d, rssi, -80.0);
  REQUIRE(series.heard < 1800);  // the floor censors a good share of the far scans
  const auto c = localize::calibrate_path_loss(series, model::Vec3::Zero());
  REQUIRE(c);
  CHECK(c->unheard == 2000 - series.heard);
  CHECK(std::abs(c->exponent - 2.5) < 3.0 * c->exponent_sd);
  CHECK(std::abs(c->rssi_at_1m_dbm + 40.0) < 3.0 * c->level_sd_db);
  CHECK(c->sigma_db == Approx(6.0).margin(0.5));
  // The heard readings' least-squares slope, by hand, is flatter by far more than that.
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (const localize::Scan& scan : series.scans) {
    if (!scan.heard) continue;
    const double x = -10.0 * std::log10(scan.position.x());
    sx += x, sy += scan.rssi_dbm, sxx += x * x, sxy += x * scan.rssi_dbm, n += 1;
  }
  const double heard_only_slope = (sxy - sx * sy / n) / (sxx - sx * sx / n);
  CHECK(heard_only_slope < 2.5 - 10.0 * c->exponent_sd);
}

TEST_CASE("calibration: a mapped wall's loss is taken off before the fit", "[localize]") {
  // A 10 dB wall at x = 5 m: the scans beyond it read 10 dB low. With the wall map the line is
  // the true one; without it the fit must differ.
  std::vector<double> d, rssi;
  for (const double distance : {2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 16.0}) {
    for (const double e : {0.5, -0.5}) {
      d.push_back(distance);
      rssi.push_back(-45.0 - 20.0 * std::log10(distance) + e - (distance > 5.0 ? 10.0 : 0.0));
    }
  }
  const std::vector<localize::WallSegment> walls = {
      {model::Vec2(5.0, -1.0), model::Vec2(5.0, 1.0), 10.0}};
  const auto with_map =
      localize::calibrate_path_loss(scans_at(d, rssi), model::Vec3::Zero(), walls);
  const auto without = localize::calibrate_path_loss(scans_at(d, rssi), model::Vec3::Zero());
  REQUIRE(with_map);
  REQUIRE(without);
  CHECK(with_map->rssi_at_1m_dbm == Approx(-45.0).margin(1e-3));
  CHECK(with_map->exponent == Approx(2.0).margin(1e-4));
  CHECK(without->exponent > 2.5);
}

TEST_CASE("calibration: a circle round the emitter tells no exponent", "[localize]") {
  const std::vector<double> d(20, 12.0), rssi(20, -70.0);
  CHECK_FALSE(localize::calibrate_path_loss(scans_at(d, rssi), model::Vec3::Zero()));
}

TEST_CASE("environment presets are paper 4's Table 4 rows and its underground stations",
          "[localize]") {
  // DESIGN.md section 9, paper 4's Table 4 (its reference [49]), midpoints of its ranges.
  const auto exponent = [](const char* name) {
    const localize::EnvironmentPreset* preset = localize::find_environment_preset(name);
    REQUIRE(preset);
    return preset->exponent;
  };
  CHECK(exponent("free-space") == 2.0);
  CHECK(exponent("urban-area") == Approx((2.7 + 4.0) / 2));
  CHECK(exponent("indoor-los") == Approx((1.6 + 1.8) / 2));
  CHECK(exponent("indoor-general") == Approx((4.0 + 6.0) / 2));
  CHECK(exponent("indoor-factories") == Approx((2.0 + 3.0) / 2));
  CHECK(exponent("indoor-through-floor") == Approx((3.0 + 6.0) / 2));
  // The thesis's text: underground stations "between 2.2 and 3 for 2.4 GHz".
  CHECK(exponent("underground-station") == Approx((2.2 + 3.0) / 2));
  CHECK(localize::environment_presets().size() == 7);
  CHECK(localize::find_environment_preset("attic") == nullptr);
  CHECK(localize::find_environment_preset("building-obstructed") == nullptr);  // Rappaport's
}
