// Paper 2's filtering stages (section 3.2): the throttle that keeps frames at a rate, and the
// radius outlier removal, each checked against cases counted by hand; their YAML keys and
// the errors bad values give; the P2_paper2 preset.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/filters/pipeline_timing.hpp"
#include "rigdesign/filters/radius_outlier.hpp"
#include "rigdesign/io/config/pipeline_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/clouds.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using test::cloud_of;
using test::TempFolder;

namespace {

// Eight points at exact binary fractions (every distance below is exact in float and double),
// radius 0.5 m. Other points within 0.5 m, inclusive, counted by hand:
//   P0 (0, 0, 0):         P1 (0.5, exactly the radius), P2 (0.354), P7 (0.433)  -> 3
//   P1 (0.5, 0, 0):       P0 (0.5), P2 (0.354), P7 (0.433)                     -> 3
//   P2 (0.25, 0.25, 0):   P0, P1 (0.354 each); P7 is 0.559 away                -> 2
//   P3 (2, 0, 0):         P4 (0.5); P1 is 1.5 away                              -> 1
//   P4 (2.5, 0, 0):       P3                                                    -> 1
//   P5, P6 (5, 5, 5):     each other (distance 0)                               -> 1
//   P7 (0.25, -0.25, 0.25): P0, P1 (0.433 each)                                 -> 2
model::PointCloud hand_counted_cloud() {
  return cloud_of({{0.0f, 0.0f, 0.0f},
                   {0.5f, 0.0f, 0.0f},
                   {0.25f, 0.25f, 0.0f},
                   {2.0f, 0.0f, 0.0f},
                   {2.5f, 0.0f, 0.0f},
                   {5.0f, 5.0f, 5.0f},
                   {5.0f, 5.0f, 5.0f},
                   {0.25f, -0.25f, 0.25f}});
}

std::vector<std::uint32_t> radius_inliers(const model::PointCloud& cloud, double radius,
                                          int min_neighbours) {
  return filters::radius_outlier_inliers(cloud, model::RadiusOutlierParams{radius, min_neighbours});
}

// PCL's definition by brute force: kept when at least `min` other points lie within `radius`.
std::vector<std::uint32_t> brute_force_radius_inliers(const std::vector<model::Point3f>& points,
                                                      double radius, int min) {
  std::vector<std::uint32_t> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    int found = 0;
    for (std::size_t j = 0; j < points.size(); ++j) {
      if (j != i && (points[i] - points[j]).cast<double>().norm() <= radius) ++found;
    }
    if (found >= min) kept.push_back(static_cast<std::uint32_t>(i));
  }
  return kept;
}

// Frames 0 .. count-1 of a `frequency` stream through one throttle at `rate`: the kept ones.
std::vector<int> kept_frames(double frequency, double rate, int count) {
  filters::PipelineStream stream(model::Pipeline{"t", {model::ThrottleParams{rate}}});
  const model::PointCloud frame = cloud_of({{1.0f, 0.0f, 0.0f}});
  std::vector<int> kept;
  for (int i = 0; i < count; ++i) {
    if (stream.run(frame, static_cast<double>(i) / frequency)) kept.push_back(i);
  }
  return kept;
}

}  // namespace

TEST_CASE("radius outlier removal keeps the hand-counted points", "[filters]") {
  const model::PointCloud cloud = hand_counted_cloud();
  using Kept = std::vector<std::uint32_t>;
  CHECK(radius_inliers(cloud, 0.5, 1) == Kept{0, 1, 2, 3, 4, 5, 6, 7});
  CHECK(radius_inliers(cloud, 0.5, 2) == Kept{0, 1, 2, 7});
  CHECK(radius_inliers(cloud, 0.5, 3) == Kept{0, 1});
  CHECK(radius_inliers(cloud, 0.5, 4).empty());
  // Just under the radius, P0-P1 and P3-P4 (0.5 apart) are no longer neighbours: P0 and P1
  // keep P2 and P7 (2 each), P3 and P4 have none.
  CHECK(radius_inliers(cloud, 0.49, 2) == Kept{0, 1, 2, 7});
  CHECK(radius_inliers(cloud, 0.49, 1) == Kept{0, 1, 2, 5, 6, 7});
  const model::PointCloud kept =
      filters::radius_outlier_removal(cloud, model::RadiusOutlierParams{0.5, 3});
  REQUIRE(kept.size() == 2);
  CHECK(kept.points[1] == model::Point3f(0.5f, 0.0f, 0.0f));
  CHECK(filters::radius_outlier_removal(model::PointCloud{}).empty());
}

TEST_CASE("radius outlier removal equals a brute-force count", "[filters]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<model::Point3f> points;
  for (int i = 0; i < 1500; ++i) points.emplace_back(unit(rng), unit(rng), 0.2f * unit(rng));
  // A few far loners stretch the box, so the grid's cells grow beyond the radius.
  points.emplace_back(40.0f, 0.0f, 0.0f);
  points.emplace_back(0.0f, 40.0f, 10.0f);
  points.emplace_back(40.0f, 40.0f, 10.0f);
  const model::PointCloud cloud = cloud_of(points);
  for (const double radius : {0.01, 0.04, 0.1}) {
    for (const int min : {1, 3, 8}) {
      INFO("radius " << radius << ", min " << min);
      CHECK(radius_inliers(cloud, radius, min) == brute_force_radius_inliers(points, radius, min));
    }
  }
}

TEST_CASE("radius outlier removal refuses a radius or a count that is not positive", "[filters]") {
  const model::PointCloud cloud = hand_counted_cloud();
  CHECK_THROWS_AS(radius_inliers(cloud, 0.0, 2), model::InputError);
  CHECK_THROWS_AS(radius_inliers(cloud, 0.5, 0), model::InputError);
}

TEST_CASE("throttle keeps the frame due at each multiple of its period", "[filters]") {
  // 30 Hz to 2 Hz: every 15th frame. 25 Hz to 5 Hz: every 5th.
  CHECK(kept_frames(30.0, 2.0, 46) == std::vector<int>{0, 15, 30, 45});
  CHECK(kept_frames(25.0, 5.0, 21) == std::vector<int>{0, 5, 10, 15, 20});
  // 15 Hz to 2 Hz: the first frame at or after 0, 0.5, 1, 1.5, 2 s: i / 15 >= k / 2, i.e.
  // i = 0, 8 (7.5), 15, 23 (22.5), 30. The long-run rate is 2 Hz, not 15 / 8.
  CHECK(kept_frames(15.0, 2.0, 31) == std::vector<int>{0, 8, 15, 23, 30});
  // A rate at or above the sensor's keeps every frame.
  CHECK(kept_frames(10.0, 10.0, 5) == std::vector<int>{0, 1, 2, 3, 4});
  CHECK(kept_frames(10.0, 50.0, 5) == std::vector<int>{0, 1, 2, 3, 4});
  // A lone cloud is the first frame of its stream: kept as it is.
  const model::PointCloud frame = hand_counted_cloud();
  std::vector<filters::StageRun> runs;
  const model::PointCloud out =
      filters::run_pipeline(model::Pipeline{"t", {model::ThrottleParams{}}}, frame, &runs);
  CHECK(out.size() == frame.size());
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].stage == "throttle");
  CHECK(runs[0].points_out == frame.size());
}

TEST_CASE("a dropped frame stops the pipeline, the throttled load counts kept frames",
          "[filters]") {
  const model::Pipeline pipeline = *filters::preset_pipeline("P2_paper2");
  REQUIRE(pipeline.stages.size() == 3);
  CHECK(model::stage_name(pipeline.stages[0]) == "throttle");
  CHECK(model::stage_name(pipeline.stages[1]) == "radius_outlier");
  CHECK(model::stage_name(pipeline.stages[2]) == "voxel_grid");
  CHECK(std::get<model::ThrottleParams>(pipeline.stages[0]).rate_hz == 2.0);
  CHECK(filters::throttled_rate(pipeline, 30.0) == 2.0);
  CHECK(filters::throttled_rate(pipeline, 1.5) == 1.5);

  filters::PipelineStream stream(pipeline);
  const model::PointCloud frame = hand_counted_cloud();
  std::vector<filters::StageRun> runs;
  REQUIRE(stream.run(frame, 0.0, &runs).has_value());
  CHECK(runs.size() == 3);
  runs.clear();
  CHECK_FALSE(stream.run(frame, 0.1, &runs).has_value());  // 0.1 s < 0.5 s: dropped
  REQUIRE(runs.size() == 1);
  CHECK(runs[0].points_out == 0);

  // 20 frames at 30 Hz through a 2 Hz throttle: frames 0 and 15 pass.
  const std::vector<model::PointCloud> frames(20, frame);
  const filters::FramesLoad load = filters::measure_filtering_load(pipeline, frames, 30.0);
  CHECK(load.frames == 20);
  CHECK(load.passed == 2);
  CHECK(load.points == 20 * frame.size());
  // Radius 5 cm, 2 neighbours: only P5 and P6 have any neighbour (each other), one each.
  CHECK(load.kept == 0);

  // U_f of a pipeline timed on one cloud: each stage's time at the rate of the frames it sees.
  filters::PipelineTiming timing;
  timing.stages = {{"throttle", 100, 100, {1e-6, 1e-6}},
                   {"radius_outlier", 100, 90, {0.010, 0.012}},
                   {"voxel_grid", 90, 50, {0.002, 0.003}}};
  timing.total = {0.012001, 0.015};
  const filters::FilteringLoadRate rate = filters::pipeline_load(timing, pipeline, 100.0, 30.0);
  CHECK(rate.cores == Approx(1e-6 * 30.0 + (0.010 + 0.002) * 2.0));
  CHECK(rate.seconds_per_point == Approx(rate.cores / (100.0 * 30.0)));
  // Without a throttle: the total's median times the sensor's rate, as before.
  const model::Pipeline plain{"v", {model::VoxelGridParams{}}};
  CHECK(filters::pipeline_load(timing, plain, 100.0, 30.0).cores == Approx(0.012001 * 30.0));
}

TEST_CASE("pipeline files read throttle, radius_outlier and floor_removal_2's slice",
          "[filters][io]") {
  TempFolder folder;
  const model::Pipeline pipeline = io::load_pipeline(
      folder.write("p.yaml",
                   "name: paper2_lidar\n"
                   "stages:\n"
                   "  - throttle: {rate_hz: 5}\n"
                   "  - radius_outlier: {radius: 0.1, min_neighbours: 3}\n"
                   "  - floor_removal_2: {slice: {min: -0.05, max: 0.05}, coarse_leaf: 0.2}\n"
                   "  - throttle\n"));
  REQUIRE(pipeline.stages.size() == 4);
  CHECK(std::get<model::ThrottleParams>(pipeline.stages[0]).rate_hz == 5.0);
  const auto& radius = std::get<model::RadiusOutlierParams>(pipeline.stages[1]);
  CHECK(radius.radius == 0.1);
  CHECK(radius.min_neighbours == 3);
  const auto& floor = std::get<model::FloorRemoval2Params>(pipeline.stages[2]);
  CHECK(floor.slice.min == -0.05);
  CHECK(floor.slice.max == 0.05);
  CHECK(floor.coarse_leaf == 0.2);
  CHECK(floor.ransac.max_tilt.has_value());  // the guard stays at its default
  CHECK(std::get<model::ThrottleParams>(pipeline.stages[3]).rate_hz == 2.0);  // the default
}

TEST_CASE("bad throttle and radius_outlier values name file, line and column", "[filters][io]") {
  struct Bad {
    std::string stage, key, value;
    int column;  // the value's: 7 (indent) + the key, ": " and one
    std::string expected;
  };
  const std::vector<Bad> cases = {
      {"throttle", "rate_hz", "0", 16, "the frames kept per second, > 0"},
      {"throttle", "rate_hz", "fast", 16, "the frames kept per second, > 0"},
      {"radius_outlier", "radius", "-0.1", 15, "the search radius in metres, > 0"},
      {"radius_outlier", "min_neighbours", "0", 23, "a neighbour count, > 0"},
      {"radius_outlier", "min_neighbours", "2.5", 23, "a neighbour count, > 0"},
  };
  TempFolder folder;
  for (const Bad& bad : cases) {
    INFO(bad.stage << "." << bad.key << ": " << bad.value);
    const std::string path =
        folder.write("bad.yaml", "name: bad\nstages:\n  - " + bad.stage + ":\n      " + bad.key +
                                     ": " + bad.value + "\n");
    try {
      io::load_pipeline(path);
      FAIL("loaded a bad value");
    } catch (const model::InputError& error) {
      const model::Diagnostic& d = error.diagnostics().front();
      CHECK(d.where.file == path);
      CHECK(d.where.line == 4);
      CHECK(d.where.column == bad.column);
      CHECK(d.field == "stages[0]." + bad.stage + "." + bad.key);
      CHECK(d.expected == bad.expected);
    }
  }
  // An unknown key is named at the key (line 4, column 7).
  const std::string typo =
      folder.write("typo.yaml", "name: typo\nstages:\n  - throttle:\n      rate: 5\n");
  try {
    io::load_pipeline(typo);
    FAIL("loaded an unknown key");
  } catch (const model::InputError& error) {
    const model::Diagnostic& d = error.diagnostics().front();
    CHECK(d.where.line == 4);
    CHECK(d.where.column == 7);
  }
}
