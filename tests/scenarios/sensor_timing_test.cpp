// Issue 35 item 1: sensors as they run. Frame times and latencies against hand arithmetic,
// and a 10 Hz and a 30 Hz version of one camera that see a pole appear at different costmap
// updates, by exactly the difference their frame spacing predicts.
#include "rigdesign/scenarios/sensor_timing.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/scenarios/scenario_runner.hpp"
#include "support/box_mesh.hpp"

using namespace rigdesign;
using Catch::Matchers::WithinAbs;

namespace {

model::SensorMode camera(double frequency) {
  model::SensorMode mode;
  mode.id = "m";
  mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(60), model::deg_to_rad(40)));
  mode.min_range = 0.1;
  mode.max_range = 5.0;
  mode.frequency = frequency;
  mode.angular_resolution_h = model::deg_to_rad(1.0);
  mode.angular_resolution_v = model::deg_to_rad(1.0);
  mode.points_per_frame = 2400;
  return mode;  // driver_cpu zero: the latency is the filters' alone
}

struct OneCamera {
  model::SensorLibrary library;
  model::Rig rig;
  explicit OneCamera(double frequency) {
    model::Sensor sensor;
    sensor.id = "cam";
    sensor.modes.push_back(camera(frequency));
    library.sensors.push_back(sensor);
    rig.body.radius = 0.2;
    rig.body.height = 0.5;
    rig.distance_of_interest = 3.0;
    model::Mount mount;
    mount.id = "cam";
    mount.sensor_id = "cam";
    mount.mode_id = "m";
    mount.T_robot_sensor = model::pose_from_xyz_rpy({0.2, 0.0, 0.3}, {0, 0, 0});
    rig.mounts.push_back(mount);
  }
};

}  // namespace

TEST_CASE("sensor timing: period, throttle, driver and filter time per frame", "[scenario]") {
  model::SensorMode mode = camera(10.0);
  mode.driver_cpu.cores = 0.1;
  mode.driver_cpu.seconds_per_point = 1e-8;
  model::Mount mount;
  // Driver: (0.1 + 1e-8 x 2400 x 10) core-equivalents over a 0.1 s frame = 0.010024 s;
  // filters: 3.5e-7 x 2400 = 0.00084 s.
  const scenarios::MountTiming timing = scenarios::mount_timing(mount, mode, 3.5e-7, 0.25);
  CHECK_THAT(timing.period, WithinAbs(0.1, 1e-15));
  CHECK_THAT(timing.phase, WithinAbs(0.05, 1e-12));  // 0.25 modulo the period
  CHECK_THAT(timing.driver, WithinAbs(0.010024, 1e-12));
  CHECK_THAT(timing.filtering, WithinAbs(0.00084, 1e-15));
  mount.throttle_hz = 2.0;  // paper 2's Kinect
  CHECK_THAT(scenarios::mount_timing(mount, mode, 0.0, 0.0).period, WithinAbs(0.5, 1e-15));
}

TEST_CASE("sensor timing: the frames the costmap holds, as nav2's observation buffer keeps them",
          "[scenario]") {
  scenarios::MountTiming timing;
  timing.period = 0.1;
  timing.phase = 0.03;
  timing.filtering = 0.02;  // latency 0.02 s
  // At t = 0.2 the newest frame captured by 0.18 is k = 1 (0.13 s).
  CHECK(scenarios::frames_held(timing, 0.2, 0.0) == std::vector<long>{1});
  // Persistence 0.1 s keeps the one captured 0.1 s before it too.
  CHECK(scenarios::frames_held(timing, 0.2, 0.1) == std::vector<long>{0, 1});
  // Before the first frame (0.03 s) has arrived (0.05 s): nothing.
  CHECK(scenarios::frames_held(timing, 0.049, 0.0).empty());
  CHECK(scenarios::frames_held(timing, 0.05, 0.0) == std::vector<long>{0});
}

TEST_CASE("a 30 Hz camera sees a pole one costmap update before the same camera at 10 Hz",
          "[scenario]") {
  // The pole (0.1 x 0.1 x 1 m at x = 1.5 m) rises from below the floor between t = 0.10 and
  // 0.11 s. Frames start at t = 0 and reach the costmap 0.02 s after capture; the costmap
  // updates at 5 Hz (t = 0, 0.2, 0.4, ...). At t = 0.2 the newest frame captured by 0.18 s is
  // the one of 0.1667 s at 30 Hz (pole up) but the one of 0.1 s at 10 Hz (pole not yet
  // risen); at 10 Hz the pole first appears in the frame of 0.3 s, held from t = 0.4.
  const auto first_seen = [](double frequency) {
    const OneCamera test(frequency);
    scenarios::ScenarioDefinition scenario;
    scenario.name = "pole";
    model::MovingObject pole;
    pole.name = "pole";
    pole.mesh = test::box_mesh({1.45, -0.05, 0.0}, {1.55, 0.05, 1.0});
    pole.T_world_object = [](double t) {
      model::Pose3 T = model::Pose3::Identity();
      T.translate(model::Vec3(0, 0, -2.0 + 2.0 * std::clamp((t - 0.10) / 0.01, 0.0, 1.0)));
      return T;
    };
    scenario.scene.moving.push_back(pole);
    scenario.route = {{model::Vec2::Zero(), 1.0, "start"}};  // the robot waits where it stands
    scenario.max_duration = 1.2;
    scenarios::ScenarioParams params;
    params.camera_decimation = 1;  // every 1-degree ray: the pole spans 3.8 degrees
    params.add_noise = false;
    params.filtering_seconds_per_point = 0.02 / 2400;  // latency 0.02 s
    params.frame_phases = {0.0};
    double seen = -1.0;
    scenarios::run_scenario(scenario, test.rig, test.library, params,
                            [&](const scenarios::ScenarioStep& step) {
                              if (seen >= 0.0) return;
                              for (const Eigen::Vector3f& p : step.clouds[0].points) {
                                if (std::abs(p.x() - 1.45) < 0.02 && std::abs(p.y()) < 0.05) {
                                  seen = step.time;
                                  return;
                                }
                              }
                            });
    return seen;
  };
  CHECK_THAT(first_seen(30.0), WithinAbs(0.2, 1e-9));
  CHECK_THAT(first_seen(10.0), WithinAbs(0.4, 1e-9));
}
