// `rigdesign report`: the page is self-contained and a real browser renders it. Headless
// Chromium (Debian's chromium, installed by scripts/setup.sh) loads it from disk with the
// network off, dumps the DOM and takes a screenshot.
#include <cairo.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

std::string report_file_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream bytes;
  bytes << file.rdbuf();
  return bytes.str();
}

// The flags that keep Chromium off the network and out of a user profile (as root it needs
// --no-sandbox); `action` is --dump-dom or --screenshot=FILE.
int chromium(const std::string& profile, const std::string& action, const std::string& page,
             const std::string& out, const std::string& log) {
  const std::string command =
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--hide-scrollbars --window-size=1280,2400 --enable-logging=stderr --v=0 "
      "--user-data-dir=" +
      profile + " " + action + " file://" + page + " >" + out + " 2>" + log;
  return std::system(command.c_str());
}

}  // namespace

TEST_CASE("report writes one self-contained page that headless Chromium renders", "[report]") {
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  TempFolder folder;
  const std::string out = folder.path() + "/report";
  const CliResult result = run_cli({"report", rig, "--out", out, "--step", "5"});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  const std::string page = out + "/report.html";
  const std::string html = report_file_text(page);

  // Self-contained: nothing fetched (the only http URIs are XML namespace names).
  for (const char* fetch : {"src=\"http", "href=\"http", "url(http", "<script", "<link"}) {
    INFO(fetch);
    CHECK(html.find(fetch) == std::string::npos);
  }

  const std::string dom = folder.path() + "/dom.html";
  const std::string log = folder.path() + "/chromium.log";
  REQUIRE(chromium(folder.path() + "/profile-dom", "--dump-dom", page, dom, log) == 0);
  const std::string rendered = report_file_text(dom);
  for (const char* id :
       {"id=\"verdicts\"", "id=\"metrics\"", "id=\"sc-cartesian\"", "id=\"sc-polar\"",
        "id=\"section-0\"", "id=\"view-isometric\"", "id=\"n-1\"", "id=\"cost\""}) {
    INFO(id);
    CHECK(rendered.find(id) != std::string::npos);
  }
  // Every mount and its sensor, from the rig file's text, is in the page the browser built.
  for (const YAML::Node& mount : YAML::LoadFile(rig)["mounts"]) {
    CHECK(rendered.find(mount["id"].as<std::string>()) != std::string::npos);
    CHECK(rendered.find(mount["sensor"].as<std::string>()) != std::string::npos);
  }
  // Paper 1's Table 1 for the UR Cleaner: F = 15 Hz, R = 122.2 mm (the VLP-16), N = 30 mm.
  CHECK(rendered.find("15.0 Hz") != std::string::npos);
  CHECK(rendered.find("122.2 mm") != std::string::npos);
  // No console errors: a failed load or a script error would be logged as one.
  const std::string messages = report_file_text(log);
  INFO(messages);
  CHECK(messages.find("Uncaught") == std::string::npos);
  CHECK(messages.find("Failed to load resource") == std::string::npos);
  CHECK(messages.find(":ERROR:CONSOLE") == std::string::npos);

  const std::string shot = folder.path() + "/shot.png";
  REQUIRE(chromium(folder.path() + "/profile-shot", "--screenshot=" + shot, page,
                   folder.path() + "/shot.out", folder.path() + "/shot.log") == 0);
  cairo_surface_t* surface = cairo_image_surface_create_from_png(shot.c_str());
  REQUIRE(cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  long inked = 0, curve_blue = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto pixel = *reinterpret_cast<const std::uint32_t*>(data + y * stride + x * 4);
      const int r = (pixel >> 16) & 255, g = (pixel >> 8) & 255, b = pixel & 255;
      inked += (r + g + b < 600) ? 1 : 0;
      // The SC complete curve's blue, (0.12, 0.35, 0.75) x 255.
      curve_blue +=
          (std::abs(r - 31) < 25 && std::abs(g - 89) < 25 && std::abs(b - 191) < 25) ? 1 : 0;
    }
  }
  cairo_surface_destroy(surface);
  CHECK(width == 1280);
  CHECK(inked > width * height / 50);  // text, tables and pictures, not a blank page
  CHECK(curve_blue > 200);             // the SC chart was drawn
}
