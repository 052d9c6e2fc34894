// A costmap run's report written from a result built by hand (issue 51 item 3: a report is
// data, so its writers run without the simulation). Expected values are the hand-set fields,
// or what they mean: a 0.1 s period is a 10 Hz rate, a latency is driver + filtering time.
#include "rigdesign/report/costmap_run_report.hpp"

#include <catch2/catch.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

namespace rigdesign {
namespace {

report::CostmapRun collided_run() {
  report::CostmapRun run;
  run.label = "voxel + Hit Layer";
  run.layer = "voxel";
  run.hit_layer = true;
  run.folder = "out";
  run.frames = 3;
  scenarios::ScenarioResult& result = run.result;
  result.collided = true;
  result.collision_object = "wall";
  result.collision_time = 3.2;
  result.collision_position = model::Vec2(1.0, -0.5);
  result.min_clearance = std::numeric_limits<double>::infinity();
  result.update_seconds = {0.002, 0.004, 0.003};
  result.planner_seconds = {0.001};
  // Two mounts in the rig, one timing: the sensors list holds what both have.
  scenarios::MountTiming timing;
  timing.period = 0.1;
  timing.phase = 0.02;
  timing.driver = 0.005;
  timing.filtering = 0.001;
  result.timings = {timing};
  result.trajectory = {{0.0, {}}, {3.2, {}}};
  return run;
}

TEST_CASE("costmap_run_json: the run's fields, undefined values as null", "[report]") {
  const report::CostmapContext context{"cart", {"front", "back"}, "stationary", 7};
  const nlohmann::json summary = report::costmap_run_json(context, collided_run());
  CHECK(summary["rig"] == "cart");
  CHECK(summary["scenario"] == "stationary");
  CHECK(summary["seed"] == 7);
  CHECK(summary["layer"] == "voxel");
  CHECK(summary["hit_layer"] == true);
  CHECK(summary["observation_persistence"] == false);
  CHECK(summary["collided"] == true);
  CHECK(summary["collision_time_s"].get<double>() == Approx(3.2));
  CHECK(summary["collision_object"] == "wall");
  CHECK(summary["min_clearance_m"].is_null());  // infinite: nothing in the height band
  CHECK(summary["frames"] == 3);
  REQUIRE(summary["sensors"].size() == 1);
  CHECK(summary["sensors"][0]["mount"] == "front");
  CHECK(summary["sensors"][0]["rate_hz"].get<double>() == Approx(10.0));
  CHECK(summary["sensors"][0]["latency_s"].get<double>() == Approx(0.006));
  CHECK(summary["trajectory"].size() == 2);
}

TEST_CASE("print_costmap_run: the collision and the clearance in words", "[report]") {
  std::ostringstream out;
  report::print_costmap_run(collided_run(), out);
  const std::string text = out.str();
  CHECK(text.rfind("voxel + Hit Layer\n", 0) == 0);
  CHECK(
      text.find("  collision: collision with wall at t = 3.20 s (robot at x 1.00, y -0.50 m)\n") !=
      std::string::npos);
  CHECK(text.find("  minimum clearance: no obstacle in the body's height band\n") !=
        std::string::npos);
  CHECK(text.find("3 frame(s) in frames/") != std::string::npos);
}

}  // namespace
}  // namespace rigdesign
