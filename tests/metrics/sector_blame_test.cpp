// Issue 39: a sector's verdict points at what decides it. A camera (60 x 40 deg, 4 m) at the
// back of a 0.2 m cylinder 0.5 m tall, 0.3 m up, looking forward: every ray it sends ahead
// enters the cylinder (the steepest, 20 deg up, is at 0.3 + 0.41 tan 20 = 0.45 m < 0.5 m when
// it reaches the front edge; a ray 30 deg to the side passes 0.21 sin 30 = 0.105 m < 0.2 m from
// the axis), so the front sector fails and the body, not the camera, is to blame: R2 points at
// the rig's `body` line. Turned to look backwards it sees the back sector: the camera's pose.
#include "rigdesign/metrics/sector_blame.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

#include "rigdesign/io/config/requirements_loader.hpp"
#include "rigdesign/io/config/rig_loader.hpp"
#include "rigdesign/io/config/sensor_library_loader.hpp"
#include "rigdesign/metrics/requirement_check.hpp"
#include "rigdesign/metrics/resultant.hpp"
#include "support/fixture_files.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

const std::string kBlockedRig = R"(name: camera behind the body
body: {radius: 0.2, height: 0.5}
distance_of_interest: 3.0
mounts:
  - id: rear_cam
    sensor: cam
    mode: m30
    pose: {xyz: [-0.21, 0, 0.3], rpy_deg: [0, 0, 0]}
)";

const std::string kSectors = R"(name: ahead and behind
range: {distance: 3.0}
sectors:
  - {name: front, from_deg: -10, to_deg: 10, min_complete_coverage: 0.1, min_floor_coverage: 0}
  - {name: back, from_deg: 170, to_deg: 190, min_complete_coverage: 0.1, min_floor_coverage: 0}
)";

}  // namespace

TEST_CASE("a sector the body hides points at the body, one a mount misses at the mount",
          "[metrics][blame]") {
  test::TempFolder folder;
  const model::SensorLibrary library =
      io::load_sensor_library(folder.write("sensors.yaml", test::kLibrary));
  const model::Requirements requirements =
      io::load_requirements(folder.write("req.yaml", kSectors));
  const model::Rig blocked = io::load_rig(folder.write("rig.yaml", kBlockedRig));
  const metrics::SectorBlame ahead = metrics::sector_blame(blocked, library, 0.0, false);
  REQUIRE(ahead.mount);
  CHECK(ahead.body);
  CHECK(ahead.hidden > 0.1);
  CHECK(ahead.where.line == 2);  // `body:` in the rig above
  const metrics::RigCoverage coverage =
      metrics::compute_coverage(blocked, library, requirements.sectors);
  const std::vector<metrics::RequirementResult> results = metrics::evaluate_requirements(
      blocked, metrics::compute_resultant(blocked, library), requirements, &coverage, &library);
  const auto front = std::find_if(results.begin(), results.end(),
                                  [](const auto& r) { return r.field == "sectors.front"; });
  REQUIRE(front != results.end());
  CHECK(front->verdict == metrics::Verdict::fail);
  CHECK(front->annotated_where().line == 2);
  CHECK(front->limiting_mounts == std::vector<std::string>{"rear_cam"});
  CHECK(front->explanation.find("the body hides") != std::string::npos);
  // Turned round (yaw 180) it looks away from the body: the back sector rests on its pose.
  std::string turned = kBlockedRig;
  turned.replace(turned.find("[0, 0, 0]"), 9, "[0, 0, 180]");
  const model::Rig behind = io::load_rig(folder.write("turned.yaml", turned));
  const metrics::SectorBlame back = metrics::sector_blame(behind, library, 3.14159265358979, false);
  REQUIRE(back.mount);
  CHECK_FALSE(back.body);
  CHECK(back.where.line == 8);  // rear_cam's pose
}
