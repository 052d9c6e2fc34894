// Every picture names the sensors it draws: the SVGs' text (real <text> elements) holds each
// mount of the rig and its sensor, read here from the rig file with yaml-cpp.
#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign::test;

namespace {

// The words of an SVG: the contents of its <text> elements, entities decoded.
std::string svg_words(const std::string& path) {
  std::ifstream file(path);
  REQUIRE(file);
  std::stringstream bytes;
  bytes << file.rdbuf();
  const std::string svg = bytes.str();
  std::string words;
  // <text ...>words</text>, found by hand (GCC 12 warns inside std::regex under the sanitizers).
  for (std::size_t open = svg.find("<text"); open != std::string::npos;
       open = svg.find("<text", open + 1)) {
    const std::size_t start = svg.find('>', open) + 1;
    const std::size_t end = svg.find("</text>", start);
    REQUIRE(end != std::string::npos);
    std::string text = svg.substr(start, end - start);
    for (const auto& [entity, character] : {std::pair{"&lt;", "<"}, std::pair{"&gt;", ">"},
                                            std::pair{"&quot;", "\""}, std::pair{"&amp;", "&"}}) {
      for (std::size_t at = text.find(entity); at != std::string::npos; at = text.find(entity))
        text.replace(at, std::string(entity).size(), character);
    }
    words += text + "\n";
  }
  return words;
}

struct MountNames {
  std::string id, sensor;
};

std::vector<MountNames> mounts_of(const std::string& rig_file) {
  std::vector<MountNames> mounts;
  for (const YAML::Node& mount : YAML::LoadFile(rig_file)["mounts"]) {
    mounts.push_back({mount["id"].as<std::string>(), mount["sensor"].as<std::string>()});
  }
  return mounts;
}

}  // namespace

TEST_CASE("coverage pictures name every mounted sensor in their SVG legends") {
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  TempFolder folder;
  const std::string out = folder.path() + "/cov";
  const CliResult result = run_cli({"coverage", rig, "--out", out, "--angles", "0"});
  REQUIRE(result.exit_code == 0);
  const std::vector<MountNames> mounts = mounts_of(rig);
  REQUIRE(mounts.size() == 5);
  for (const char* picture : {"sc_cartesian.svg", "sc_polar.svg", "section_0.svg",
                              "view_isometric.svg", "view_top.svg"}) {
    INFO(picture);
    const std::string words = svg_words(out + "/" + picture);
    CHECK(words.find("UR Cleaner") != std::string::npos);  // the title
    for (const MountNames& mount : mounts) {
      INFO(mount.id);
      CHECK(words.find(mount.id) != std::string::npos);
      CHECK(words.find(mount.sensor) != std::string::npos);
    }
  }
  // Units and scales: the charts' axes, the 3D views' scale bar.
  CHECK(svg_words(out + "/sc_cartesian.svg").find("azimuth theta [deg]") != std::string::npos);
  CHECK(svg_words(out + "/section_0.svg").find("[m]") != std::string::npos);
  const std::string top = svg_words(out + "/view_top.svg");
  bool scale_bar = false;  // a line that is a length: digits, then " m"
  std::istringstream lines(top);
  for (std::string line; std::getline(lines, line);) {
    scale_bar = scale_bar || (line.size() > 2 && line.substr(line.size() - 2) == " m" &&
                              line.find_first_not_of("0123456789.") == line.size() - 2);
  }
  CHECK(scale_bar);
}

TEST_CASE("a costmap frame has a cost legend, axes, a scale bar and names every sensor") {
  const std::string rig = source_path("rigs/ur_cleaner.yaml");
  TempFolder folder;
  const std::string out = folder.path() + "/cm";
  const CliResult result =
      run_cli({"costmap", rig, "--scenario", "wall_following", "--out", out, "--frame-every", "0"});
  REQUIRE(result.exit_code == 0);
  // The final frame as SVG: the same drawing routine, chosen by the extension.
  REQUIRE(std::ifstream(out + "/final.png").good());
  const std::string words = svg_words(out + "/final.svg");
  for (const char* legend : {"254 lethal: obstacle", "253 inscribed", "0 free", "255 unknown",
                             "kept by the Hit Layer only", "planned path", "driven trail",
                             "x [m] (world)", "y [m]", "1 m"}) {
    INFO(legend);
    CHECK(words.find(legend) != std::string::npos);
  }
  for (const MountNames& mount : mounts_of(rig)) {
    INFO(mount.id);
    CHECK(words.find(mount.id + ": " + mount.sensor) != std::string::npos);
  }
}
