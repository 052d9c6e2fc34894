#include "rigdesign/io/maps/map_files.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "rigdesign/model/input_error.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;

namespace {

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("costs translate to occupancy as nav2 publishes them", "[costmap]") {
  costmap::GridWindow window;
  window.width = 7;
  window.height = 1;
  costmap::CostGrid grid(window, 0);
  grid.cells() = {0, 1, 252, 253, 254, 255, 128};
  const io::OccupancyMap map = io::to_occupancy_map(grid);
  // 1 + 97 (c - 1) / 251 in integers: c = 1 -> 1, 252 -> 98, 128 -> 1 + 12319 / 251 = 50.
  CHECK(map.cells == std::vector<std::int8_t>{0, 1, 98, 99, 100, -1, 50});
}

TEST_CASE("a map written as PGM + YAML reads back (map_server convention)", "[costmap]") {
  test::TempFolder folder;
  io::OccupancyMap map;
  map.width = 3;
  map.height = 2;
  map.resolution = 0.05;
  map.origin = model::Vec2(-1.5, 2.25);
  // Row y = 0 then y = 1.
  map.cells = {0, 100, -1, 50, 20, 70};
  const std::string yaml = folder.path() + "/local.yaml";
  io::write_map_files(map, yaml);
  // Pixels, first row = largest y: y = 1 gives 50 -> 205 (between the thresholds), 20 -> 254
  // (<= 25), 70 -> 0 (>= 65); y = 0 gives 0 -> 254, 100 -> 0, -1 -> 205.
  const std::string pgm = contents(folder.path() + "/local.pgm");
  const std::string header = "P5\n3 2\n255\n";
  REQUIRE(pgm.size() == header.size() + 6);
  CHECK(pgm.substr(0, header.size()) == header);
  const std::string pixels = pgm.substr(header.size());
  CHECK(std::vector<unsigned char>(pixels.begin(), pixels.end()) ==
        std::vector<unsigned char>{205, 254, 0, 254, 0, 205});
  const std::string text = contents(yaml);
  CHECK(text.find("image: local.pgm\n") != std::string::npos);
  CHECK(text.find("origin: [-1.5, 2.25, 0]\n") != std::string::npos);
  CHECK(text.find("occupied_thresh: 0.65\n") != std::string::npos);
  CHECK(text.find("free_thresh: 0.25\n") != std::string::npos);
  CHECK(text.find("negate: 0\n") != std::string::npos);

  const io::OccupancyMap back = io::read_map_files(yaml);
  CHECK(back.width == 3);
  CHECK(back.height == 2);
  CHECK(back.resolution == 0.05);
  CHECK(back.origin == model::Vec2(-1.5, 2.25));
  CHECK(back.cells == std::vector<std::int8_t>{0, 100, -1, -1, 0, 100});
}

TEST_CASE("reading a map applies the thresholds and negate to other shades", "[costmap]") {
  test::TempFolder folder;
  // One row: shades 0, 100, 200, 255. occ = (255 - v) / 255 = 1, 0.61, 0.22, 0.
  folder.write("m.pgm", std::string("P5\n# a comment\n4 1\n255\n") +
                            std::string{'\x00', '\x64', '\xc8', '\xff'});
  folder.write("m.yaml",
               "image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n"
               "occupied_thresh: 0.6\nfree_thresh: 0.25\n");
  CHECK(io::read_map_files(folder.path() + "/m.yaml").cells ==
        std::vector<std::int8_t>{100, 100, 0, 0});
  folder.write("n.yaml",
               "image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 1\n"
               "occupied_thresh: 0.6\nfree_thresh: 0.25\n");
  // negate: occ = v / 255 = 0, 0.39, 0.78, 1.
  CHECK(io::read_map_files(folder.path() + "/n.yaml").cells ==
        std::vector<std::int8_t>{0, -1, 100, 100});
}

TEST_CASE("bad map files name the file, line and field", "[costmap]") {
  test::TempFolder folder;
  const std::string yaml = folder.write("bad.yaml",
                                        "image: m.pgm\nresolution: -0.1\norigin: [0, 0, 0]\n"
                                        "occupied_thresh: 0.65\nfree_thresh: 0.25\n");
  try {
    io::read_map_files(yaml);
    FAIL("expected an error");
  } catch (const model::InputError& error) {
    const model::Diagnostic& d = error.diagnostics().front();
    CHECK(d.field == "resolution");
    CHECK(d.where.file == yaml);
    CHECK(d.where.line == 2);
  }
  folder.write("short.pgm", "P5\n4 4\n255\nab");
  const std::string truncated =
      folder.write("t.yaml",
                   "image: short.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n"
                   "occupied_thresh: 0.65\nfree_thresh: 0.25\n");
  try {
    io::read_map_files(truncated);
    FAIL("expected an error");
  } catch (const model::InputError& error) {
    CHECK(error.diagnostics().front().field == "image");
    CHECK(error.diagnostics().front().where.file.find("short.pgm") != std::string::npos);
    CHECK(error.diagnostics().front().expected.find("16 bytes") != std::string::npos);
  }
}
