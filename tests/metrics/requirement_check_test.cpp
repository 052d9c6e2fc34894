#include "rigdesign/metrics/requirement_check.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

#include "rigdesign/model/units.hpp"

using namespace rigdesign;

namespace {

// One 15 Hz sensor with a 2 deg step, 30 mm noise, blind in sunlight: the VLP-16's numbers
// with the Azure Kinect's lighting, so every requirement has something to bite on.
struct Fixture {
  model::SensorLibrary library;
  model::Rig rig;
  Fixture() {
    model::Sensor sensor;
    sensor.id = "s";
    model::SensorMode mode;
    mode.id = "m";
    mode.frequency = 15;
    mode.max_range = 10;
    mode.angular_resolution_h = model::deg_to_rad(2.0);
    mode.noise.a = 0.03;
    mode.light = {true, true, false};
    sensor.modes.push_back(mode);
    library.sensors.push_back(sensor);
    rig.body.radius = 0.45;
    rig.body.height = 1.0;
    rig.distance_of_interest = 3.5;
    model::Mount mount;
    mount.id = "only";
    mount.sensor_id = "s";
    mount.mode_id = "m";
    rig.mounts.push_back(mount);
  }
  std::vector<metrics::RequirementResult> judge(const model::Requirements& requirements) const {
    return metrics::evaluate_requirements(rig, metrics::compute_resultant(rig, library),
                                          requirements);
  }
};

const metrics::RequirementResult& find(const std::vector<metrics::RequirementResult>& results,
                                       const std::string& id) {
  const auto it = std::find_if(results.begin(), results.end(),
                               [&](const metrics::RequirementResult& r) { return r.id == id; });
  REQUIRE(it != results.end());
  return *it;
}

}  // namespace

TEST_CASE("R4 and R5 bound F from below by speed over travel between frames") {
  Fixture fixture;
  model::Requirements requirements;
  requirements.distance = 3.5;
  requirements.robot_speed = model::MotionBetweenFrames{2.0, 0.1, {}};       // needs 20 Hz
  requirements.object_dynamics = model::MotionBetweenFrames{1.5, 0.15, {}};  // needs 10 Hz
  const auto results = fixture.judge(requirements);
  const metrics::RequirementResult& r5 = find(results, "R5");
  CHECK(r5.verdict == metrics::Verdict::fail);
  CHECK(*r5.required == Approx(20.0));
  CHECK(*r5.actual == 15.0);
  CHECK(r5.limiting_mounts == std::vector<std::string>{"only"});
  CHECK(find(results, "R4").verdict == metrics::Verdict::pass);
  CHECK(requirements.required_frequency() == Approx(20.0));
}

TEST_CASE("R6 needs the ray spacing at d no wider than the smallest obstacle") {
  Fixture fixture;
  model::Requirements requirements;
  requirements.distance = 3.5;
  requirements.smallest_obstacle = 0.10;  // 3.5 m * tan 2 deg = 122 mm > 100 mm
  CHECK(find(fixture.judge(requirements), "R6").verdict == metrics::Verdict::fail);
  requirements.smallest_obstacle = 0.13;
  CHECK(find(fixture.judge(requirements), "R6").verdict == metrics::Verdict::pass);
}

TEST_CASE("R7 compares the noisiest sensor with the allowed noise, R8 every condition") {
  Fixture fixture;
  model::Requirements requirements;
  requirements.distance = 3.5;
  requirements.max_noise = 0.029;
  requirements.lighting = {model::LightCondition::dark, model::LightCondition::sunlight};
  const auto results = fixture.judge(requirements);
  CHECK(find(results, "R7").verdict == metrics::Verdict::fail);
  const metrics::RequirementResult& r8 = find(results, "R8");
  CHECK(r8.verdict == metrics::Verdict::fail);
  CHECK(r8.limiting_mounts == std::vector<std::string>{"only"});
  requirements.lighting = {model::LightCondition::dark, model::LightCondition::indoor};
  CHECK(find(fixture.judge(requirements), "R8").verdict == metrics::Verdict::pass);
}

TEST_CASE("R1 and R3 check the rig describes the application's body and range") {
  Fixture fixture;
  model::Requirements requirements;
  requirements.distance = 4.0;
  requirements.body_radius = 0.40;
  requirements.body_height = 1.0;
  const auto results = fixture.judge(requirements);
  CHECK(find(results, "R1").verdict == metrics::Verdict::fail);
  CHECK(find(results, "R3").verdict == metrics::Verdict::fail);
}

// Issue 30 item 6: a verdict and the sign of its margin agree. The coverage is built by hand,
// so every number below is the test's own.
TEST_CASE("R2 judges the tighter of SC complete and floor, unrounded, margin sign agreeing") {
  const Fixture fixture;
  model::Requirements requirements;
  model::SectorRequirement sector;
  sector.name = "front";
  sector.min_complete_coverage = 0.54;
  sector.min_floor_coverage = 0.5;
  requirements.sectors = {sector};
  const auto judged = [&](double complete, double floor) {
    metrics::RigCoverage coverage;
    metrics::SectorCoverage measured;
    measured.sector = sector;
    measured.complete.min = complete;
    measured.floor.min = floor;
    measured.pass = metrics::judged_share(complete) >= sector.min_complete_coverage &&
                    metrics::judged_share(floor) >= sector.min_floor_coverage;
    coverage.sectors = {measured};
    return find(metrics::evaluate_requirements(
                    fixture.rig, metrics::compute_resultant(fixture.rig, fixture.library),
                    requirements, &coverage),
                "R2");
  };
  // 0.53996 < 0.54: the case fails now, with a negative margin.
  const metrics::RequirementResult short_by_little = judged(0.53996, 0.9);
  CHECK(short_by_little.verdict == metrics::Verdict::fail);
  CHECK(*short_by_little.margin() == Approx(-0.00004).margin(1e-12));
  CHECK(short_by_little.metric == "SC");
  // Complete has 0.06 to spare, floor only 0.01: the floor is what the verdict rests on.
  const metrics::RequirementResult floor_binds = judged(0.60, 0.51);
  CHECK(floor_binds.verdict == metrics::Verdict::pass);
  CHECK(floor_binds.metric == "SC floor");
  CHECK(*floor_binds.margin() == Approx(0.01));
  // A floor below its requirement fails even when SC complete passes, margin negative.
  const metrics::RequirementResult floor_fails = judged(0.60, 0.49);
  CHECK(floor_fails.verdict == metrics::Verdict::fail);
  CHECK(*floor_fails.margin() < 0.0);
  CHECK(metrics::judged_share(0.99995) == 1.0);  // a fully covered section's exact-path gaps
  CHECK(metrics::judged_share(0.9998) == 0.9998);
}
