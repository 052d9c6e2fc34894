// Issue 14: where a sensor sees its own robot, against geometry worked by hand.
#include "rigdesign/deploy/self_filters.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {
constexpr double kRadiansPerDegree = std::numbers::pi / 180;
}  // namespace

TEST_CASE("self-filters: a scanner on a bracket sees the face behind it", "[deploy]") {
  // The cart's front scanner stands 0.2 m ahead of a 0.4 m wide face: the face's corners are
  // at atan2(+-0.2, -0.2) = +-135 deg, so its rays hit the cart for |angle| >= 135 deg, a
  // quarter of the 1452 rays of a 0.248 deg scan (about 363), and nowhere else.
  const model::SensorLibrary library = io::load_sensor_library(source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(source_path("rigs/cart_two_scanners.yaml"));
  const std::vector<deploy::SelfFilter> filters = deploy::self_filters(rig, library);
  REQUIRE(filters.size() == 2);
  for (const deploy::SelfFilter& filter : filters) {
    INFO(filter.mount_id);
    CHECK(filter.scanner);
    CHECK(filter.rays == 1452);
    CHECK(std::abs(filter.body_hits - 1452 / 4) <= 2);
    REQUIRE(filter.bands.size() == 2);
    const double step = 0.248 * kRadiansPerDegree;
    // Bands reach half a step past the outermost hit rays; -135 and 135 deg are their inner
    // ends, -180 and 180 deg (and a little beyond) the outer ones.
    CHECK(filter.bands[0].lower < -std::numbers::pi + 1e-12);
    CHECK(filter.bands[0].upper == Approx(-135 * kRadiansPerDegree).margin(step));
    CHECK(filter.bands[1].lower == Approx(135 * kRadiansPerDegree).margin(step));
    CHECK(filter.bands[1].upper > std::numbers::pi - step);
  }
}

TEST_CASE("self-filters: a spinning lidar above a wide top gets a crop box around it", "[deploy]") {
  // The test library's spinner (beams every 2 deg from -15 to +15, 0.5-50 m, sigma 0.03 m)
  // 0.2 m above the top of a cylinder 2 m in radius and 1 m high. A beam at -e deg meets the
  // top 0.2 / tan e out: -15, -13, -11, -9 and -7 deg do within the radius (0.746..1.629 m,
  // each beyond the 0.5 m minimum range along the ray); -5 deg would at 2.286 m, past it.
  // The box is the hit ring's extent, +-1.629 m in x and y at z = 1, padded by 3 sigma =
  // 0.09 m.
  TempFolder folder;
  folder.write("sensors.yaml", kLibrary);
  const model::Rig rig = io::load_rig(folder.write("rig.yaml", R"(name: wide top
sensor_library: sensors.yaml
body: {radius: 2.0, height: 1.0}
distance_of_interest: 5.0
mounts:
  - {id: top, sensor: spin, mode: s10, pose: {xyz: [0, 0, 1.2], rpy_deg: [0, 0, 0]}}
)"));
  const model::SensorLibrary library = io::load_sensor_library(folder.path() + "/sensors.yaml");
  const std::vector<deploy::SelfFilter> filters = deploy::self_filters(rig, library);
  REQUIRE(filters.size() == 1);
  const deploy::SelfFilter& filter = filters.front();
  CHECK_FALSE(filter.scanner);
  // 1800 columns of 0.2 deg, 5 of the 16 beams hit.
  CHECK(filter.body_hits == 5 * 1800);
  REQUIRE(filter.boxes.size() == 1);
  const double reach = 0.2 / std::tan(7 * kRadiansPerDegree);
  CHECK(reach == Approx(1.6289).epsilon(1e-4));
  CHECK(filter.padding == Approx(0.09));
  CHECK(filter.boxes[0].max.x() == Approx(reach + 0.09).margin(1e-6));
  CHECK(filter.boxes[0].min.y() == Approx(-reach - 0.09).margin(1e-3));
  CHECK(filter.boxes[0].min.z() == Approx(1.0 - 0.09).margin(1e-9));
  CHECK(filter.boxes[0].max.z() == Approx(1.0 + 0.09).margin(1e-9));
}
