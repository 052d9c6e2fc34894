#include "rigdesign/filters/pipeline_timing.hpp"

#include <catch2/catch.hpp>
#include <vector>

#include "rigdesign/model/filtering_loads.hpp"

using namespace rigdesign;

namespace {

// Points on a 1 cm lattice in a 10 cm cube: a 3 cm voxel grid keeps ceil(10 / 3)^3 = 64.
model::PointCloud lattice_cube() {
  model::PointCloud cloud;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 10; ++k)
        cloud.points.emplace_back(0.005f + 0.01f * static_cast<float>(i),
                                  0.005f + 0.01f * static_cast<float>(j),
                                  0.005f + 0.01f * static_cast<float>(k));
  return cloud;
}

model::Pipeline voxel_only() {
  return model::Pipeline{"voxel", {model::VoxelGridParams{}}};
}

}  // namespace

TEST_CASE("time_pipeline counts points per stage and summarises every run", "[filters]") {
  const filters::PipelineTiming timing = filters::time_pipeline(voxel_only(), lattice_cube(), 5);
  REQUIRE(timing.stages.size() == 1);
  CHECK(timing.stages[0].stage == "voxel_grid");
  CHECK(timing.stages[0].points_in == 1000);
  CHECK(timing.stages[0].points_out == 64);
  CHECK(timing.result.size() == 64);
  CHECK(timing.stages[0].seconds.p95 >= timing.stages[0].seconds.median);
  CHECK(timing.total.median >= timing.stages[0].seconds.median * 0.999);
}

TEST_CASE("filtering load: paper 1 eq. 5, seconds per frame times frames per second", "[filters]") {
  const filters::FilteringLoadRate rate = filters::filtering_load(0.02, 144545.0, 30.0);
  CHECK(rate.cores == Approx(0.6));  // 0.02 s x 30 Hz
  CHECK(rate.seconds_per_point == Approx(0.02 / 144545.0));
  CHECK(filters::filtering_load(0.02, 0.0, 30.0).seconds_per_point == 0.0);

  const std::vector<model::PointCloud> frames{lattice_cube(), lattice_cube(), lattice_cube()};
  const filters::FramesLoad load = filters::measure_filtering_load(voxel_only(), frames, 15.0);
  CHECK(load.frames == 3);
  CHECK(load.points == 3000);
  CHECK(load.kept == 3 * 64);
  CHECK(load.load.cores == Approx(load.seconds_per_frame.median * 15.0));
}

TEST_CASE("mounts of one sensor share its measured load: the slower per point", "[filters]") {
  model::FilteringLoads loads;
  loads.record({"pico", "m9", 2e-8, 1000.0, 2e-5, {}});
  loads.record({"pico", "m9", 3e-8, 1000.0, 3e-5, {}});
  loads.record({"pico", "m9", 1e-8, 1000.0, 1e-5, {}});
  loads.record({"vlp16", "15hz", 4e-7, 18000.0, 7e-3, {}});
  REQUIRE(loads.sensors.size() == 2);
  CHECK(loads.find("pico")->seconds_per_point == 3e-8);
  CHECK(loads.find("vlp16")->seconds_per_point == 4e-7);
}
