#include "coverage_chart_parts.hpp"

#include <algorithm>
#include <cmath>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::render {

std::string coverage_title(const metrics::RigCoverage& coverage, const std::string& rig_name) {
  return rig_name + ": spatial coverage, d = " + model::format_number(coverage.distance) +
         " m, h = " + model::format_number(coverage.height) + " m";
}

std::vector<std::pair<double, double>> sector_ranges_deg(const model::SectorRequirement& sector) {
  double from = std::fmod(model::rad_to_deg(sector.from), 360.0);
  if (from < 0) from += 360.0;
  const double to = from + model::rad_to_deg(sector.to - sector.from);
  if (to <= 360.0) return {{from, to}};
  return {{from, 360.0}, {0.0, to - 360.0}};
}

std::vector<std::pair<double, double>> mount_spans(const metrics::RigCoverage& coverage,
                                                   std::size_t mount) {
  std::vector<std::pair<double, double>> spans;
  const std::size_t n = coverage.angles.size();
  if (n == 0) return spans;
  const double half = 180.0 / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::vector<bool>& sees = coverage.angles[i].mount_sees;
    if (mount >= sees.size() || !sees[mount]) continue;
    const double centre = model::rad_to_deg(coverage.angles[i].theta);
    const double from = std::max(0.0, centre - half), to = std::min(360.0, centre + half);
    if (!spans.empty() && std::abs(spans.back().second - from) < 1e-6) {
      spans.back().second = to;
    } else {
      spans.emplace_back(from, to);
    }
  }
  return spans;
}

std::string mount_label(const metrics::RigCoverage& coverage, std::size_t mount) {
  const std::string sensor =
      mount < coverage.mount_sensors.size() ? coverage.mount_sensors[mount] : "";
  return coverage.mount_ids[mount] + (sensor.empty() ? "" : " (" + sensor + ")");
}

void legend_line(cairo_t* cairo, double x, double y, const Rgb& colour, bool dashed,
                 const std::string& label) {
  set_colour(cairo, colour);
  cairo_set_line_width(cairo, 2.5);
  const double dash[] = {6.0, 4.0};
  cairo_set_dash(cairo, dash, dashed ? 2 : 0, 0);
  cairo_move_to(cairo, x, y - 4);
  cairo_line_to(cairo, x + 30, y - 4);
  cairo_stroke(cairo);
  cairo_set_dash(cairo, nullptr, 0, 0);
  set_colour(cairo, kInkColour);
  draw_text(cairo, label, x + 38, y, 14);
}

void legend_box(cairo_t* cairo, double x, double y, const Rgb& colour, const std::string& label,
                double size) {
  set_colour(cairo, colour);
  cairo_rectangle(cairo, x, y - 11, 30, 12);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, label, x + 38, y, size);
}

}  // namespace rigdesign::render
