// Self-occlusion by a robot description's collision geometry against cases solved by hand:
// a spinning lidar on the axis of four standoffs (vertical cylinders of radius r at distance
// D) is blind exactly where the standoffs are, over an azimuth width of 2 asin(r / D).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <sstream>

#include "rigdesign/io/robot/collision_body.hpp"
#include "rigdesign/io/robot/robot_description_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.02;   // r: standoff radius [m]
constexpr double kDistance = 0.3;  // D: standoff axis from the robot's axis [m]
constexpr double kLidarZ = 0.2;    // lidar height [m]
constexpr double kStandoffTop = 0.5;

// A 360-degree band of +-15 degrees elevation, no minimum range.
model::SensorLibrary band_library() {
  model::SensorMode mode;
  mode.id = "band";
  mode.fov = model::FieldOfView(
      model::band_fov(2 * kPi, model::deg_to_rad(-15.0), model::deg_to_rad(15.0)));
  mode.min_range = 0.0;
  mode.max_range = 10.0;
  mode.frequency = 10;
  mode.angular_resolution_h = model::deg_to_rad(0.2);
  mode.angular_resolution_v = model::deg_to_rad(2.0);
  model::Sensor sensor;
  sensor.id = "lidar";
  sensor.modes.push_back(mode);
  model::SensorLibrary library;
  library.sensors.push_back(sensor);
  return library;
}

// A description: a floor plate link and four standoff links at azimuths 45, 135, 225, 315
// degrees, each with `geometry` as its collision (a <cylinder> or a <mesh>).
std::string standoffs_urdf(const std::string& geometry) {
  std::ostringstream urdf;
  urdf.precision(17);
  urdf << "<robot name=\"standoffs\">\n  <link name=\"base_footprint\"/>\n";
  for (int k = 0; k < 4; ++k) {
    const double azimuth = kPi / 4 + k * kPi / 2;
    urdf << "  <link name=\"standoff" << k << "\"><collision><geometry>" << geometry
         << "</geometry></collision></link>\n"
         << "  <joint name=\"j" << k << "\" type=\"fixed\"><parent link=\"base_footprint\"/>"
         << "<child link=\"standoff" << k << "\"/><origin xyz=\"" << kDistance * std::cos(azimuth)
         << " " << kDistance * std::sin(azimuth) << " " << kStandoffTop / 2 << "\"/></joint>\n";
  }
  urdf << "</robot>\n";
  return urdf.str();
}

// An ASCII STL of a prism with `sides` corners on a circle of radius r (inscribed polygon),
// from z = -h/2 to h/2 around its own axis.
std::string prism_stl(int sides, double radius, double height) {
  std::ostringstream stl;
  stl.precision(17);
  const auto vertex = [&](int k, double z) {
    const double a = 2 * kPi * k / sides;
    stl << "      vertex " << radius * std::cos(a) << " " << radius * std::sin(a) << " " << z
        << "\n";
  };
  const auto facet = [&](auto&& corners) {
    stl << "  facet normal 0 0 0\n    outer loop\n";
    corners();
    stl << "    endloop\n  endfacet\n";
  };
  stl << "solid prism\n";
  for (int k = 0; k < sides; ++k) {
    facet([&] { vertex(k, -height / 2), vertex(k + 1, -height / 2), vertex(k + 1, height / 2); });
    facet([&] { vertex(k, -height / 2), vertex(k + 1, height / 2), vertex(k, height / 2); });
    facet([&] {
      stl << "      vertex 0 0 " << height / 2 << "\n";
      vertex(k, height / 2), vertex(k + 1, height / 2);
    });
    facet([&] {
      stl << "      vertex 0 0 " << -height / 2 << "\n";
      vertex(k + 1, -height / 2), vertex(k, -height / 2);
    });
  }
  stl << "endsolid prism\n";
  return stl.str();
}

model::Rig standoff_rig(const std::string& urdf_path) {
  io::RobotDescriptionRequest request;
  request.path = urdf_path;
  const model::RobotDescription description = io::load_robot_description(request);
  model::Rig rig;
  rig.body = io::body_from_description(description, "base_footprint");
  rig.distance_of_interest = 2.0;
  model::Mount mount;
  mount.id = "lidar";
  mount.sensor_id = "lidar";
  mount.mode_id = "band";
  mount.T_robot_sensor = model::pose_from_xyz_rpy({0, 0, kLidarZ}, {0, 0, 0});
  rig.mounts.push_back(mount);
  return rig;
}

double complete_at(const model::Rig& rig, const model::SensorLibrary& library, double theta) {
  return metrics::section_view(rig, library, theta).complete;
}

}  // namespace

TEST_CASE("standoffs hide exactly 2 asin(r / D) of azimuth each from a lidar on their axis") {
  const model::SensorLibrary library = band_library();
  test::TempFolder folder;
  const std::string cylinder = "<cylinder radius=\"" + std::to_string(kRadius) + "\" length=\"" +
                               std::to_string(kStandoffTop) + "\"/>";
  const model::Rig rig = standoff_rig(folder.write("standoffs.urdf", standoffs_urdf(cylinder)));
  REQUIRE(rig.body.parts.size() == 4);
  REQUIRE(rig.body.parts[0].cylinder.has_value());  // vertical: kept round, exact
  const double half_width = std::asin(kRadius / kDistance);
  // Beyond the standoff the column from z = 0 to the body's top is seen by the band where
  // unshadowed; away from the standoffs the section is the same at every azimuth.
  const double open = complete_at(rig, library, 0.0);
  REQUIRE(open > 0.1);
  for (int k = 0; k < 4; ++k) {
    const double centre = kPi / 4 + k * kPi / 2;
    INFO("standoff " << k);
    for (const double side : {-1.0, 1.0}) {
      const double inside = centre + side * (half_width - 1e-4);
      const double outside = centre + side * (half_width + 1e-4);
      // The band's whole elevation range meets the standoff (it spans -33.7 to 45 degrees
      // from the lidar), so inside the wedge nothing beyond rho = D - r is seen.
      CHECK(complete_at(rig, library, inside) < open - 0.5);
      CHECK_THAT(complete_at(rig, library, outside), WithinAbs(open, 1e-9));
    }
  }
  SECTION("the same standoffs as STL meshes, within their tessellation") {
    // A 64-sided inscribed prism's silhouette from the axis lies between r cos(pi / 64) and r
    // from its centre line, so its half-width lies in [asin(r cos(pi/64) / D), asin(r / D)].
    folder.write("standoff.stl", prism_stl(64, kRadius, kStandoffTop));
    const model::Rig meshed = standoff_rig(
        folder.write("meshed.urdf", standoffs_urdf("<mesh filename=\"standoff.stl\"/>")));
    REQUIRE_FALSE(meshed.body.parts[0].cylinder.has_value());
    const double narrow = std::asin(kRadius * std::cos(kPi / 64) / kDistance);
    const double centre = kPi / 4;
    CHECK(complete_at(meshed, library, centre + narrow - 1e-4) < open - 0.5);
    CHECK_THAT(complete_at(meshed, library, centre + half_width + 1e-4), WithinAbs(open, 1e-9));
    CHECK(complete_at(meshed, library, centre - narrow + 1e-4) < open - 0.5);
    CHECK_THAT(complete_at(meshed, library, centre - half_width - 1e-4), WithinAbs(open, 1e-9));
  }
}

TEST_CASE("the area to perceive starts at the description's outline at every azimuth") {
  const model::SensorLibrary library = band_library();
  test::TempFolder folder;
  const std::string cylinder = "<cylinder radius=\"" + std::to_string(kRadius) + "\" length=\"" +
                               std::to_string(kStandoffTop) + "\"/>";
  const model::Rig rig = standoff_rig(folder.write("standoffs.urdf", standoffs_urdf(cylinder)));
  // Along a standoff's azimuth the outline is its far side, D + r; between them there is no
  // body, so the area starts on the axis.
  CHECK_THAT(metrics::section_view(rig, library, kPi / 4).frame.r,
             WithinAbs(kDistance + kRadius, 1e-12));
  CHECK_THAT(metrics::section_view(rig, library, 0.0).frame.r, WithinAbs(0.0, 1e-12));
  CHECK_THAT(rig.body.height, WithinAbs(kStandoffTop, 1e-12));
  CHECK_THAT(rig.body.radius, WithinAbs(kDistance + kRadius, 1e-12));
}
