// Sensor housings (issue 52 item 2): the shadow one housing casts on another sensor, by hand on
// both coverage paths; overlap depth against hand cases and an independent point sampler; B2.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <utility>

#include "rigdesign/geometry/housing_clearance.hpp"
#include "rigdesign/geometry/housing_geometry.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/metrics/mount_placement_verdicts.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

model::SensorMode mode_with(std::shared_ptr<const model::FovShape> shape, double max_range) {
  model::SensorMode mode;
  mode.id = "m";
  mode.fov = model::FieldOfView(std::move(shape));
  mode.max_range = max_range;
  mode.frequency = 10;
  mode.angular_resolution_h = model::deg_to_rad(0.2);
  mode.angular_resolution_v = model::deg_to_rad(0.2);
  return mode;
}

model::HousingSolid box(const model::Vec3& size, const model::Vec3& center) {
  model::HousingSolid housing;
  housing.shape = model::HousingShape::box;
  housing.size = size;
  housing.center = center;
  return housing;
}

model::HousingSolid cylinder(double radius, double height, const model::Vec3& center) {
  model::HousingSolid housing = box(model::Vec3(2 * radius, 2 * radius, height), center);
  housing.shape = model::HousingShape::cylinder;
  return housing;
}

model::Mount mount_at(const std::string& id, const std::string& sensor, const model::Vec3& xyz,
                      double yaw_deg = 0.0) {
  model::Mount mount;
  mount.id = id;
  mount.sensor_id = sensor;
  mount.mode_id = "m";
  mount.T_robot_sensor =
      model::pose_from_xyz_rpy(xyz, model::Vec3(0, 0, model::deg_to_rad(yaw_deg)));
  return mount;
}

// A spinning lidar on a mast above a cylinder body (r 0.2 m, h 0.3 m) and a short-range camera
// whose housing, a 20 x 90 x 200 mm box, stands 0.2 m in front of the lidar.
struct LidarBehindCamera {
  model::SensorLibrary library;
  model::Rig rig;
  explicit LidarBehindCamera(bool housing) {
    model::Sensor lidar;
    lidar.id = "lidar";
    lidar.modes.push_back(mode_with(
        model::band_fov(2 * std::numbers::pi, model::deg_to_rad(-15.0), model::deg_to_rad(15.0)),
        5.0));
    model::Sensor camera;
    camera.id = "camera";
    // Sees nothing of the sections: 5 cm of range at z = 0.5 m, above the 0.3 m area.
    camera.modes.push_back(
        mode_with(model::pyramid_fov(model::deg_to_rad(60), model::deg_to_rad(40)), 0.05));
    // Data origin on the front face: the box reaches 20 mm behind it.
    if (housing) camera.housing = box({0.02, 0.09, 0.2}, {-0.01, 0.0, 0.0});
    library.sensors = {lidar, camera};
    rig.body.radius = 0.2;
    rig.body.height = 0.3;
    rig.distance_of_interest = 2.0;
    rig.mounts = {mount_at("lidar", "lidar", {0, 0, 0.5}),
                  mount_at("camera", "camera", {0.22, 0, 0.5})};
  }
};

// An independent membership test: inside the solid shrunk by `margin` [m] (sensor frame).
bool inside(const model::HousingSolid& h, const model::Pose3& T, const model::Vec3& p_robot,
            double margin) {
  const model::Vec3 q = T.inverse() * p_robot - h.center;
  const model::Vec3 half = 0.5 * h.size - model::Vec3::Constant(margin);
  if (h.shape == model::HousingShape::box)
    return std::abs(q.x()) <= half.x() && std::abs(q.y()) <= half.y() &&
           std::abs(q.z()) <= half.z();
  return q.head<2>().norm() <= h.radius() - margin && std::abs(q.z()) <= half.z();
}

}  // namespace

TEST_CASE("a camera housing in front of a spinning lidar hides 2 atan(45/200) of azimuth") {
  // By hand: seen from the lidar the box's front face spans |y| <= 45 mm at x = 200 mm, so
  // its shadow spans |azimuth| <= atan(0.045 / 0.2) = 12.68 deg; at the face the band's
  // +-15 deg reach z = 0.5 +- 0.205 tan 15 = 0.5 +- 0.055 m, inside the box's +-0.1 m. Every
  // point of a section within 12.68 deg is hidden (the lidar sees it only through the box),
  // every section from 13 deg on is untouched. Both paths must show exactly that.
  for (const bool exact : {true, false}) {
    metrics::CoverageSettings settings;
    settings.exact = exact;
    const LidarBehindCamera open(false);
    const LidarBehindCamera housed(true);
    const metrics::RigCoverage without =
        metrics::compute_coverage(open.rig, open.library, {}, settings);
    const metrics::RigCoverage with =
        metrics::compute_coverage(housed.rig, housed.library, {}, settings);
    REQUIRE(with.angles.size() == 360);
    for (int degrees = 0; degrees < 360; ++degrees) {
      INFO((exact ? "exact" : "raster") << " path, azimuth " << degrees << " deg");
      const auto& a = with.angles[static_cast<std::size_t>(degrees)];
      const auto& b = without.angles[static_cast<std::size_t>(degrees)];
      REQUIRE(b.complete > 0.05);  // the lidar alone sees part of every section
      const int from_front = degrees <= 180 ? degrees : 360 - degrees;
      if (from_front <= 12) {
        CHECK(a.complete == 0.0);
        CHECK(a.floor == 0.0);
      } else {
        CHECK_THAT(a.complete, WithinAbs(b.complete, 1e-12));
        CHECK_THAT(a.floor, WithinAbs(b.floor, 1e-12));
      }
    }
  }
}

TEST_CASE("housing overlap depth: hand cases") {
  const model::Pose3 I = model::Pose3::Identity();
  const auto depth = [&](const model::HousingSolid& a, const model::Pose3& Ta,
                         const model::HousingSolid& b, const model::Pose3& Tb) {
    return geometry::penetration(geometry::housing_solid(a, Ta), geometry::housing_solid(b, Tb));
  };
  const model::HousingSolid cube = box({0.1, 0.1, 0.1}, model::Vec3::Zero());
  model::Pose3 moved = I;
  moved.translation() = model::Vec3(0.095, 0.02, 0.0);  // 5 mm of x overlap
  CHECK_THAT(depth(cube, I, cube, moved), WithinAbs(0.005, 1e-12));
  moved.translation() = model::Vec3(0.0, 0.0, 0.1);  // standing on top: touching
  CHECK_THAT(depth(cube, I, cube, moved), WithinAbs(0.0, 1e-12));
  moved.translation() = model::Vec3(0.0, 0.0, 0.13);  // 30 mm apart
  CHECK_THAT(depth(cube, I, cube, moved), WithinAbs(-0.03, 1e-12));
  // A cube turned 45 deg about z reaches 50 sqrt(2) mm along x: beside another at 0.12 m it
  // overlaps by 0.05 + 0.0707 - 0.12 = 0.7 mm.
  model::Pose3 turned = model::pose_from_xyz_rpy({0.12, 0, 0}, {0, 0, std::numbers::pi / 4});
  CHECK_THAT(depth(cube, I, cube, turned), WithinAbs(0.05 + 0.05 * std::sqrt(2.0) - 0.12, 1e-12));
  // Two vertical cylinders (r 50 and 30 mm) 75 mm apart overlap by 5 mm, within the
  // circumscribed prisms' 0.5 % of a radius.
  moved.translation() = model::Vec3(0.075, 0.0, 0.0);
  CHECK_THAT(depth(cylinder(0.05, 0.07, model::Vec3::Zero()), I,
                   cylinder(0.03, 0.07, model::Vec3::Zero()), moved),
             WithinAbs(0.005, 0.0005));
}

TEST_CASE("housing overlap agrees with a point sampler on random pairs") {
  // Independent of the separating axes: a 2 mm grid of points, each tested against both solids
  // shrunk by 2 mm with the solids' own equations. A point in both proves an overlap at least
  // 2 mm deep; the sampler proves nothing about pairs it finds apart, so the test asserts the
  // two sound implications: common point => depth >= 2 mm; depth <= 0 => no common point.
  constexpr double kGrid = 0.002;
  std::mt19937 rng(52);
  std::uniform_real_distribution<double> size(0.02, 0.12);
  std::uniform_real_distribution<double> offset(-0.1, 0.1);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  int overlaps = 0;
  int apart = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto random_solid = [&] {
      return (rng() % 2) ? box({size(rng), size(rng), size(rng)}, model::Vec3::Zero())
                         : cylinder(0.5 * size(rng), size(rng), model::Vec3::Zero());
    };
    const model::HousingSolid a = random_solid();
    const model::HousingSolid b = random_solid();
    const model::Pose3 Ta = model::pose_from_xyz_rpy({0, 0, 0}, {angle(rng), angle(rng), 0});
    const model::Pose3 Tb = model::pose_from_xyz_rpy({offset(rng), offset(rng), offset(rng)},
                                                     {angle(rng), angle(rng), angle(rng)});
    const double depth =
        geometry::penetration(geometry::housing_solid(a, Ta), geometry::housing_solid(b, Tb));
    // A's bounding sphere bounds the points worth trying.
    const double reach = 0.5 * a.size.norm();
    bool common = false;
    for (double x = -reach; x <= reach && !common; x += kGrid)
      for (double y = -reach; y <= reach && !common; y += kGrid)
        for (double z = -reach; z <= reach && !common; z += kGrid)
          common = inside(a, Ta, {x, y, z}, kGrid) && inside(b, Tb, {x, y, z}, kGrid);
    INFO("trial " << trial << ": depth " << depth);
    if (common) {
      ++overlaps;
      CHECK(depth >= kGrid - 1e-9);
    }
    if (depth <= 0.0) {
      ++apart;
      CHECK_FALSE(common);
    }
  }
  CHECK(overlaps >= 10);  // both kinds of pair were drawn
  CHECK(apart >= 10);
}

TEST_CASE("B2: housings that overlap each other or cut into the body fail, touching passes") {
  model::SensorLibrary library;
  model::Sensor camera;
  camera.id = "camera";
  camera.modes.push_back(
      mode_with(model::pyramid_fov(model::deg_to_rad(60), model::deg_to_rad(40)), 3.0));
  camera.housing = box({0.025, 0.09, 0.025}, {-0.0125, 0.0, 0.0});
  library.sensors = {camera};
  model::Rig rig;
  rig.body.radius = 0.2;
  rig.body.height = 0.3;
  rig.distance_of_interest = 2.0;
  // Two cameras standing on the body's top, one 60 mm to the other's left: their 90 mm wide
  // boxes overlap by 30 mm along y and fully along x (25 mm) and z (25 mm): moving one 25 mm
  // forward would part them.
  rig.mounts = {mount_at("left", "camera", {0.1, 0.03, 0.3125}),
                mount_at("right", "camera", {0.1, -0.03, 0.3125})};
  const auto verdicts = [&] { return metrics::placement_verdicts(rig, library); };
  std::vector<metrics::RequirementResult> found = verdicts();
  REQUIRE(found.size() == 4);  // B1 per mount, then B2 per mount
  CHECK(found[2].id == "B2");
  CHECK(found[2].verdict == metrics::Verdict::fail);
  CHECK_THAT(found[2].explanation, Catch::Contains("cuts 25 mm into the housing of mount 'right'"));
  CHECK(found[3].verdict == metrics::Verdict::fail);
  // 100 mm apart they touch nothing but the body's top, which they stand on.
  rig.mounts[0].T_robot_sensor.translation().y() = 0.05;
  rig.mounts[1].T_robot_sensor.translation().y() = -0.05;
  found = verdicts();
  CHECK(found[2].verdict == metrics::Verdict::pass);
  CHECK(found[3].verdict == metrics::Verdict::pass);
  // Lowered 5 mm, the boxes sink into the body's top face.
  rig.mounts[0].T_robot_sensor.translation().z() = 0.3075;
  found = verdicts();
  CHECK(found[2].verdict == metrics::Verdict::fail);
  CHECK_THAT(found[2].explanation, Catch::Contains("cuts 5 mm into the robot body"));
}

TEST_CASE("a housing nothing holds is a warning with its gap; one standing on the body is not") {
  model::SensorLibrary library;
  model::Sensor lidar;
  lidar.id = "lidar";
  lidar.modes.push_back(mode_with(
      model::band_fov(2 * std::numbers::pi, model::deg_to_rad(-15.0), model::deg_to_rad(15.0)),
      5.0));
  // A VLP-16-like cylinder whose optical centre is 38 mm above its base.
  lidar.housing = cylinder(0.0516, 0.0717, {0.0, 0.0, 0.03585 - 0.038});
  library.sensors = {lidar};
  model::Rig rig;
  rig.body.radius = 0.3;
  rig.body.height = 0.5;
  rig.distance_of_interest = 2.0;
  rig.mounts = {mount_at("top", "lidar", {0.0, 0.0, 0.5 + 0.038})};  // on the top plate
  CHECK_FALSE(geometry::housing_gap(rig, library, 0));
  CHECK(metrics::floating_warnings(rig, library).empty());
  // 40 mm up with nothing under it: the base floats 40 mm above the plate.
  rig.mounts[0].T_robot_sensor.translation().z() = 0.5 + 0.038 + 0.04;
  const std::optional<double> gap = geometry::housing_gap(rig, library, 0);
  REQUIRE(gap);
  CHECK_THAT(*gap, WithinAbs(0.04, 0.0005));
  const std::vector<model::Diagnostic> warnings = metrics::floating_warnings(rig, library);
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings[0].message(), Catch::Contains("floats about 40 mm"));
  // 3 mm up is a shim's gap: held.
  rig.mounts[0].T_robot_sensor.translation().z() = 0.5 + 0.038 + 0.003;
  CHECK_FALSE(geometry::housing_gap(rig, library, 0));
}
