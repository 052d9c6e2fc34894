// The filter stage registry: every registered name loads from a pipeline file into the stage
// of that name, runs, and is reported under it; an unknown name lists the registered ones.
#include <catch2/catch.hpp>

#include "rigdesign/filters/pipeline.hpp"
#include "rigdesign/io/config/pipeline_loader.hpp"
#include "rigdesign/model/input_error.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using rigdesign::test::TempFolder;

TEST_CASE("every registered stage loads, runs and keeps its name", "[filters][io]") {
  // The nine stages of DESIGN.md section 6 and paper 2 (its throttle and radius outlier
  // filter, issue 39), in StageParams' order.
  const std::vector<std::string> documented = {
      "voxel_grid",      "statistical_outlier", "pass_through", "ransac_plane",  "floor_removal_1",
      "floor_removal_2", "negative_obstacles",  "throttle",     "radius_outlier"};
  CHECK(model::stage_names() == documented);
  model::PointCloud cloud;
  for (int i = 0; i < 50; ++i)
    cloud.points.emplace_back(0.02f * static_cast<float>(i), 0.0f,
                              0.01f * static_cast<float>(i % 3));
  TempFolder folder;
  for (std::size_t i = 0; i < documented.size(); ++i) {
    const std::string path =
        folder.write("p.yaml", "name: one\nstages:\n  - " + documented[i] + ": {}\n");
    const model::Pipeline pipeline = io::load_pipeline(path);
    REQUIRE(pipeline.stages.size() == 1);
    CHECK(pipeline.stages[0].index() == i);
    CHECK(model::stage_name(pipeline.stages[0]) == documented[i]);
    std::vector<filters::StageRun> runs;
    filters::run_pipeline(pipeline, cloud, &runs);
    REQUIRE(runs.size() == 1);
    CHECK(runs[0].stage == documented[i]);
    CHECK(runs[0].points_in == cloud.size());
  }
}

TEST_CASE("an unknown stage names the registered ones", "[filters][io]") {
  TempFolder folder;
  const std::string path = folder.write("p.yaml", "name: typo\nstages:\n  - voxel_grd: {}\n");
  try {
    io::load_pipeline(path);
    FAIL("loaded a pipeline with an unknown stage");
  } catch (const model::InputError& error) {
    const model::Diagnostic& d = error.diagnostics().front();
    CHECK(d.where.line == 3);
    CHECK(d.problem == "unknown stage 'voxel_grd'");
    CHECK(d.expected.find("voxel_grid, statistical_outlier") != std::string::npos);
    CHECK(d.expected.find("negative_obstacles") != std::string::npos);
  }
}

TEST_CASE("statistical_outlier reads a thread count and refuses one out of range",
          "[filters][io]") {
  TempFolder folder;
  const model::Pipeline two = io::load_pipeline(folder.write(
      "two.yaml", "name: two\nstages:\n  - statistical_outlier: {neighbours: 8, threads: 2}\n"));
  REQUIRE(two.stages.size() == 1);
  CHECK(std::get<model::StatisticalOutlierParams>(two.stages[0]).threads == 2);
  CHECK(
      std::get<model::StatisticalOutlierParams>(filters::with_threads(two, 3).stages[0]).threads ==
      3);
  for (const std::string bad : {"0", "65", "two"}) {
    const std::string path = folder.write(
        "bad.yaml", "name: bad\nstages:\n  - statistical_outlier:\n      threads: " + bad + "\n");
    try {
      io::load_pipeline(path);
      FAIL("loaded threads: " << bad);
    } catch (const model::InputError& error) {
      const model::Diagnostic& d = error.diagnostics().front();
      CHECK(d.where.line == 4);
      CHECK(d.field.find("threads") != std::string::npos);
      CHECK(d.expected == "a thread count, 1 to 64");
    }
  }
}
