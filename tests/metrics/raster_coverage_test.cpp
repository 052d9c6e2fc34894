// Issue 37: the studio recomputes only the mount an edit changed. Whatever the order of edits,
// the kept rasters must give what a fresh raster run on the edited rig gives, bit for bit.
#include "rigdesign/metrics/raster_coverage.hpp"

#include <catch2/catch.hpp>
#include <string>

#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"

using namespace rigdesign;

namespace {

void require_same(const metrics::RigCoverage& kept, const metrics::RigCoverage& fresh) {
  REQUIRE(kept.angles.size() == fresh.angles.size());
  for (std::size_t a = 0; a < kept.angles.size(); ++a) {
    INFO("angle " << a);
    CHECK(kept.angles[a].complete == fresh.angles[a].complete);
    CHECK(kept.angles[a].floor == fresh.angles[a].floor);
    CHECK(kept.angles[a].redundancy == fresh.angles[a].redundancy);
    CHECK(kept.angles[a].mount_sees == fresh.angles[a].mount_sees);
    CHECK(kept.angles[a].coarsest_mount == fresh.angles[a].coarsest_mount);
  }
  CHECK(kept.mount_ids == fresh.mount_ids);
  REQUIRE(kept.sectors.size() == fresh.sectors.size());
  for (std::size_t s = 0; s < kept.sectors.size(); ++s) {
    CHECK(kept.sectors[s].complete.min == fresh.sectors[s].complete.min);
    CHECK(kept.sectors[s].floor.min == fresh.sectors[s].floor.min);
    CHECK(kept.sectors[s].pass == fresh.sectors[s].pass);
  }
  REQUIRE(kept.without_each.size() == fresh.without_each.size());
  for (std::size_t m = 0; m < kept.without_each.size(); ++m)
    CHECK(kept.without_each[m].complete.mean == fresh.without_each[m].complete.mean);
}

}  // namespace

TEST_CASE("raster coverage kept per mount: an edit gives what a fresh run gives", "[metrics]") {
  const model::SensorLibrary library = io::load_sensor_library(test::source_path("sensors.yaml"));
  model::Rig rig = io::load_rig(test::source_path("rigs/ur_cleaner.yaml"));
  metrics::CoverageSettings settings;
  settings.step = model::deg_to_rad(5.0);
  settings.exact = false;
  model::SectorRequirement front;
  front.from = model::deg_to_rad(-45.0);
  front.to = model::deg_to_rad(45.0);
  front.min_complete_coverage = 0.5;
  front.min_floor_coverage = 0.9;
  const std::vector<model::SectorRequirement> sectors = {front};

  metrics::RasterCoverage kept(rig, library, settings);
  require_same(kept.coverage(sectors), metrics::compute_coverage(rig, library, sectors, settings));

  // The front camera 10 cm higher and pitched 15 degrees further down.
  model::Mount moved = rig.mounts.front();
  moved.T_robot_sensor.translation().z() += 0.10;
  moved.T_robot_sensor.linear() =
      moved.T_robot_sensor.linear() *
      Eigen::AngleAxisd(model::deg_to_rad(15.0), model::Vec3::UnitY()).toRotationMatrix();
  kept.set_mount(0, moved);
  rig.mounts.front() = moved;
  require_same(kept.coverage(sectors), metrics::compute_coverage(rig, library, sectors, settings));

  // The second mount removed, then put back at the end.
  const model::Mount second = rig.mounts[1];
  kept.remove_mount(1);
  rig.mounts.erase(rig.mounts.begin() + 1);
  require_same(kept.coverage(sectors), metrics::compute_coverage(rig, library, sectors, settings));
  kept.add_mount(second);
  rig.mounts.push_back(second);
  CHECK(kept.mount_count() == rig.mounts.size());
  require_same(kept.coverage(sectors), metrics::compute_coverage(rig, library, sectors, settings));
}
