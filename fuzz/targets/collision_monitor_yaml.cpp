// Fuzz target: a nav2 collision_monitor parameter file (check --collision-monitor), read for a
// rig with one mount (front_lidar on /front_lidar/scan, as the seeds from the cart name it).
#include "fuzz_input.hpp"
#include "rigdesign/deploy/ros/nav2/collision_monitor_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rigdesign::fuzz::input_file(data, size, "collision_monitor.yaml");
  static const rigdesign::model::Rig rig = [] {
    rigdesign::model::Rig r;
    r.file = "rig.yaml";
    r.mounts.emplace_back();
    r.mounts.back().id = "front_lidar";
    return r;
  }();
  return rigdesign::fuzz::expect_input_errors([&] {
    rigdesign::deploy::load_collision_monitor(path, rig, {{"/front_lidar/scan", "front_lidar"}});
  });
}
