#include "rigdesign/metrics/requirement_check.hpp"

#include <algorithm>
#include <catch2/catch.hpp>

#include "rigdesign/model/units.hpp"

using namespace rigdesign;

namespace {

// One 15 Hz sensor with a 2 deg step, 30 mm noise, blind in sunlight: the VLP-16's numbers
// with the Azure Kinect's lighting, so every requirement has something to bite on.
struct Fixture {
  SensorLibrary library;
  Rig rig;
  Fixture() {
    Sensor sensor;
    sensor.id = "s";
    SensorMode mode;
    mode.id = "m";
    mode.frequency = 15;
    mode.max_range = 10;
    mode.angular_resolution_h = deg_to_rad(2.0);
    mode.noise.a = 0.03;
    mode.light = {true, true, false};
    sensor.modes.push_back(mode);
    library.sensors.push_back(sensor);
    rig.body.radius = 0.45;
    rig.body.height = 1.0;
    rig.distance_of_interest = 3.5;
    Mount mount;
    mount.id = "only";
    mount.sensor_id = "s";
    mount.mode_id = "m";
    rig.mounts.push_back(mount);
  }
  std::vector<RequirementResult> judge(const Requirements& requirements) const {
    return evaluate_requirements(rig, compute_resultant(rig, library), requirements);
  }
};

const RequirementResult& find(const std::vector<RequirementResult>& results,
                              const std::string& id) {
  const auto it = std::find_if(results.begin(), results.end(),
                               [&](const RequirementResult& r) { return r.id == id; });
  REQUIRE(it != results.end());
  return *it;
}

}  // namespace

TEST_CASE("R4 and R5 bound F from below by speed over travel between frames") {
  Fixture fixture;
  Requirements requirements;
  requirements.distance = 3.5;
  requirements.robot_speed = MotionBetweenFrames{2.0, 0.1, {}};       // needs 20 Hz
  requirements.object_dynamics = MotionBetweenFrames{1.5, 0.15, {}};  // needs 10 Hz
  const auto results = fixture.judge(requirements);
  const RequirementResult& r5 = find(results, "R5");
  CHECK(r5.verdict == Verdict::fail);
  CHECK(*r5.required == Approx(20.0));
  CHECK(*r5.actual == 15.0);
  CHECK(r5.limiting_mounts == std::vector<std::string>{"only"});
  CHECK(find(results, "R4").verdict == Verdict::pass);
  CHECK(requirements.required_frequency() == Approx(20.0));
}

TEST_CASE("R6 needs the ray spacing at d no wider than the smallest obstacle") {
  Fixture fixture;
  Requirements requirements;
  requirements.distance = 3.5;
  requirements.smallest_obstacle = 0.10;  // 3.5 m * tan 2 deg = 122 mm > 100 mm
  CHECK(find(fixture.judge(requirements), "R6").verdict == Verdict::fail);
  requirements.smallest_obstacle = 0.13;
  CHECK(find(fixture.judge(requirements), "R6").verdict == Verdict::pass);
}

TEST_CASE("R7 compares the noisiest sensor with the allowed noise, R8 every condition") {
  Fixture fixture;
  Requirements requirements;
  requirements.distance = 3.5;
  requirements.max_noise = 0.029;
  requirements.lighting = {LightCondition::dark, LightCondition::sunlight};
  const auto results = fixture.judge(requirements);
  CHECK(find(results, "R7").verdict == Verdict::fail);
  const RequirementResult& r8 = find(results, "R8");
  CHECK(r8.verdict == Verdict::fail);
  CHECK(r8.limiting_mounts == std::vector<std::string>{"only"});
  requirements.lighting = {LightCondition::dark, LightCondition::indoor};
  CHECK(find(fixture.judge(requirements), "R8").verdict == Verdict::pass);
}

TEST_CASE("R1 and R3 check the rig describes the application's body and range") {
  Fixture fixture;
  Requirements requirements;
  requirements.distance = 4.0;
  requirements.body_radius = 0.40;
  requirements.body_height = 1.0;
  const auto results = fixture.judge(requirements);
  CHECK(find(results, "R1").verdict == Verdict::fail);
  CHECK(find(results, "R3").verdict == Verdict::fail);
}
