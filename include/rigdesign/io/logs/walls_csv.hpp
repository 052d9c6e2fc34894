#pragma once
/// Reads and writes wall maps for `localize --walls`: CSV with header
/// `x1,y1,x2,y2,attenuation_db` (columns in any order), one wall segment per line, metres in
/// the log's frame, the loss in dB (>= 0) a radio path suffers crossing it. Errors name
/// file:line:column like the log readers.
#include <string>
#include <vector>

#include "rigdesign/localize/walls.hpp"

namespace rigdesign::io {

std::vector<localize::WallSegment> parse_walls_csv(const std::string& text,
                                                   const std::string& file);

std::vector<localize::WallSegment> read_walls_csv(const std::string& path);

std::string to_walls_csv(const std::vector<localize::WallSegment>& walls);

}  // namespace rigdesign::io
