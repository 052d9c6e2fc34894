#include "rigdesign/io/maps/map_files.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "rigdesign/costmap/cost_values.hpp"
#include "rigdesign/io/atomic_write.hpp"
#include "rigdesign/io/config/yaml_reader.hpp"
#include "rigdesign/io/file_bytes.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

// map_server's trinary shades.
constexpr std::uint8_t kOccupiedPixel = 0;
constexpr std::uint8_t kFreePixel = 254;
constexpr std::uint8_t kUnknownPixel = 205;
constexpr int kFullShade = 255;

// Shortest text that reads back to the same double.
std::string exact(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::int8_t occupancy_of_cost(std::uint8_t c) {
  if (c == costmap::cost::kUnknown) return kOccupancyUnknown;
  if (c == costmap::cost::kLethal) return 100;
  if (c == costmap::cost::kInscribed) return 99;
  if (c == costmap::cost::kFree) return 0;
  return static_cast<std::int8_t>(1 + (97 * (c - 1)) / 251);  // nav2's integer translation
}

[[noreturn]] void bad_image(const std::string& file, const std::string& problem,
                            const std::string& expected) {
  throw model::InputError(
      model::Diagnostic{model::SourceLocation{file, 0, 0}, "image", problem, expected});
}

// Skips whitespace and '#' comments between PGM header tokens.
void skip_separators(const std::string& bytes, std::size_t& at) {
  while (at < bytes.size()) {
    if (bytes[at] == '#') {
      while (at < bytes.size() && bytes[at] != '\n') ++at;
    } else if (std::isspace(static_cast<unsigned char>(bytes[at]))) {
      ++at;
    } else {
      return;
    }
  }
}

int header_number(const std::string& bytes, std::size_t& at, const std::string& file,
                  const std::string& what) {
  skip_separators(bytes, at);
  int value = 0;
  const auto result = std::from_chars(bytes.data() + at, bytes.data() + bytes.size(), value);
  if (result.ec != std::errc() || value <= 0)
    bad_image(file, "has no valid " + what + " in its header", "a binary PGM (P5)");
  at = static_cast<std::size_t>(result.ptr - bytes.data());
  return value;
}

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> shades;  // 0..255, first row first (the top of the image)
};

Image read_pgm(const std::string& file) {
  const std::string bytes = read_file_bytes(file, "a readable binary PGM (P5) file");
  if (bytes.size() < 2 || bytes.compare(0, 2, "P5") != 0)
    bad_image(file, "is not a binary PGM", "a file starting with P5");
  std::size_t at = 2;
  Image image;
  image.width = header_number(bytes, at, file, "width");
  image.height = header_number(bytes, at, file, "height");
  const int max_value = header_number(bytes, at, file, "maximum value");
  if (max_value > kFullShade)
    bad_image(file, "has 16-bit pixels", "8-bit pixels (maximum value <= 255)");
  ++at;  // the single whitespace byte before the pixels
  const std::size_t count =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (bytes.size() < at + count) {
    bad_image(file,
              "holds " + std::to_string(bytes.size() - std::min(at, bytes.size())) + " pixel bytes",
              std::to_string(count) + " bytes for " + std::to_string(image.width) + " x " +
                  std::to_string(image.height) + " pixels");
  }
  image.shades.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto v = static_cast<std::uint8_t>(bytes[at + i]);
    image.shades[i] = static_cast<std::uint8_t>(v * kFullShade / max_value);
  }
  return image;
}

}  // namespace

OccupancyMap to_occupancy_map(const costmap::CostGrid& grid) {
  OccupancyMap map;
  map.width = grid.width();
  map.height = grid.height();
  map.resolution = grid.window().resolution;
  map.origin = grid.window().origin();
  map.cells.resize(grid.cells().size());
  for (std::size_t i = 0; i < map.cells.size(); ++i)
    map.cells[i] = occupancy_of_cost(grid.cells()[i]);
  return map;
}

std::uint8_t trinary_pixel(std::int8_t occupancy, const MapFileParams& params) {
  if (occupancy < 0 || occupancy > 100) return kUnknownPixel;
  if (occupancy <= params.free_thresh * 100) return kFreePixel;
  if (occupancy >= params.occupied_thresh * 100) return kOccupiedPixel;
  return kUnknownPixel;
}

void write_map_files(const OccupancyMap& map, const std::string& yaml_path,
                     const MapFileParams& params) {
  const std::filesystem::path image_path =
      std::filesystem::path(yaml_path).replace_extension(".pgm");
  std::string pgm =
      "P5\n" + std::to_string(map.width) + " " + std::to_string(map.height) + "\n255\n";
  pgm.reserve(pgm.size() + map.cells.size());
  // The image's first row is the grid's last (largest y), as map_server expects.
  for (int y = map.height - 1; y >= 0; --y) {
    for (int x = 0; x < map.width; ++x) {
      pgm.push_back(static_cast<char>(
          trinary_pixel(map.cells[static_cast<std::size_t>(y) * map.width + x], params)));
    }
  }
  write_file_atomically(image_path.string(), pgm);
  std::ostringstream yaml;
  yaml << "image: " << image_path.filename().string() << "\n"
       << "mode: trinary\n"
       << "resolution: " << exact(map.resolution) << "\n"
       << "origin: [" << exact(map.origin.x()) << ", " << exact(map.origin.y()) << ", 0]\n"
       << "negate: 0\n"
       << "occupied_thresh: " << exact(params.occupied_thresh) << "\n"
       << "free_thresh: " << exact(params.free_thresh) << "\n";
  write_file_atomically(yaml_path, yaml.str());
}

OccupancyMap read_map_files(const std::string& yaml_path) {
  model::Diagnostics diagnostics;
  const YAML::Node root = io::load_yaml_file(yaml_path);
  io::MapReader top(root, "", yaml_path, diagnostics, {yaml_path, 1, 1});
  const auto image =
      top.text("image", io::Need::required, "the PGM file's path, relative to this file");
  const auto resolution = top.number("resolution", io::Need::required, "metres per pixel, > 0");
  top.require(!resolution || *resolution > 0, "resolution", "is not positive",
              "metres per pixel, > 0");
  const auto origin =
      top.numbers("origin", io::Need::required, 3, 3, "[x, y, yaw] of the lower-left pixel");
  if (origin)
    top.require((*origin)[2] == 0.0, "origin", "has a non-zero yaw",
                "[x, y, 0] (rotated maps are not supported)");
  const auto negate = top.integer("negate", io::Need::optional, "0 or 1");
  top.require(!negate || *negate == 0 || *negate == 1, "negate", "is not 0 or 1", "0 or 1");
  const auto occupied_thresh =
      top.number("occupied_thresh", io::Need::required, "a fraction in (0, 1]");
  const auto free_thresh = top.number("free_thresh", io::Need::required, "a fraction in [0, 1)");
  top.require(!occupied_thresh || !free_thresh || *free_thresh < *occupied_thresh, "free_thresh",
              "is not below occupied_thresh", "free_thresh < occupied_thresh");
  top.choice("mode", io::Need::optional, {"trinary"});
  top.reject_unknown_keys();
  diagnostics.throw_if_errors();

  std::filesystem::path image_path(*image);
  if (image_path.is_relative())
    image_path = std::filesystem::path(yaml_path).parent_path() / image_path;
  const Image pgm = read_pgm(image_path.string());
  OccupancyMap map;
  map.width = pgm.width;
  map.height = pgm.height;
  map.resolution = *resolution;
  map.origin = model::Vec2((*origin)[0], (*origin)[1]);
  map.cells.resize(pgm.shades.size());
  const bool negated = negate.value_or(0) == 1;
  for (int row = 0; row < pgm.height; ++row) {
    const int y = pgm.height - 1 - row;  // the first row is the largest y
    for (int x = 0; x < pgm.width; ++x) {
      const std::uint8_t shade = pgm.shades[static_cast<std::size_t>(row) * pgm.width + x];
      const double occ = (negated ? shade : kFullShade - shade) / static_cast<double>(kFullShade);
      std::int8_t value = kOccupancyUnknown;
      if (occ > *occupied_thresh) {
        value = 100;
      } else if (occ < *free_thresh && !(shade == kUnknownPixel && !negated)) {
        value = 0;
      }
      map.cells[static_cast<std::size_t>(y) * pgm.width + x] = value;
    }
  }
  return map;
}

}  // namespace rigdesign::io
