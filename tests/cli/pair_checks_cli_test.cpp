// Issue 38 through `rigdesign check`: crosstalk (D5) fails two Azure Kinects that light the
// same floor, exit 1, with a GitHub annotation on each mount's line; stated sync 160 us apart
// passes; calibration overlap (R9) names the lidar that shares nothing with the cameras.
#include <catch2/catch.hpp>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::string two_kinects(const std::string& left_extra, const std::string& right_extra) {
  return "name: two kinects\nsensor_library: " + source_path("sensors.yaml") +
         "\nbody: {radius: 0.2, height: 0.5}\ndistance_of_interest: 3.0\nmounts:\n"
         "  - id: left\n    sensor: azure_kinect_dk\n    mode: nfov_unbinned_30\n" +
         left_extra + "    pose: {xyz: [0.21, 0.1, 0.4], rpy_deg: [0, 20, 0]}\n" +
         "    recessed: true\n" +  // the 126 mm deep housings sit in pockets of the shell
         "  - id: right\n    sensor: azure_kinect_dk\n    mode: nfov_unbinned_30\n" + right_extra +
         "    pose: {xyz: [0.21, -0.1, 0.4], rpy_deg: [0, 20, 0]}\n    recessed: true\n";
}

}  // namespace

TEST_CASE("check: crosstalk fails at both mounts' lines, sync 160 us apart passes",
          "[cli][crosstalk]") {
  TempFolder folder;
  const std::string bare = folder.write("bare.yaml", two_kinects("", ""));
  const CliResult failed = run_cli({"check", bare, "--format", "github"});
  INFO(failed.out << failed.err);
  CHECK(failed.exit_code == 1);
  // The mounts' entries are on lines 6 and 11 of the file written above.
  CHECK(failed.out.find("::error file=" + bare +
                        ",line=6,col=5,title=rigdesign D5 crosstalk%3A "
                        "left and right::") != std::string::npos);
  CHECK(failed.out.find("::error file=" + bare +
                        ",line=11,col=5,title=rigdesign D5 crosstalk%3A "
                        "left and right::") != std::string::npos);
  const std::string synced =
      folder.write("synced.yaml", two_kinects("    crosstalk: {sync: front, delay_us: 0}\n",
                                              "    crosstalk: {sync: front, delay_us: 160}\n"));
  const CliResult passed = run_cli({"check", synced});
  INFO(passed.out << passed.err);
  CHECK(passed.exit_code == 0);
  CHECK(passed.out.find("pass: D5 crosstalk: left and right") != std::string::npos);
}

TEST_CASE("check: calibration overlap names the lidar the cameras cannot see with",
          "[cli][covisibility]") {
  TempFolder folder;
  folder.write("req.yaml",
               "name: calibrate\nrange: {distance: 3.0}\n"
               "calibration: {pairs: connected, min_overlap_m2: 0.5}\n");
  const std::string rig = folder.write(
      "rig.yaml",
      "name: calibration case\nsensor_library: " + source_path("sensors.yaml") +
          "\nrequirements: req.yaml\nbody: {radius: 0.2, height: 0.5}\n"
          "distance_of_interest: 3.0\nmounts:\n"
          "  - {id: cam_left, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: [0.21, "
          "0.05, 0.3], rpy_deg: [0, 15, 0]}}\n"
          "  - {id: cam_right, sensor: realsense_d435, mode: z16_848x480_30, pose: {xyz: [0.21, "
          "-0.05, 0.3], rpy_deg: [0, 15, 0]}}\n"
          "  - {id: rear_lidar, sensor: sick_tim571, mode: 0.33deg_15hz, pose: {xyz: [-0.21, 0, "
          "0.2], rpy_deg: [0, 0, 180]}}\n");
  const CliResult result = run_cli({"check", rig});
  INFO(result.out << result.err);
  CHECK(result.exit_code == 1);
  // rear_lidar is the third mount, line 9.
  CHECK(result.out.find(rig + ":9:5: calibration: fail: R9 calibration overlap") !=
        std::string::npos);
  CHECK(result.out.find("cut off from the rest: rear_lidar") != std::string::npos);
}
