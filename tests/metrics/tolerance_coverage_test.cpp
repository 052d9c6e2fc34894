// Issue 38 item 1: a sector's SC over a mount's tolerance box. The hand case: a 60 x 40 deg
// pyramid camera 0.5 m up at x = 0.25 m on a 0.2 m cylinder, pitched 20 deg down, so its lower
// edge meets the floor 40 deg below the horizon and its upper edge is level; along azimuth 0
// it sees the floor from rho = x + z / tan(pitch + 20 deg) out to d = 2 m (its 4 m range reaches
// past d). With +-5 mm in x and z and +-1 deg of pitch the floor edge is farthest at x + 5 mm,
// z + 5 mm, pitch - 1 deg.
#include "rigdesign/metrics/tolerance_coverage.hpp"

#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/tolerance_verdicts.hpp"
#include "rigdesign/model/units.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

const std::string kToleranceRig = R"(name: Tolerance case
body: {radius: 0.2, height: 0.5}
distance_of_interest: 2.0
tolerance: {xyz: [0.005, 0, 0.005], rpy_deg: [0, 1, 0]}
mounts:
  - {id: front, sensor: cam, mode: m30, pose: {xyz: [0.25, 0, 0.5], rpy_deg: [0, 20, 0]}}
)";

// SC floor along azimuth 0 for the camera at (x, z) pitched `pitch_deg` down, by hand.
double floor_share(double x, double z, double pitch_deg) {
  const double near = x + z / std::tan(model::deg_to_rad(pitch_deg + 20.0));
  return (2.0 - near) / (2.0 - 0.2);
}

}  // namespace

TEST_CASE("tolerance: the floor edge at the box's worst corner, by hand", "[metrics][tolerance]") {
  test::TempFolder folder;
  const model::SensorLibrary library =
      io::load_sensor_library(folder.write("sensors.yaml", test::kLibrary));
  const model::Rig rig = io::load_rig(folder.write("rig.yaml", kToleranceRig));
  REQUIRE(rig.tolerance);
  CHECK(rig.tolerance_for(rig.mounts.front()) == &*rig.tolerance);
  // One azimuth: the sector [0, 0] deg. Nominal 64.1 %, required 64 %: met with 0.1 % to spare.
  model::SectorRequirement ahead;
  ahead.name = "ahead";
  ahead.min_floor_coverage = 0.64;
  const std::vector<metrics::SectorTolerance> result =
      metrics::tolerance_coverage(rig, library, {ahead});
  REQUIRE(result.size() == 1);
  const double nominal = floor_share(0.25, 0.5, 20.0);
  const double worst = floor_share(0.255, 0.505, 19.0);
  CHECK(nominal == Approx(0.64118).margin(1e-5));  // the numbers above, to 5 digits
  CHECK(result[0].nominal_floor == Approx(nominal).margin(1e-6));
  CHECK(result[0].floor.share == Approx(worst).margin(1e-6));
  REQUIRE(result[0].floor.errors.size() == 1);
  const metrics::MountError& worst_error = result[0].floor.errors.front();
  CHECK(worst_error.mount_id == "front");
  CHECK(worst_error.error.xyz.x() == Approx(0.005));
  CHECK(worst_error.error.xyz.z() == Approx(0.005));
  CHECK(worst_error.error.rpy.y() == Approx(model::deg_to_rad(-1.0)));
  // 1 deg and 5 mm take the sector from pass to fail.
  CHECK(nominal >= ahead.min_floor_coverage);
  CHECK_FALSE(result[0].pass);
  CHECK(result[0].margin() == Approx(worst - 0.64).margin(1e-6));
  // check's verdict: R2 fails on the floor and points at the rig's tolerance line (line 4).
  const std::vector<metrics::RequirementResult> verdicts = metrics::tolerance_verdicts(rig, result);
  REQUIRE(verdicts.size() == 1);
  CHECK(verdicts[0].id == "R2");
  CHECK(verdicts[0].metric == "SC floor");
  CHECK(verdicts[0].verdict == metrics::Verdict::fail);
  CHECK(verdicts[0].limiting_mounts == std::vector<std::string>{"front"});
  CHECK(verdicts[0].rig_where.line == 4);
}

TEST_CASE("tolerance: the box's corners and face centres, axes of zero width left out",
          "[metrics][tolerance]") {
  model::PoseTolerance tolerance;
  tolerance.xyz = model::Vec3(0.005, 0, 0.005);
  tolerance.rpy = model::Vec3(0, model::deg_to_rad(1.0), 0);
  // Three axes: 2^3 corners and 2 x 3 face centres.
  CHECK(metrics::tolerance_samples(tolerance).size() == 14);
  tolerance.xyz = model::Vec3::Zero();
  CHECK(metrics::tolerance_samples(tolerance).size() == 2);  // one axis: -w and +w
  // A pitch error turns about the sensor's own y axis: a level camera pitched +1 deg looks
  // 1 deg down (its x axis gains -sin(1 deg) in z).
  const model::Pose3 turned =
      metrics::with_error(model::Pose3::Identity(), {model::Vec3::Zero(), tolerance.rpy});
  CHECK(turned.linear().col(0).z() == Approx(-std::sin(model::deg_to_rad(1.0))));
}

TEST_CASE("tolerance: a translation over 0.1 m or a rotation over 10 deg is a warning",
          "[metrics][tolerance]") {
  test::TempFolder folder;
  std::string text = kToleranceRig;
  text.replace(text.find("xyz: [0.005, 0, 0.005], rpy_deg: [0, 1, 0]"),
               std::string("xyz: [0.005, 0, 0.005], rpy_deg: [0, 1, 0]").size(),
               "xyz: [5, 0, 5], rpy_deg: [0, 15, 0]");
  const model::Rig rig = io::load_rig(folder.write("rig.yaml", text));
  REQUIRE(rig.load_warnings.size() == 2);
  CHECK(rig.load_warnings[0].field == "tolerance.xyz");
  CHECK(rig.load_warnings[1].field == "tolerance.rpy_deg");
  text.replace(text.find("[0, 15, 0]"), 10, "[0, -1, 0]");
  CHECK_THROWS_AS(io::load_rig(folder.write("bad.yaml", text)), model::InputError);
}

TEST_CASE("tolerance: a mode's FOV spread is judged at its narrowest", "[metrics][tolerance]") {
  // The same camera with a datasheet spread of 4 deg on its 40 deg vertical angle: the
  // narrowest unit's lower edge is 18 deg below the axis, 38 deg below the horizon, and its
  // floor starts at 0.25 + 0.5 / tan 38 deg. A zero box still judges the spread.
  test::TempFolder folder;
  std::string library_text = test::kLibrary;
  library_text.replace(library_text.find("        range: {min: 0.1, max: 4.0}"), 0,
                       "        fov_spread_deg: [0, 4]\n");
  const model::SensorLibrary library =
      io::load_sensor_library(folder.write("sensors.yaml", library_text));
  std::string rig_text = kToleranceRig;
  rig_text.replace(rig_text.find("xyz: [0.005, 0, 0.005], rpy_deg: [0, 1, 0]"),
                   std::string("xyz: [0.005, 0, 0.005], rpy_deg: [0, 1, 0]").size(),
                   "xyz: [0, 0, 0], rpy_deg: [0, 0, 0]");
  const model::Rig rig = io::load_rig(folder.write("rig.yaml", rig_text));
  model::SectorRequirement ahead;
  ahead.name = "ahead";
  ahead.min_floor_coverage = 0.6;
  const std::vector<metrics::SectorTolerance> result =
      metrics::tolerance_coverage(rig, library, {ahead});
  REQUIRE(result.size() == 1);
  const double narrowest = (2.0 - 0.25 - 0.5 / std::tan(model::deg_to_rad(38.0))) / 1.8;
  CHECK(result[0].nominal_floor == Approx(floor_share(0.25, 0.5, 20.0)).margin(1e-6));
  CHECK(result[0].floor.share == Approx(narrowest).margin(1e-6));
  REQUIRE(result[0].floor.errors.size() == 1);
  CHECK(result[0].floor.errors.front().error.narrowest_fov);
  CHECK(metrics::error_text(result[0].floor.errors.front().error) ==
        "FOV at its datasheet narrowest");
  // A scanner has no FOV spread: the file says so at the field.
  std::string scanner = test::kLibrary;
  scanner.replace(scanner.find("        range: {min: 0.5, max: 50}"), 0,
                  "        fov_spread_deg: [1, 1]\n");
  CHECK_THROWS_AS(io::load_sensor_library(folder.write("bad.yaml", scanner)), model::InputError);
}
