#pragma once
/// Grids as ROS map_server files (DESIGN.md section 7): a binary PGM image and a YAML file
/// naming it with the resolution, the world position of the lower-left pixel, the thresholds
/// and `negate`. Trinary pixels: occupied 0, free 254, unknown 205; the image's first row is
/// the grid's largest y.
#include <cstdint>
#include <string>
#include <vector>

#include "rigdesign/costmap/rolling_grid.hpp"

namespace rigdesign::io {

/// A nav_msgs/OccupancyGrid in memory: -1 unknown, else 0..100, row-major from the lowest y.
struct OccupancyMap {
  int width = 0;
  int height = 0;
  double resolution = 0.05;  ///< [m]
  model::Vec2 origin =
      model::Vec2::Zero();  ///< world position of the lower-left corner of cell (0, 0) [m]
  std::vector<std::int8_t> cells;
};

constexpr std::int8_t kOccupancyUnknown = -1;

/// A costmap as nav2 publishes it (Costmap2DPublisher's translation table): 0 -> 0,
/// 1..252 -> 1 + 97 (c - 1) / 251 (integer division), 253 -> 99, 254 -> 100, 255 -> -1.
OccupancyMap to_occupancy_map(const costmap::CostGrid& grid);

/// map_saver's thresholds (occupancy as a fraction of 100), written into the YAML.
struct MapFileParams {
  double occupied_thresh = 0.65;
  /// The 0.25 (nav2 map_saver's default). Note nav2's own loader then reads the
  /// unknown shade 205 as free ((255 - 205) / 255 = 0.196 < 0.25); ROS 1 wrote 0.196 to avoid
  /// that, and read_map_files keeps 205 unknown (docs/costmap.md).
  double free_thresh = 0.25;
};

/// The trinary pixel of an occupancy value, as nav2's map_saver writes it: -1 -> 205,
/// <= free_thresh x 100 -> 254, >= occupied_thresh x 100 -> 0, anything between -> 205.
std::uint8_t trinary_pixel(std::int8_t occupancy, const MapFileParams& params = {});

/// Writes `yaml_path` and the image beside it (same name, extension .pgm), each atomically.
/// Throws InputError (field "output") when the folder is not writable.
void write_map_files(const OccupancyMap& map, const std::string& yaml_path,
                     const MapFileParams& params = {});

/// Reads a map_server YAML file and its PGM image (binary P5, 8 bits), trinary mode: a pixel
/// of shade v gives occ = (255 - v) / 255 (v / 255 with negate), occupied (100) above
/// occupied_thresh, free (0) below free_thresh, else unknown (-1); the unknown shade 205
/// always reads unknown. Throws InputError naming file:line:column and field on bad input.
OccupancyMap read_map_files(const std::string& yaml_path);

}  // namespace rigdesign::io
