// The TurtleBot 4's self-occlusion three ways: the exact path (shadow intervals, CGAL
// polygons), the raster path, and an independent sampler that casts a ray from each sensor to
// points of the cross-section through a CGAL AABB tree of the body's triangles (vertical
// cylinders tessellated finely for it), skipping each sensor's own link as its housing.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/coverage.hpp"
#include "rigdesign/sim/ray_caster.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;

namespace {

// A vertical cylinder as a 512-sided prism: within r (1 - cos(pi / 512)) = 1.9e-5 r of round.
model::TriangleMesh prism(const model::VerticalCylinder& c) {
  constexpr int kSides = 512;
  model::TriangleMesh mesh;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2 * std::numbers::pi * k / kSides;
    const model::Vec2 p = c.centre + c.radius * model::Vec2(std::cos(a), std::sin(a));
    mesh.vertices.emplace_back(p.x(), p.y(), c.z_min);
    mesh.vertices.emplace_back(p.x(), p.y(), c.z_max);
  }
  mesh.vertices.emplace_back(c.centre.x(), c.centre.y(), c.z_min);
  mesh.vertices.emplace_back(c.centre.x(), c.centre.y(), c.z_max);
  const int bottom = 2 * kSides;
  for (int k = 0; k < kSides; ++k) {
    const int a = 2 * k;
    const int b = 2 * ((k + 1) % kSides);
    mesh.triangles.push_back({a, b, a + 1});
    mesh.triangles.push_back({b, b + 1, a + 1});
    mesh.triangles.push_back({bottom, b, a});
    mesh.triangles.push_back({bottom + 1, a + 1, b + 1});
  }
  return mesh;
}

// The body without `own_link`, as one mesh for the ray caster.
model::TriangleMesh body_without(const model::RobotBody& body, const std::string& own_link) {
  model::TriangleMesh mesh;
  for (const model::BodyPart& part : body.parts) {
    if (part.link == own_link) continue;
    mesh.append(part.cylinder ? prism(*part.cylinder) : part.triangles);
  }
  return mesh;
}

}  // namespace

TEST_CASE("TurtleBot 4: exact, raster and a ray-cast sampler agree on the self-occlusion") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  const model::Rig rig = io::load_rig(test::source_path("rigs/turtlebot4.yaml"));
  REQUIRE(rig.body.has_parts());
  const metrics::RigCoverage coverage = metrics::compute_coverage(rig, library, {});
  // The raster path's stated error against the exact path, over all 360 angles.
  CHECK(coverage.raster_error_complete <= 0.02);
  // The sampler's FOV test needs no body: a body of zero size occludes nothing.
  model::RobotBody nothing;
  const geometry::BodyOccluder no_body(nothing);
  const std::vector<std::string> own_links = {"rplidar_link", "oakd_link"};
  std::vector<geometry::MountedFov> fovs;
  std::vector<sim::RayCaster> casters;
  for (std::size_t i = 0; i < rig.mounts.size(); ++i) {
    const model::Mount& mount = rig.mounts[i];
    fovs.emplace_back(*library.find(mount.sensor_id)->find_mode(mount.mode_id),
                      mount.T_robot_sensor, no_body, "");
    casters.emplace_back(body_without(rig.body, own_links[i]));
  }
  constexpr int kColumns = 120;
  constexpr int kRows = 40;
  for (int degrees = 0; degrees < 360; degrees += 15) {
    const double theta = degrees * std::numbers::pi / 180;
    const metrics::SectionView view = metrics::section_view(rig, library, theta);
    const geometry::SectionFrame& frame = view.frame;
    int seen = 0;
    for (int c = 0; c < kColumns; ++c) {
      for (int r = 0; r < kRows; ++r) {
        const model::Vec3 p = frame.point(frame.r + (c + 0.5) * frame.width() / kColumns,
                                          (r + 0.5) * frame.h / kRows);
        for (std::size_t i = 0; i < fovs.size(); ++i) {
          if (!fovs[i].sees(p)) continue;
          const model::Vec3 ray = p - fovs[i].origin();
          const auto hit = casters[i].first_hit(fovs[i].origin(), ray.normalized());
          if (!hit || *hit >= ray.norm() - 1e-9) {
            ++seen;
            break;
          }
        }
      }
    }
    const double sampled = static_cast<double>(seen) / (kColumns * kRows);
    INFO("theta " << degrees << " deg: exact " << view.complete << ", raster "
                  << coverage.angles[static_cast<std::size_t>(degrees)].complete_raster
                  << ", sampled " << sampled);
    // Cell-centre sampling of a region bounded by straight and curved edges: its error is
    // the share of boundary cells, under 2 % on this 120 x 40 grid for these sections.
    CHECK(std::abs(sampled - view.complete) <= 0.02);
    CHECK(std::abs(coverage.angles[static_cast<std::size_t>(degrees)].complete - view.complete) <=
          1e-9);
  }
}
