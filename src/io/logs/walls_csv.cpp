#include "rigdesign/io/logs/walls_csv.hpp"

#include <array>
#include <cmath>

#include "io/logs/csv_fields.hpp"
#include "rigdesign/model/coordinate_limit.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/input_error.hpp"

namespace rigdesign::io {
namespace {

constexpr const char* kWallsHeader = "x1,y1,x2,y2,attenuation_db";
constexpr int kWallDigits = 10;
// One wall's loss: heavy concrete attenuates 2.4 GHz by about 10-25 dB; above 60 dB a wall
// is opaque, and larger numbers only push the fit to impossible exponents.
constexpr double kMaxWallLoss = 60.0;
// Every range evaluation crosses the whole map: a building's floor has hundreds of walls, and
// 10,000 keep a fit to seconds (200,000 ran for minutes).
constexpr std::size_t kMaxWalls = 10000;

}  // namespace

std::vector<localize::WallSegment> parse_walls_csv(const std::string& text,
                                                   const std::string& file) {
  const std::vector<std::string> names = {"x1", "y1", "x2", "y2", "attenuation_db"};
  std::vector<localize::WallSegment> walls;
  for (const csv::Row& row : csv::named_columns(text, file, names, kWallsHeader)) {
    std::array<double, 5> value{};
    for (std::size_t i = 0; i < names.size(); ++i) {
      const csv::Field& f = row.fields[i];
      value[i] = csv::parse_number(f, {file, row.number, f.column}, names[i]);
    }
    if (value[4] < 0.0 || value[4] > kMaxWallLoss) {
      throw model::InputError(model::Diagnostic{{file, row.number, row.fields[4].column},
                                                "attenuation_db",
                                                "is " + model::format_number(value[4]) + " dB",
                                                "a loss in dB in [0, 60], e.g. 8"});
    }
    for (std::size_t i = 0; i < 4; ++i) {
      if (std::abs(value[i]) > model::kMaxCoordinate) {
        throw model::InputError(
            model::Diagnostic{{file, row.number, row.fields[i].column},
                              names[i],
                              "is " + model::format_number(value[i]) + " m, beyond +-1e8 m",
                              "coordinates within +-1e8 m, in the log's frame"});
      }
    }
    if (walls.size() == kMaxWalls) {
      throw model::InputError(model::Diagnostic{{file, row.number, 1},
                                                "walls",
                                                "more than 10000 walls",
                                                "at most 10000 walls (merge collinear segments)"});
    }
    walls.push_back({{value[0], value[1]}, {value[2], value[3]}, value[4]});
  }
  return walls;
}

std::vector<localize::WallSegment> read_walls_csv(const std::string& path) {
  return parse_walls_csv(csv::read_text_file(path), path);
}

std::string to_walls_csv(const std::vector<localize::WallSegment>& walls) {
  std::string text = std::string(kWallsHeader) + "\n";
  for (const localize::WallSegment& w : walls) {
    text += model::format_number(w.a.x(), kWallDigits) + "," +
            model::format_number(w.a.y(), kWallDigits) + "," +
            model::format_number(w.b.x(), kWallDigits) + "," +
            model::format_number(w.b.y(), kWallDigits) + "," +
            model::format_number(w.attenuation_db, kWallDigits) + "\n";
  }
  return text;
}

}  // namespace rigdesign::io
