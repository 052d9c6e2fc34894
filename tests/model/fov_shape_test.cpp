// The FOV shapes against hand-derived geometry: their flags and names, the steepest ray down
// from the corner rays, and that each shape's boundary crossings split a line into pieces on
// which `contains` does not change.
#include "rigdesign/model/fov_shape.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/sensor.hpp"
#include "rigdesign/model/units.hpp"

using namespace rigdesign;

namespace {

constexpr double kFovPi = 3.141592653589793;

std::vector<std::shared_ptr<const model::FovShape>> every_shape() {
  return {model::pyramid_fov(model::deg_to_rad(87), model::deg_to_rad(58)),
          model::cone_fov(model::deg_to_rad(90)),
          model::band_fov(2 * kFovPi, model::deg_to_rad(-15), model::deg_to_rad(15)),
          model::band_fov(model::deg_to_rad(120), model::deg_to_rad(-30), model::deg_to_rad(60)),
          model::planar_fov(model::deg_to_rad(270), model::deg_to_rad(1))};
}

}  // namespace

TEST_CASE("FOV shapes: names, kinds and one-line summaries", "[model]") {
  const auto shapes = every_shape();
  CHECK(shapes[0]->name() == "pyramid");
  CHECK(shapes[1]->name() == "cone");
  CHECK(shapes[2]->name() == "band");
  CHECK(shapes[4]->name() == "planar");
  CHECK(shapes[0]->is_camera());
  CHECK(shapes[1]->is_camera());
  CHECK_FALSE(shapes[2]->is_camera());
  CHECK_FALSE(shapes[4]->is_camera());
  CHECK(shapes[4]->is_planar_scan());
  CHECK_FALSE(shapes[2]->is_planar_scan());
  CHECK(shapes[0]->summary_deg() == "87 x 58");
  CHECK(shapes[1]->summary_deg() == "cone 90");
  CHECK(shapes[2]->summary_deg() == "360 (-15..15)");
  CHECK(shapes[4]->summary_deg() == "270 planar");
  model::SensorMode lidar;
  lidar.fov = model::FieldOfView(shapes[2]);
  CHECK_FALSE(lidar.is_camera());
  CHECK(model::SensorMode().fov.horizontal() == 0.0);  // a default mode has an empty pyramid
}

TEST_CASE("FOV shapes: the steepest ray down, by hand", "[model]") {
  const model::Mat3 level = model::Mat3::Identity();
  // A level 60 x 40 frustum: along its bottom face z = -x tan 20, the normalised z is
  // tan 20 / sqrt(1 + tan^2 u + tan^2 20), steepest at u = 0: sin 20 deg (not a corner).
  CHECK(model::pyramid_fov(kFovPi / 3, 2 * kFovPi / 9)->steepest_down(level) ==
        Approx(std::sin(kFovPi / 9)).epsilon(1e-12));
  // Rolled 90 deg, its 60 deg side points down: sin 30 deg.
  CHECK(model::pyramid_fov(kFovPi / 3, 2 * kFovPi / 9)
            ->steepest_down(model::rotation_from_rpy(kFovPi / 2, 0, 0)) ==
        Approx(0.5).epsilon(1e-12));
  // A band's lowest beam: sin 15 deg below the plane.
  CHECK(model::band_fov(2 * kFovPi, -kFovPi / 12, kFovPi / 12)->steepest_down(level) ==
        Approx(std::sin(kFovPi / 12)).epsilon(1e-12));
  // A 90 deg cone pitched 10 deg down reaches 55 deg below the horizon.
  const model::Mat3 pitched = model::rotation_from_rpy(0, model::deg_to_rad(10), 0);
  CHECK(model::cone_fov(kFovPi / 2)->steepest_down(pitched) ==
        Approx(std::sin(model::deg_to_rad(55))).epsilon(1e-12));
  // A camera looking up has no ray pointing down.
  const model::Mat3 up = model::rotation_from_rpy(0, -kFovPi / 2, 0);
  CHECK(model::pyramid_fov(kFovPi / 3, kFovPi / 4)->steepest_down(up) < 0.0);
}

TEST_CASE("FOV shapes: directions of the domain lie inside, crossings bound the pieces",
          "[model]") {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const auto& shape : every_shape()) {
    INFO(shape->summary_deg());
    const model::AngularDomain range = shape->domain();
    for (int i = 1; i < 10; ++i) {
      for (int j = 1; j < 10; ++j) {
        const double u = range.u_min + (range.u_max - range.u_min) * i / 10;
        const double v = range.v_min + (range.v_max - range.v_min) * j / 10;
        const model::Vec3 d = shape->direction(u, v);
        CHECK(d.norm() == Approx(1.0));
        CHECK(shape->contains(d));
      }
    }
    // Between two consecutive crossings of a line, `contains` is constant: probe 50 points
    // of every piece of 200 random lines.
    int mixed_pieces = 0;
    for (int line = 0; line < 200; ++line) {
      const model::Vec3 c(unit(rng) * 3, unit(rng) * 3, unit(rng) * 3);
      const model::Vec3 w(unit(rng), unit(rng), unit(rng));
      std::vector<double> cuts = {-10.0, 10.0};
      shape->append_boundary_crossings(c, w, cuts);
      std::sort(cuts.begin(), cuts.end());
      for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double low = std::max(cuts[k], -10.0), high = std::min(cuts[k + 1], 10.0);
        if (high - low < 1e-6) continue;
        const bool first = shape->contains(c + (low + 1e-7 * (high - low)) * w);
        for (int probe = 1; probe <= 50; ++probe) {
          const double t = low + (high - low) * (probe - 0.5) / 50;
          if (shape->contains(c + t * w) != first) {
            ++mixed_pieces;
            break;
          }
        }
      }
    }
    CHECK(mixed_pieces == 0);
  }
}

TEST_CASE("FOV shapes: a triangle a shape excludes holds no direction of the FOV", "[model]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const auto& shape : every_shape()) {
    INFO(shape->summary_deg());
    int excluded = 0;
    for (int trial = 0; trial < 2000; ++trial) {
      const std::array<model::Vec3, 3> q = {model::Vec3(unit(rng), unit(rng), unit(rng)) * 2,
                                            model::Vec3(unit(rng), unit(rng), unit(rng)) * 2,
                                            model::Vec3(unit(rng), unit(rng), unit(rng)) * 2};
      if (!shape->excludes_triangle(q)) continue;
      ++excluded;
      for (int a = 0; a <= 10; ++a) {  // barycentric samples of the triangle
        for (int b = 0; a + b <= 10; ++b) {
          const model::Vec3 p = (a * q[0] + b * q[1] + (10 - a - b) * q[2]) / 10.0;
          if (p.norm() > 1e-9) CHECK_FALSE(shape->contains(p));
        }
      }
    }
    CHECK(excluded > 0);  // the test exercised the exclusion
  }
}
