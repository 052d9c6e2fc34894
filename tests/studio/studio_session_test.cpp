// Issue 37: the studio's session. Every expected value comes from another way in: the rig
// written by hand with the edited values and run through `rigdesign metrics` and `check`, or
// the file's text edited by hand.
#include "rigdesign/studio/studio_session.hpp"

#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

const std::string kFrontPose = "{xyz: [0.5, 0, 0.2], rpy_deg: [0, 0, 0]}";

// The bundled cart with its requirements named by absolute path (the copy lives elsewhere).
std::string cart_text() {
  std::string text = test::file_text(test::source_path("rigs/cart_two_scanners.yaml"));
  const std::string from = "requirements: requirements/cart_two_scanners.yaml";
  text.replace(text.find(from), from.size(),
               "requirements: " + test::source_path("rigs/requirements/cart_two_scanners.yaml"));
  return text;
}

std::string with_text_replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string library_path() {
  return test::source_path("sensors.yaml");
}

}  // namespace

TEST_CASE("studio: a moved mount gets the numbers `metrics` gives the rig written with its pose",
          "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("cart.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  CHECK_FALSE(session.dirty());
  session.set_pose("front_lidar", {{0.5, 0, 0.35}, {0, 10, 0}});
  CHECK(session.dirty());
  const studio::StudioNumbers exact = session.numbers(true);
  const studio::StudioNumbers raster = session.numbers(false);

  const std::string by_hand =
      with_text_replaced(cart_text(), kFrontPose, "{xyz: [0.5, 0, 0.35], rpy_deg: [0, 10, 0]}");
  const std::string other = folder.write("by_hand.yaml", by_hand);
  const test::CliResult metrics =
      test::run_cli({"metrics", other, "--sensors", library_path(), "--json"});
  REQUIRE(metrics.exit_code == 0);
  const nlohmann::json report = nlohmann::json::parse(metrics.out);
  CHECK(exact.coverage.complete.min == Approx(report["coverage"]["complete"]["min"].get<double>()));
  CHECK(exact.coverage.complete.mean ==
        Approx(report["coverage"]["complete"]["mean"].get<double>()));
  // The raster path as `metrics` reports it (its N-1 baseline is the raster run).
  CHECK(raster.coverage.complete.mean ==
        Approx(report["coverage"]["n_minus_1_baseline"]["complete"]["mean"].get<double>()));
  const nlohmann::json& results = report["requirements"]["results"];
  REQUIRE(results.size() == exact.requirements.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    INFO(results[i]["id"]);
    CHECK(to_string(exact.requirements[i].verdict) == results[i]["verdict"].get<std::string>());
  }

  // Saving changes the pose's characters and nothing else; `check` reads the file back.
  session.save();
  CHECK(test::file_text(path) == by_hand);
  CHECK_FALSE(session.dirty());
  // check's exit code is what the verdicts of `metrics` make it: 1 when one fails.
  bool any_fails = false;
  for (const nlohmann::json& result : results) any_fails = any_fails || result["verdict"] == "fail";
  CHECK(test::run_cli({"check", path, "--sensors", library_path()}).exit_code ==
        (any_fails ? 1 : 0));
}

TEST_CASE("studio: an edit that makes the rig invalid is refused with check's message",
          "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("cart.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  const model::Pose3 before = session.inputs().rig.mounts.front().T_robot_sensor;

  // A mode the sensor lacks: `check` on the file with that mode written names the same place.
  std::string message;
  try {
    session.set_sensor("front_lidar", "rplidar_a1m8", "20hz");
    FAIL("accepted");
  } catch (const model::InputError& error) {
    message = error.diagnostics().front().message();
  }
  const std::string bad_mode = folder.write(
      "bad_mode.yaml", with_text_replaced(cart_text(), "sensor: rplidar_a1m8, mode: 5_5hz",
                                          "sensor: rplidar_a1m8, mode: 20hz"));
  test::CliResult check = test::run_cli({"check", bad_mode, "--sensors", library_path()});
  CHECK(check.exit_code == 2);
  // The message names the studio's file; check's names its copy: compare after the file name.
  const std::string tail = message.substr(message.find(':'));
  CHECK(check.out.find(tail) != std::string::npos);

  // A sensor inside the cart's prism.
  try {
    session.set_pose("front_lidar", {{0.1, 0, 0.2}, {0, 0, 0}});
    FAIL("accepted");
  } catch (const model::InputError& error) {
    message = error.diagnostics().front().message();
  }
  const std::string inside = folder.write(
      "inside.yaml",
      with_text_replaced(cart_text(), kFrontPose, "{xyz: [0.1, 0, 0.2], rpy_deg: [0, 0, 0]}"));
  check = test::run_cli({"check", inside, "--sensors", library_path()});
  // check judges it B1 (a failure, exit 1) in the words the studio refused it with.
  CHECK(check.exit_code == 1);
  // (up to the body's place, which names each its own file)
  const std::string reason = message.substr(message.find("the sensor's data origin"));
  CHECK(check.out.find(reason.substr(0, reason.find(" ("))) != std::string::npos);

  // The last valid state is kept.
  CHECK(session.inputs().rig.mounts.front().T_robot_sensor.matrix() == before.matrix());
  CHECK(session.inputs().rig.mounts.front().mode_id == "5_5hz");
  CHECK_FALSE(session.dirty());
}

TEST_CASE("studio: a rig that fails to load is kept as its errors", "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("broken.yaml", "name: x\nbody: {radius: 0.2, height: [\n");
  studio::StudioSession session(path, library_path(), "");
  CHECK_FALSE(session.loaded());
  REQUIRE_FALSE(session.diagnostics().empty());
  CHECK(session.diagnostics().front().message().find(path + ":") == 0);
  // Mended on disk, a reload takes it.
  folder.write("broken.yaml", cart_text());
  session.reload();
  CHECK(session.loaded());
}

TEST_CASE("studio: saves go only to the file loaded, never over a change on disk", "[studio]") {
  test::TempFolder folder;
  const std::string real = folder.write("real.yaml", cart_text());
  const std::string link = folder.path() + "/rig.yaml";
  std::filesystem::create_symlink(real, link);
  studio::StudioSession session(link, library_path(), "");
  REQUIRE(session.loaded());

  // Through a symbolic link: the file it leads to is written, the link stays a link.
  session.set_pose("rear_lidar", {{-0.55, 0, 0.2}, {0, 0, 180}});
  session.save();
  CHECK(std::filesystem::is_symlink(link));
  CHECK(test::file_text(real) ==
        with_text_replaced(cart_text(), "xyz: [-0.5, 0, 0.2]", "xyz: [-0.55, 0, 0.2]"));

  // Someone edits the file: the save is refused and their text kept.
  session.set_pose("rear_lidar", {{-0.6, 0, 0.2}, {0, 0, 180}});
  const std::string theirs = test::file_text(real) + "# a comment added by hand\n";
  folder.write("real.yaml", theirs);
  CHECK_THROWS_AS(session.save(), model::InputError);
  CHECK(test::file_text(real) == theirs);

  // The link now leads elsewhere: not followed.
  const std::string elsewhere = folder.write("elsewhere.yaml", cart_text());
  std::filesystem::remove(link);
  std::filesystem::create_symlink(elsewhere, link);
  CHECK_THROWS_AS(session.save(), model::InputError);
  CHECK(test::file_text(elsewhere) == cart_text());
}

TEST_CASE("studio: mounts added and removed are saved as list items", "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("cart.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  const std::string id = session.add_mount("rplidar_a1m8", "5_5hz", {{0, 0.4, 0.2}, {0, 0, 90}});
  CHECK(id == "rplidar_a1m8");
  session.remove_mount("rear_lidar");
  session.save();
  const std::string text = cart_text();
  const std::string expected =
      text.substr(0, text.find("  - {id: rear_lidar")) +
      "  - {id: rplidar_a1m8, sensor: rplidar_a1m8, mode: 5_5hz, pose: {xyz: [0, 0.4, 0.2], "
      "rpy_deg: [0, 0, 90]}}\n";
  CHECK(test::file_text(path) == expected);
  REQUIRE(session.loaded());
  CHECK(session.inputs().rig.mounts.size() == 2);
  // The last mount cannot go.
  session.remove_mount("front_lidar");
  CHECK_THROWS_AS(session.remove_mount("rplidar_a1m8"), model::InputError);
}

TEST_CASE("studio: the exact numbers kept between requests follow every edit and reload",
          "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("cart.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  // sensors.yaml: the A1's 5_5hz mode runs at 5.5 Hz, its 10hz mode at 10 Hz.
  const studio::StudioNumbers from_file = session.numbers(true);
  CHECK(from_file.resultant.frequency.value == Approx(5.5));
  session.set_sensor("front_lidar", "rplidar_a1m8", "10hz");
  session.set_sensor("rear_lidar", "rplidar_a1m8", "10hz");
  CHECK(session.numbers(true).resultant.frequency.value == Approx(10.0));
  // Without the rear scanner the sight behind the cart is gone.
  session.remove_mount("rear_lidar");
  CHECK(session.numbers(true).coverage.complete.mean < from_file.coverage.complete.mean);
  session.reload();  // edits dropped: the file's two 5.5 Hz scanners again
  const studio::StudioNumbers reloaded = session.numbers(true);
  CHECK(reloaded.resultant.frequency.value == Approx(5.5));
  CHECK(reloaded.coverage.complete.mean == Approx(from_file.coverage.complete.mean));
}

TEST_CASE("studio: another mode is judged and saved as that one word", "[studio]") {
  test::TempFolder folder;
  const std::string path = folder.write("cart.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  // sensors.yaml: the A1's 10hz mode runs at 10 Hz with 0.45 deg between rays (5_5hz: 5.5 Hz);
  // both scanners set F, so F stays the rear's 5.5 Hz until it changes too.
  session.set_sensor("front_lidar", "rplidar_a1m8", "10hz");
  CHECK(session.numbers(false).resultant.frequency.value == Approx(5.5));
  session.set_sensor("rear_lidar", "rplidar_a1m8", "10hz");
  CHECK(session.numbers(false).resultant.frequency.value == Approx(10.0));
  session.save();
  std::string expected = cart_text();
  for (int i = 0; i < 2; ++i) expected = with_text_replaced(expected, "mode: 5_5hz", "mode: 10hz");
  CHECK(test::file_text(path) == expected);
}

TEST_CASE("studio: an edit through a YAML alias is refused and the anchor's mount kept",
          "[studio]") {
  // Reproducer 21: a third mount whose pose is front_lidar's, by alias.
  std::string text =
      with_text_replaced(cart_text(), "pose: " + kFrontPose, "pose: &fp " + kFrontPose);
  text += "  - {id: third, sensor: rplidar_a1m8, mode: 5_5hz, pose: *fp}\n";
  test::TempFolder folder;
  const std::string path = folder.write("alias.yaml", text);
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  const studio::MountPose third_before = session.pose(session.inputs().rig.mounts[2]);
  try {
    session.set_pose("third", {{0.5, 0, 0.25}, {0, 0, 0}});
    FAIL("not refused");
  } catch (const model::InputError& error) {
    const model::Diagnostic& found = error.diagnostics().front();
    // At the alias, on the file's last line, counted here.
    CHECK(found.where.line == test::line_of(text, "*fp"));
    const std::size_t line_start = text.rfind('\n', text.find("*fp")) + 1;
    CHECK(found.where.column == static_cast<int>(text.find("*fp") - line_start + 1));
  }
  // The session keeps its last valid state: nothing to save, the third where it was.
  CHECK_FALSE(session.dirty());
  CHECK(session.pose(session.inputs().rig.mounts[2]).xyz == third_before.xyz);
  CHECK_THROWS_AS(session.set_pose("front_lidar", {{0.5, 0, 0.25}, {0, 0, 0}}), model::InputError);
  CHECK_FALSE(session.dirty());
  // Another mount still moves, and the save leaves front_lidar's line byte for byte.
  session.set_pose("rear_lidar", {{-0.55, 0, 0.2}, {0, 0, 180}});
  session.save();
  CHECK(test::file_text(path) ==
        with_text_replaced(text, "xyz: [-0.5, 0, 0.2]", "xyz: [-0.55, 0, 0.2]"));
}

TEST_CASE("studio: an edit the rig loader would refuse is refused with its message", "[studio]") {
  // Reproducer 28: a pose 1e300 m away (the loader's limit is +-1e8 m).
  test::TempFolder folder;
  const std::string path = folder.write("far.yaml", cart_text());
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  try {
    session.set_pose("front_lidar", {{1e300, 0, 0.2}, {0, 0, 0}});
    FAIL("not refused");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().problem.find("beyond +-1e8 m") != std::string::npos);
    CHECK(error.diagnostics().front().field == "mounts[0].pose.xyz");
  }
  CHECK_FALSE(session.dirty());
  CHECK(session.pose(session.inputs().rig.mounts[0]).xyz == std::array<double, 3>{0.5, 0, 0.2});
}

TEST_CASE("studio: a mount added for a sensor whose id is no ROS name gets one, and loads",
          "[studio]") {
  // Reproducer 28: the library names the scanner `rplidar-a1m8`; a mount id may not have '-'.
  test::TempFolder folder;
  const std::string library = folder.write(
      "sensors.yaml", with_text_replaced(test::file_text(library_path()), "  - id: rplidar_a1m8\n",
                                         "  - id: rplidar-a1m8\n"));
  std::string text = cart_text();
  for (int i = 0; i < 2; ++i)
    text = with_text_replaced(text, "sensor: rplidar_a1m8", "sensor: rplidar-a1m8");
  const std::string path = folder.write("dash.yaml", text);
  studio::StudioSession session(path, library, "");
  REQUIRE(session.loaded());
  const std::string id = session.add_mount("rplidar-a1m8", "5_5hz", {{0, 0.4, 0.2}, {0, 0, 90}});
  CHECK(id == "rplidar_a1m8");
  session.save();
  CHECK(test::file_text(path) ==
        text +
            "  - {id: rplidar_a1m8, sensor: rplidar-a1m8, mode: 5_5hz, pose: {xyz: [0, 0.4, "
            "0.2], rpy_deg: [0, 0, 90]}}\n");
  // Read back as `check` reads it.
  CHECK_NOTHROW(io::load_rig_inputs(path, library, ""));
  REQUIRE(session.loaded());
  CHECK(session.inputs().rig.mounts.size() == 3);
}

TEST_CASE("studio: a save keeps the rig file's mode and its hard links", "[studio]") {
  // Reproducer 22.
  test::TempFolder folder;
  const std::string path = folder.write("private.yaml", cart_text());
  const std::string other = folder.path() + "/other_name.yaml";
  std::filesystem::create_hard_link(path, other);
  std::filesystem::permissions(
      path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  studio::StudioSession session(path, library_path(), "");
  REQUIRE(session.loaded());
  session.set_pose("rear_lidar", {{-0.55, 0, 0.2}, {0, 0, 180}});
  session.save();
  const std::string expected =
      with_text_replaced(cart_text(), "xyz: [-0.5, 0, 0.2]", "xyz: [-0.55, 0, 0.2]");
  CHECK(test::file_text(path) == expected);
  CHECK(test::file_text(other) == expected);
  CHECK(std::filesystem::hard_link_count(path) == 2);
  CHECK(std::filesystem::status(path).permissions() ==
        (std::filesystem::perms::owner_read | std::filesystem::perms::owner_write));
}
