// Issue 53 items 3, 4 and 6: inputs that used to run for hours, forever or block. Each value
// expected here is computed in this file from the geometry or the input's own text: a zone's
// perimeter, where a 10 m sensor stops seeing a straight side, a polygon drawn by hand.
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "rigdesign/deploy/zone_visibility.hpp"
#include "rigdesign/geometry/body_occluder.hpp"
#include "rigdesign/geometry/mounted_fov.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"
#include "rigdesign/model/polygon_checks.hpp"
#include "rigdesign/model/rotation.hpp"
#include "rigdesign/model/units.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;

namespace {

// A 90 x 90 deg pyramid of 10 m range at (0.2, 0, 0.15) looking ahead, on a cylinder r 0.2 m,
// h 0.3 m (the hand case of collision_monitor_test).
struct PyramidOnCylinder {
  model::RobotBody body;
  model::SensorMode mode;
  PyramidOnCylinder() {
    body.radius = 0.2;
    body.height = 0.3;
    mode.id = "pyramid";
    mode.fov = model::FieldOfView(model::pyramid_fov(model::deg_to_rad(90), model::deg_to_rad(90)));
    mode.max_range = 10.0;
    mode.frequency = 10.0;
  }
};

double total_length(const std::vector<deploy::BoundaryArc>& arcs) {
  double sum = 0.0;
  for (const deploy::BoundaryArc& arc : arcs) sum += arc.length;
  return sum;
}

// The cart (rigs/cart_two_scanners.yaml) with one text replaced, in `folder`.
std::string cart_with(const TempFolder& folder, const std::string& name, const std::string& from,
                      const std::string& to) {
  std::string rig = file_text(source_path("rigs/cart_two_scanners.yaml"));
  const std::size_t at = rig.find(from);
  REQUIRE(at != std::string::npos);
  rig.replace(at, from.size(), to);
  const std::string ref = "requirements: requirements/";
  rig.replace(rig.find(ref), ref.size(), "requirements: " + source_path("rigs/requirements/"));
  return folder.write(name, rig);
}

}  // namespace

TEST_CASE("a zone typed in millimetres is measured within the sensors' reach (25)", "[deploy]") {
  const PyramidOnCylinder hand;
  const geometry::BodyOccluder occluder(hand.body);
  const geometry::MountedFov ahead(hand.mode, model::pose_from_xyz_rpy({0.2, 0, 0.15}, {0, 0, 0}),
                                   occluder, "");
  deploy::BodyOutline outline;
  outline.radius = 0.2;
  SECTION("860 m x 400 m around the robot: all of its boundary is beyond 10.2 m, unseen") {
    const std::vector<model::Vec2> zone = {{-300, -200}, {560, -200}, {560, 200}, {-300, 200}};
    const deploy::ZoneVisibility seen =
        deploy::zone_visibility(zone, outline, {{&ahead, 0.0, 1.0}}, hand.body.height);
    const double perimeter = 2 * (860.0 + 400.0);
    CHECK_THAT(seen.checked_boundary, WithinAbs(perimeter, 1e-6));
    CHECK_THAT(total_length(seen.unseen), WithinAbs(perimeter, 1e-6));
    CHECK(seen.sees[0]);  // the inside ahead of the sensor, found by the interior samples
  }
  SECTION("a 50 m corridor ahead: each side is seen from x = 0.5 to where the range ends") {
    // A side |y| = 0.3 enters the pyramid at x - 0.2 = 0.3; a column there is within 10 m of
    // the sensor while (x - 0.2)^2 + 0.3^2 <= 10^2 (its point at the sensor's height).
    const std::vector<model::Vec2> zone = {{0.2, -0.3}, {50, -0.3}, {50, 0.3}, {0.2, 0.3}};
    const deploy::ZoneVisibility seen =
        deploy::zone_visibility(zone, outline, {{&ahead, 0.0, 1.0}}, hand.body.height);
    const double range_end = 0.2 + std::sqrt(100.0 - 0.09);
    const double step = deploy::kBoundaryStep;
    CHECK_THAT(seen.seen_boundary[0], WithinAbs(2 * (range_end - 0.5), 4 * step));
    // Unseen: one arc over the far end (both sides past range_end and the 0.6 m end) and the
    // back edge's two stretches beside the body with the sides up to x = 0.5.
    REQUIRE(seen.unseen.size() == 3);
    double far = 0.0;
    for (const deploy::BoundaryArc& arc : seen.unseen) far = std::max(far, arc.length);
    CHECK_THAT(far, WithinAbs(2 * (50.0 - range_end) + 0.6, 4 * step));
  }
}

TEST_CASE("polygons that cannot be judged are named with why (item 6)", "[model]") {
  using model::polygon_problem;
  CHECK_FALSE(polygon_problem({{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  CHECK_FALSE(polygon_problem({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));  // clockwise is fine
  CHECK_THAT(*polygon_problem({{0, 0}, {1, 0}}), Contains("has 2 corners"));
  // Collinear corners: every edge lies on one line, so neighbours' ends meet other edges.
  CHECK(polygon_problem({{0, 0}, {1, 0}, {2, 0}, {3, 0}}));
  CHECK_THAT(*polygon_problem({{0, 0}, {1, 0}, {1, 1e-12}}), Contains("encloses no area"));
  // A bow tie: edge 1-2 from (1, 0) to (0, 1) meets edge 3-0 from (1, 1) to (0, 0) at (0.5, 0.5).
  CHECK_THAT(*polygon_problem({{0, 0}, {1, 0}, {0, 1}, {1, 1}}),
             Contains("edge 1-2 meets edge 3-0"));
  // A corner touching a non-neighbouring edge.
  CHECK_THAT(*polygon_problem({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}),
             Contains("crosses itself"));
  CHECK_THAT(*polygon_problem({{0, 0}, {2e8, 0}, {0, 1}}), Contains("beyond +-1e8 m"));
}

TEST_CASE("check --collision-monitor: a zone in millimetres warns and ends, 1e300 is refused",
          "[deploy][cli]") {
  TempFolder folder;
  const std::string base = file_text(source_path("tests/data/collision_monitor/cart_jazzy.yaml"));
  const std::string zone = "points: \"[[-0.3, -0.2], [0.56, -0.2], [0.56, 0.2], [-0.3, 0.2]]\"";
  const auto with_zone = [&](const std::string& name, const std::string& points) {
    std::string text = base;
    text.replace(text.find(zone), zone.size(), "points: \"" + points + "\"");
    return folder.write(name, text);
  };
  const std::string mm =
      with_zone("mm.yaml", "[[-300, -200], [560, -200], [560, 200], [-300, 200]]");
  const CliResult far =
      run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor", mm});
  CHECK_THAT(far.out + far.err, Contains("probably typed in millimetres"));
  const std::string huge = with_zone(
      "huge.yaml", "[[-1e300, -1e300], [1e300, -1e300], [1e300, 1e300], [-1e300, 1e300]]");
  const CliResult refused =
      run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor", huge});
  CHECK(refused.exit_code == 2);
  const int line = line_of(file_text(huge), "1e300");
  CHECK_THAT(refused.out + refused.err,
             Contains("huge.yaml:" + std::to_string(line) + ":") && Contains("beyond +-1e8 m"));
  // Edge 1-2 from (2, 0) to (0, 1) crosses edge 3-0 from (1, 1) to (0, 0) at (2/3, 2/3).
  const std::string bow = with_zone("bow.yaml", "[[0, 0], [2, 0], [0, 1], [1, 1]]");
  const CliResult crossed =
      run_cli({"check", source_path("rigs/cart_two_scanners.yaml"), "--collision-monitor", bow});
  CHECK(crossed.exit_code == 2);
  CHECK_THAT(crossed.out + crossed.err, Contains("crosses itself"));
}

TEST_CASE("export: a throttle of 1e-9 Hz or a deceleration of 1e-300 is refused by name (26)",
          "[deploy][cli]") {
  TempFolder folder;
  const std::string throttled =
      cart_with(folder, "throttle.yaml", "mode: 5_5hz, pose: {xyz: [0.5, 0, 0.2]",
                "mode: 5_5hz, throttle_hz: 1e-9, pose: {xyz: [0.5, 0, 0.2]");
  const CliResult slow =
      run_cli({"export", throttled, "--to", folder.path() + "/out1", "--max-speed", "1"});
  CHECK(slow.exit_code == 2);
  CHECK_THAT(slow.err, Contains("front_lidar.throttle_hz") && Contains("throttle.yaml:"));
  std::string requirements = file_text(source_path("rigs/requirements/cart_two_scanners.yaml"));
  const std::string speed = "max_travel_between_frames: 0.1}";
  requirements.replace(requirements.find(speed), speed.size(),
                       "max_travel_between_frames: 0.1, deceleration: 1e-300}");
  folder.write("req.yaml", requirements);
  std::string rig = file_text(source_path("rigs/cart_two_scanners.yaml"));
  const std::string ref = "requirements: requirements/cart_two_scanners.yaml";
  rig.replace(rig.find(ref), ref.size(), "requirements: req.yaml");
  const std::string decel = folder.write("decel.yaml", rig);
  const CliResult braking =
      run_cli({"export", decel, "--to", folder.path() + "/out2", "--max-speed", "1"});
  CHECK(braking.exit_code == 2);
  CHECK_THAT(braking.err, Contains("req.yaml:") && Contains(": robot_speed.deceleration: makes"));
}

TEST_CASE("coverage --sweep arc:1e-20 is refused by the sample cap, not judged in one step (30)",
          "[metrics][cli]") {
  TempFolder folder;
  const CliResult result = run_cli({"coverage", source_path("rigs/ur_cleaner.yaml"), "--no-3d",
                                    "--out", folder.path() + "/out", "--sweep", "arc:1e-20"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, Contains("cell samples"));
}

TEST_CASE("a FIFO a socket or a device where a file is read is refused at once (29, item 4)",
          "[io][cli]") {
  TempFolder folder;
  const std::string fifo = folder.path() + "/rig.yaml";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Without a writer, opening it to read would wait forever; a refusal returns here.
  try {
    (void)io::read_file_bytes(fifo, "a rig");
    FAIL("a FIFO was read");
  } catch (const model::InputError& error) {
    CHECK_THAT(error.what(), Contains("is a pipe (FIFO), not a file"));
  }
  const std::string socket_path = folder.path() + "/s.yaml";
  const int listener = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  socket_path.copy(address.sun_path, sizeof address.sun_path - 1);
  REQUIRE(::bind(listener, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
  CHECK_THROWS_WITH(io::read_file_bytes(socket_path, "a rig"), Contains("is a socket"));
  ::close(listener);
  CHECK_THROWS_WITH(io::read_file_bytes("/dev/zero", "a rig"), Contains("is a device"));
  const CliResult check = run_cli({"check", fifo});
  CHECK(check.exit_code == 2);
  CHECK_THAT(check.out, Contains(fifo) && Contains("pipe (FIFO)"));
  const CliResult serve = run_cli({"serve", fifo, "--port", "0", "--no-open"});
  CHECK(serve.exit_code == 2);
  const std::string scenario = folder.path() + "/scenario.yaml";
  REQUIRE(::mkfifo(scenario.c_str(), 0600) == 0);
  const CliResult costmap = run_cli({"costmap", source_path("rigs/cart_two_scanners.yaml"),
                                     "--scenario", scenario, "--out", folder.path() + "/c"});
  CHECK(costmap.exit_code == 2);
  CHECK_THAT(costmap.err, Contains("pipe (FIFO)"));
}

TEST_CASE("check --max-seconds stops the tolerance poses with how many were judged (item 3)",
          "[metrics][cli]") {
  // Six axes of tolerance on each of the UR Cleaner's five mounts: 2^6 corners and 2 x 6 face
  // centres per mount (docs/tolerance.md), 5 x 76 = 380 moved rigs.
  TempFolder folder;
  std::string rig = file_text(source_path("rigs/ur_cleaner.yaml"));
  const std::size_t name_end = rig.find('\n', rig.find("name:"));
  rig.insert(name_end + 1, "tolerance: {xyz: [0.005, 0.005, 0.005], rpy_deg: [1, 1, 1]}\n");
  const std::string ref = "requirements: requirements/";
  rig.replace(rig.find(ref), ref.size(), "requirements: " + source_path("rigs/requirements/"));
  const std::string path = folder.write("tolerant.yaml", rig);
  const CliResult result = run_cli({"check", path, "--max-seconds", "0.5"});
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.out, Contains("--max-seconds: reached after") &&
                             Contains(" of 380 tolerance poses judged"));
}
