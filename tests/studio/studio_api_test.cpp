// Issue 37: the studio's JSON API on the bundled cart, called as the page calls it. Expected
// values are read off sensors.yaml's text or written by hand.
#include "rigdesign/studio/studio_api.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

struct ApiFixture {
  test::TempFolder folder;
  std::string path;
  std::unique_ptr<studio::StudioSession> session;
  std::unique_ptr<studio::StudioApi> api;

  // `edit`: changes the cart's text before it is served.
  explicit ApiFixture(std::string (*edit)(std::string) = nullptr) {
    std::string text = test::file_text(test::source_path("rigs/cart_two_scanners.yaml"));
    const std::string from = "requirements: requirements/cart_two_scanners.yaml";
    text.replace(text.find(from), from.size(),
                 "requirements: " + test::source_path("rigs/requirements/cart_two_scanners.yaml"));
    if (edit != nullptr) text = edit(text);
    path = folder.write("cart.yaml", text);
    session = std::make_unique<studio::StudioSession>(path, test::source_path("sensors.yaml"), "");
    api = std::make_unique<studio::StudioApi>(*session, [](const std::string&) {
      return std::pair<int, std::string>{0, "checked"};
    });
  }

  std::pair<int, nlohmann::json> call(const std::string& method, const std::string& name,
                                      const std::string& query = "", const std::string& body = "") {
    const studio::Reply reply = (*api)(method, name, query, body);
    return {reply.status, reply.content_type.rfind("application/json", 0) == 0
                              ? nlohmann::json::parse(reply.body)
                              : nlohmann::json(reply.body)};
  }
};

}  // namespace

TEST_CASE("studio API: the sensor list answers `sensors`' filters", "[studio]") {
  ApiFixture fixture;
  // sensors.yaml: the RPLIDAR A1 (A1M8) is lidar_2d with modes 5_5hz (5.5 Hz) and 10hz (10 Hz);
  // at 7 Hz or more only its 10hz mode answers.
  auto [status, reply] = fixture.call("GET", "sensors", "technology=lidar_2d&min_rate=7");
  REQUIRE(status == 200);
  bool found = false;
  for (const nlohmann::json& sensor : reply["sensors"]) {
    if (sensor["id"] != "rplidar_a1m8") continue;
    found = true;
    CHECK(sensor["modes"] == nlohmann::json::array({"10hz"}));
  }
  CHECK(found);
  // The search text arrives percent-encoded; "RPLIDAR A1" is in the name of the A1M8 only
  // ("RPLIDAR A2", "S2", "S3" are the others).
  std::tie(status, reply) = fixture.call("GET", "sensors", "search=RPLIDAR%20A1");
  REQUIRE(reply["sensors"].size() == 1);
  CHECK(reply["sensors"][0]["id"] == "rplidar_a1m8");
  CHECK(fixture.call("GET", "sensors", "min_rate=fast").first == 400);
  CHECK(fixture.call("GET", "sensors", "max_price=-1").first == 400);
}

TEST_CASE("studio API: malformed edits are 400, invalid ones 422 with check's words", "[studio]") {
  ApiFixture fixture;
  CHECK(fixture.call("POST", "pose", "", "{not json").first == 400);
  CHECK(fixture.call("POST", "pose", "", R"({"mount": "front_lidar", "xyz": [0, 0]})").first ==
        400);
  CHECK(fixture
            .call("POST", "pose", "",
                  R"({"mount": "front_lidar", "xyz": [0, 0, 1e999], "rpy_deg": [0, 0, 0]})")
            .first == 400);
  const auto [status, reply] = fixture.call(
      "POST", "pose", "", R"({"mount": "front_lidar", "xyz": [0, 0, 0.2], "rpy_deg": [0, 0, 0]})");
  CHECK(status == 422);
  REQUIRE(reply["error"].is_array());
  // The cart's prism spans x in [-0.3, 0.3]: the origin is inside, reported at the mount's pose.
  CHECK(reply["error"][0]["field"].get<std::string>().find("mounts[0].pose") == 0);
  // Its line: the rig file's line holding front_lidar's entry, counted here.
  const std::string rig_text = test::file_text(test::source_path("rigs/cart_two_scanners.yaml"));
  const std::size_t entry = rig_text.find("{id: front_lidar");
  REQUIRE(entry != std::string::npos);
  const auto line =
      1 + std::count(rig_text.begin(), rig_text.begin() + static_cast<long>(entry), '\n');
  CHECK(reply["error"][0]["line"] == line);
  CHECK(fixture.call("GET", "nothing").first == 404);
  // A valid move answers with the numbers on the raster path, then saves through check.
  const auto [moved, numbers] =
      fixture.call("POST", "pose", "",
                   R"({"mount": "front_lidar", "xyz": [0.5, 0, 0.3], "rpy_deg": [0, 0, 0]})");
  CHECK(moved == 200);
  CHECK(numbers["exact"] == false);
  CHECK(numbers["dirty"] == true);
  CHECK(numbers["coverage"]["curve_complete"].size() == 360);
  const auto [saved, state] = fixture.call("POST", "save");
  CHECK(saved == 200);
  CHECK(state["check"]["report"] == "checked");
  CHECK(test::file_text(fixture.path).find("pose: {xyz: [0.5, 0, 0.3], rpy_deg: [0, 0, 0]}") !=
        std::string::npos);
}

TEST_CASE("studio API: a pose reply carries the moved mount's B2 verdict, live on a drag",
          "[studio]") {
  ApiFixture fixture;
  // rear_lidar onto front_lidar's pose (turned about z): the same RPLIDAR housing in one place.
  const auto [status, onto] = fixture.call(
      "POST", "pose", "", R"({"mount": "rear_lidar", "xyz": [0.5, 0, 0.2], "rpy_deg": [0, 0, 0]})");
  REQUIRE(status == 200);
  CHECK(onto["exact"] == false);  // the raster path, as while dragging
  CHECK(onto["clash"]["mount"] == "rear_lidar");
  const std::string text = onto["clash"]["text"].get<std::string>();
  CHECK(text.find("rear_lidar's housing") == 0);
  CHECK(text.find("front_lidar") != std::string::npos);
  CHECK(text.find("(check: B2)") != std::string::npos);
  // Back where the rig file has it: nothing.
  const auto [back_status, back] =
      fixture.call("POST", "pose", "",
                   R"({"mount": "rear_lidar", "xyz": [-0.5, 0, 0.2], "rpy_deg": [0, 0, 180]})");
  REQUIRE(back_status == 200);
  CHECK(back["clash"]["text"] == "");
}

TEST_CASE("studio API: an edit through a YAML alias is 422 at the alias; the state is kept",
          "[studio]") {
  // Reproducer 21: third's pose is front_lidar's, by alias.
  ApiFixture fixture([](std::string text) {
    const std::string front = "pose: {xyz: [0.5, 0, 0.2]";
    text.replace(text.find(front), front.size(), "pose: &fp {xyz: [0.5, 0, 0.2]");
    return text + "  - {id: third, sensor: rplidar_a1m8, mode: 5_5hz, pose: *fp}\n";
  });
  const std::string before = test::file_text(fixture.path);
  const auto [status, reply] = fixture.call(
      "POST", "pose", "", R"({"mount": "third", "xyz": [0.5, 0, 0.45], "rpy_deg": [0, 0, 0]})");
  CHECK(status == 422);
  REQUIRE(reply["error"].is_array());
  // The file's last line holds the alias, counted here.
  CHECK(reply["error"][0]["line"] == std::count(before.begin(), before.end(), '\n'));
  CHECK(reply["error"][0]["problem"].get<std::string>().find("alias *fp") != std::string::npos);
  // Nothing changed: the state has third where it was, a save writes nothing new.
  const auto [state_status, state] = fixture.call("GET", "state");
  REQUIRE(state_status == 200);
  CHECK(state["numbers"]["dirty"] == false);
  CHECK(state["numbers"]["mounts"][2]["xyz"][2] == 0.2);
  CHECK(fixture.call("POST", "save").first == 200);
  CHECK(test::file_text(fixture.path) == before);
}

TEST_CASE("studio API: a pose the rig loader refuses is 422 with its message", "[studio]") {
  ApiFixture fixture;
  const std::string before = test::file_text(fixture.path);
  const auto [status, reply] =
      fixture.call("POST", "pose", "",
                   R"({"mount": "front_lidar", "xyz": [1e300, 0, 0.2], "rpy_deg": [0, 0, 0]})");
  CHECK(status == 422);
  CHECK(reply["error"][0]["problem"].get<std::string>().find("beyond +-1e8 m") !=
        std::string::npos);
  CHECK(fixture.call("POST", "save").first == 200);
  CHECK(test::file_text(fixture.path) == before);
}
