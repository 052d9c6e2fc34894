// Spatial coverage against areas computed by hand (paper 1, section 2.3).
#include <catch2/catch.hpp>
#include <cmath>

#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

model::SensorMode pyramid(double horizontal_deg, double vertical_deg, double min_range,
                          double max_range) {
  model::SensorMode mode;
  mode.id = "pyramid";
  mode.fov = model::FieldOfView(
      model::pyramid_fov(model::deg_to_rad(horizontal_deg), model::deg_to_rad(vertical_deg)));
  mode.min_range = min_range;
  mode.max_range = max_range;
  mode.frequency = 10;
  mode.angular_resolution_h = model::deg_to_rad(0.1);
  mode.angular_resolution_v = model::deg_to_rad(0.1);
  return mode;
}

model::SensorMode band(double elevation_min_deg, double elevation_max_deg, double max_range) {
  model::SensorMode mode = pyramid(10, 10, 0, max_range);
  mode.id = "band";
  mode.fov = model::FieldOfView(model::band_fov(2 * 3.141592653589793,
                                                model::deg_to_rad(elevation_min_deg),
                                                model::deg_to_rad(elevation_max_deg)));
  return mode;
}

// A rig of one sensor type "s" with the given mounts (xyz, rpy in degrees).
struct TestRig {
  model::SensorLibrary library;
  model::Rig rig;
  TestRig(const model::SensorMode& mode, double radius, double height, double distance) {
    model::Sensor sensor;
    sensor.id = "s";
    sensor.modes.push_back(mode);
    library.sensors.push_back(sensor);
    rig.body.radius = radius;
    rig.body.height = height;
    rig.distance_of_interest = distance;
  }
  TestRig& mount(const model::Vec3& xyz, const model::Vec3& rpy_deg) {
    model::Mount mount;
    mount.id = "m" + std::to_string(rig.mounts.size());
    mount.sensor_id = "s";
    mount.mode_id = library.sensors[0].modes[0].id;
    mount.T_robot_sensor = model::pose_from_xyz_rpy(
        xyz, model::Vec3(model::deg_to_rad(rpy_deg.x()), model::deg_to_rad(rpy_deg.y()),
                         model::deg_to_rad(rpy_deg.z())));
    rig.mounts.push_back(mount);
    return *this;
  }
  const metrics::AngleCoverage& at_degrees(const metrics::RigCoverage& coverage,
                                           int degrees) const {
    return coverage.angles.at(static_cast<std::size_t>(degrees));
  }
};

}  // namespace

TEST_CASE("a horizontal pyramid on the body's front: a wedge in the forward section") {
  // Sensor at rho = r = 0.5 m, z0 = 0.5 m, looking forward; vertical FOV 40 deg. In the
  // forward half-plane it covers |z - z0| <= tan(20 deg) * s, s = rho - r, so the wedge fills
  // the 1 m height from s* = 0.5 / tan 20 deg on: area = tan(20) s*^2 + (3 - s*) * 1.
  const double t = std::tan(model::deg_to_rad(20.0));
  const double s_star = 0.5 / t;
  const double wedge_area = t * s_star * s_star + (3.0 - s_star);
  TestRig test(pyramid(60, 40, 0.0, 10.0), 0.5, 1.0, 3.5);
  test.mount({0.5, 0, 0.5}, {0, 0, 0});
  const metrics::RigCoverage coverage = metrics::compute_coverage(test.rig, test.library, {});
  const metrics::AngleCoverage& ahead = test.at_degrees(coverage, 0);
  CHECK_THAT(ahead.complete, WithinAbs(wedge_area / 3.0, 1e-5));
  CHECK_THAT(ahead.floor, WithinAbs((3.0 - s_star) / 3.0, 1e-6));
  CHECK_THAT(ahead.complete_raster, WithinAbs(wedge_area / 3.0, 0.005));
  CHECK(test.at_degrees(coverage, 90).complete == 0.0);  // behind the lens plane

  SECTION("a 2 m range cap cuts the wedge with a circle around the sensor") {
    // Beyond s*, the strip |y| <= 0.5 (y = z - z0) inside the disk s^2 + y^2 <= 4:
    // integral of sqrt(4 - y^2) - s* over y in [-0.5, 0.5].
    const auto primitive = [](double y) {
      return y / 2 * std::sqrt(4 - y * y) + 2 * std::asin(y / 2);
    };
    const double capped = t * s_star * s_star + (primitive(0.5) - primitive(-0.5)) - s_star;
    TestRig capped_rig(pyramid(60, 40, 0.0, 2.0), 0.5, 1.0, 3.5);
    capped_rig.mount({0.5, 0, 0.5}, {0, 0, 0});
    const metrics::RigCoverage capped_coverage =
        metrics::compute_coverage(capped_rig.rig, capped_rig.library, {});
    // The arc is tessellated to 1 mm chord error: area within ~1e-3 m^2 of the true disk.
    CHECK_THAT(capped_rig.at_degrees(capped_coverage, 0).complete, WithinAbs(capped / 3.0, 3e-4));
  }
}

TEST_CASE("a 360-degree band above the body gives a constant curve, shaded by the top") {
  // Band -15..+15 deg at z = 1.1 m over a body r = 0.5, h = 1: rays steeper than
  // tan e = 0.1 / 0.5 = 0.2 hit the top face, so the section sees z >= 1.1 - 0.2 rho:
  // area = integral over rho in [0.5, 3.5] of (0.2 rho - 0.1) = 0.9 m^2 of 3 m^2.
  TestRig test(band(-15, 15, 100.0), 0.5, 1.0, 3.5);
  test.mount({0, 0, 1.1}, {0, 0, 0});
  const metrics::RigCoverage coverage = metrics::compute_coverage(test.rig, test.library, {});
  for (const metrics::AngleCoverage& angle : coverage.angles) {
    CHECK_THAT(angle.complete, WithinAbs(0.3, 1e-5));
    CHECK(angle.floor == 0.0);
  }
  CHECK_THAT(coverage.complete.min, WithinAbs(coverage.complete.mean, 1e-9));
}

TEST_CASE("two identical sensors cover what one covers, redundancy is the overlap") {
  TestRig one(pyramid(60, 40, 0.2, 4.0), 0.4, 1.0, 3.0);
  one.mount({0.41, 0, 0.5}, {0, 15, 0});
  TestRig two = one;
  two.mount({0.41, 0, 0.5}, {0, 15, 0});
  const metrics::RigCoverage single = metrics::compute_coverage(one.rig, one.library, {});
  const metrics::RigCoverage twice = metrics::compute_coverage(two.rig, two.library, {});
  for (std::size_t i = 0; i < single.angles.size(); ++i) {
    CHECK_THAT(twice.angles[i].complete, WithinAbs(single.angles[i].complete, 1e-9));
    CHECK_THAT(twice.angles[i].redundancy, WithinAbs(single.angles[i].complete_raster, 1e-12));
  }
}

TEST_CASE("a sensor behind the body sees nothing through it") {
  TestRig behind(pyramid(60, 40, 0.0, 10.0), 0.5, 1.0, 3.5);
  behind.mount({-0.51, 0, 0.5}, {0, 0, 0});  // on the back, looking forward through the body
  TestRig in_front(pyramid(60, 40, 0.0, 10.0), 0.5, 1.0, 3.5);
  in_front.mount({0.51, 0, 0.5}, {0, 0, 0});
  CHECK(metrics::compute_coverage(behind.rig, behind.library, {}).angles[0].complete == 0.0);
  CHECK(metrics::compute_coverage(in_front.rig, in_front.library, {}).angles[0].complete > 0.7);
}

TEST_CASE("line coverage of a pyramid matches its edge planes and range sphere") {
  // Sensor at the origin looking along x, FOV 90 x 90 deg, range [1, 5]; the vertical line
  // x = 2, y = 0 is seen for |z| <= 2 (edge planes z = +-x) and x^2 + z^2 in [1, 25].
  const model::SensorMode mode = pyramid(90, 90, 1.0, 5.0);
  model::RobotBody tiny;
  tiny.radius = 0.01;
  tiny.height = 0.01;
  const geometry::BodyOccluder body(tiny);
  const geometry::MountedFov fov(
      mode, model::pose_from_xyz_rpy(model::Vec3(0, 0, 1), model::Vec3::Zero()), body, "");
  const geometry::IntervalSet covered =
      fov.covered_along(model::Vec3(2, 0, 1), model::Vec3::UnitZ(), -10, 10);
  REQUIRE(covered.intervals().size() == 1);
  CHECK_THAT(covered.intervals()[0].first, WithinAbs(-2.0, 1e-12));
  CHECK_THAT(covered.intervals()[0].second, WithinAbs(2.0, 1e-12));
  // The line x = 4: the edge planes allow |z| <= 4, the sphere |z| <= 3.
  const geometry::IntervalSet far =
      fov.covered_along(model::Vec3(4, 0, 1), model::Vec3::UnitZ(), -10, 10);
  REQUIRE(far.intervals().size() == 1);
  CHECK_THAT(far.intervals()[0].second, WithinAbs(3.0, 1e-12));
  // The min range splits the line x = 0.5 into two pieces: z^2 >= 0.75, |z| <= 0.5? none.
  CHECK(
      fov.covered_along(model::Vec3(0.5, 0, 1), model::Vec3::UnitZ(), -10, 10).intervals().size() ==
      0);
}

TEST_CASE("a mirror-symmetric rig has SC(theta) = SC(-theta)") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(test::source_path("rigs/ur_cleaner.yaml"));
  const metrics::RigCoverage coverage = metrics::compute_coverage(rig, library, {});
  const std::size_t n = coverage.angles.size();
  for (std::size_t i = 1; i < n; ++i) {
    INFO("theta index " << i);
    CHECK_THAT(coverage.angles[i].complete, WithinAbs(coverage.angles[n - i].complete, 1e-6));
    CHECK_THAT(coverage.angles[i].floor, WithinAbs(coverage.angles[n - i].floor, 1e-9));
  }
}

TEST_CASE("the raster path stays within 0.5 % of the exact path on every bundled rig") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  for (const char* file :
       {"rigs/ur_cleaner.yaml", "rigs/elektron.yaml", "rigs/delivery_amr.yaml"}) {
    INFO(file);
    const metrics::RigCoverage coverage =
        metrics::compute_coverage(io::load_rig(test::source_path(file)), library, {});
    CHECK(coverage.raster_error_complete <= 0.005);
    CHECK(coverage.raster_error_floor <= 0.005);
  }
}

TEST_CASE("azimuth culling never drops a section a sensor sees") {
  // Where the conservative bound says a sensor cannot reach an azimuth, the exact column
  // coverage (which does no culling) must be empty at every rho.
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  for (const char* file :
       {"rigs/ur_cleaner.yaml", "rigs/elektron.yaml", "rigs/delivery_amr.yaml"}) {
    const model::Rig rig = io::load_rig(test::source_path(file));
    const geometry::BodyOccluder body(rig.body);
    for (const model::Mount& mount : rig.mounts) {
      const geometry::MountedFov fov(*library.find(mount.sensor_id)->find_mode(mount.mode_id),
                                     mount.T_robot_sensor, body, mount.housing_link);
      for (int degrees = 0; degrees < 360; degrees += 2) {
        const geometry::SectionFrame frame =
            geometry::section_frame(body, model::deg_to_rad(degrees), rig.distance_of_interest);
        if (fov.may_reach_azimuth(frame.theta)) continue;
        for (double rho = frame.r; rho <= frame.d; rho += 0.05) {
          INFO(file << " " << mount.id << " theta " << degrees << " rho " << rho);
          CHECK(geometry::column_coverage(fov, frame, rho).empty());
        }
      }
    }
  }
}
