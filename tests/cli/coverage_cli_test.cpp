#include <cairo.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "rigdesign/geometry/cross_section.hpp"
#include "rigdesign/render/coverage_plots.hpp"
#include "rigdesign/render/palette.hpp"
#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

struct Png {
  int width = 0;
  int height = 0;
  cairo_surface_t* surface = nullptr;
  explicit Png(const std::string& path) {
    surface = cairo_image_surface_create_from_png(path.c_str());
    REQUIRE(cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS);
    width = cairo_image_surface_get_width(surface);
    height = cairo_image_surface_get_height(surface);
  }
  ~Png() { cairo_surface_destroy(surface); }
  // (r, g, b) in [0, 255] of an opaque pixel.
  std::array<int, 3> at(double x, double y) const {
    const auto* data = cairo_image_surface_get_data(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const auto pixel = *reinterpret_cast<const std::uint32_t*>(data + static_cast<int>(y) * stride +
                                                               static_cast<int>(x) * 4);
    return {static_cast<int>((pixel >> 16) & 255), static_cast<int>((pixel >> 8) & 255),
            static_cast<int>(pixel & 255)};
  }
};

// A camera on the front of a 0.5 m body at z = 0.5 m looking forward, 60 x 40 deg: in the
// forward section it sees |z - 0.5| <= tan(20 deg) (rho - 0.5).
const std::string kWedgeLibrary = R"(reference_machine: test
sensors:
  - id: cam
    name: Camera
    technology: tof
    source: test
    price: {usd: 100, year: 2020, basis: estimate, source: test}
    modes:
      - {id: m, frequency: 10, pixels: [600, 400], bytes_per_point: 2, noise: {a: 0.01},
         fov: {shape: pyramid, horizontal_deg: 60, vertical_deg: 40}, range: {min: 0.0, max: 10},
         light: {dark: true, indoor: true, sunlight: true}, driver_cpu: {cores: 0.1, basis: estimate}}
)";
const std::string kWedgeRig = R"(name: Wedge
sensor_library: sensors.yaml
body: {radius: 0.5, height: 1.0}
distance_of_interest: 3.5
mounts:
  - {id: front, sensor: cam, mode: m, pose: {xyz: [0.5, 0, 0.5]}}
)";

}  // namespace

TEST_CASE("coverage writes curves, sections, 3D views, CSV and JSON") {
  TempFolder folder;
  const std::string out = folder.path() + "/out";
  const CliResult result = run_cli({"coverage", source_path("rigs/ur_cleaner.yaml"), "--out", out,
                                    "--angles", "0,90", "--step", "10"});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  for (const char* name :
       {"sc_cartesian.png", "sc_cartesian.svg", "sc_polar.png", "sc_polar.svg", "section_0.png",
        "section_90.svg", "view_isometric.png", "view_top.png", "coverage.csv", "coverage.json"}) {
    INFO(name);
    CHECK(std::filesystem::file_size(out + "/" + name) > 100);
  }
  const Png cartesian(out + "/sc_cartesian.png");
  CHECK(cartesian.width == 1200);
  CHECK(cartesian.height == 620 + 30 + 16 * 5);  // the chart, then a 16 px strip per mount
  std::ifstream csv(out + "/coverage.csv");
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  CHECK(lines == 1 + 36);  // header + one row per 10 degrees
  std::ifstream json_file(out + "/coverage.json");
  const auto json = nlohmann::json::parse(json_file);
  CHECK(json["curves"].size() == 36);
  CHECK(json["sectors"].size() == 4);
}

TEST_CASE("a cross-section image shows the sensor's colour where it sees and white where not") {
  TempFolder folder;
  folder.write("sensors.yaml", kWedgeLibrary);
  const std::string rig = folder.write("rig.yaml", kWedgeRig);
  const std::string out = folder.path() + "/out";
  REQUIRE(run_cli({"coverage", rig, "--out", out, "--angles", "0", "--step", "30", "--no-3d"})
              .exit_code == 0);
  const Png image(out + "/section_0.png");
  geometry::SectionFrame frame;
  frame.r = 0.5;
  frame.d = 3.5;
  frame.h = 1.0;
  const render::SectionLayout layout = render::section_layout(frame, 1);
  CHECK(image.width == layout.width);
  CHECK(image.height == layout.height);
  // (rho 3.1, z 0.6) is inside the wedge: the sensor colour at 45 % over white.
  const render::Rgb colour = render::sensor_colour(0);
  const auto seen = image.at(layout.x(3.1), layout.y(0.6));
  const auto expected = [](double c) {
    return static_cast<int>(std::lround(255 * (0.55 + 0.45 * c)));
  };
  CHECK(std::abs(seen[0] - expected(colour.r)) <= 3);
  CHECK(std::abs(seen[1] - expected(colour.g)) <= 3);
  CHECK(std::abs(seen[2] - expected(colour.b)) <= 3);
  // (rho 1.1, z 0.9) is above the wedge (it is 0.22 m tall there): background white.
  const auto unseen = image.at(layout.x(1.1), layout.y(0.9));
  CHECK(unseen == std::array<int, 3>{255, 255, 255});
}

TEST_CASE("coverage refuses bad options before writing anything") {
  TempFolder folder;
  const std::string out = folder.path() + "/out";
  const CliResult result =
      run_cli({"coverage", source_path("rigs/ur_cleaner.yaml"), "--out", out, "--step", "0"});
  CHECK(result.exit_code == 2);
  CHECK(result.err.find("--step") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out));
}
