// SC around the robot seen from above: the radius is the coverage share, with one ring per
// mount outside the 100 % circle showing the angles where it sees the section.
#include <cmath>
#include <numbers>
#include <tuple>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "coverage_chart_parts.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"

namespace rigdesign::render {
namespace {

constexpr double kRingStep = 0.035;     // a mount ring's width, as a share of the radius
constexpr double kSpokeStep = 45.0;     // [deg]
constexpr double kRingTickStep = 25.0;  // [%]

struct PolarChart {
  double cx, cy, radius;
  double ring_outer;  // beyond the mount rings, as a share of the radius
  // Robot seen from above: theta = 0 (x, forward) up, theta = 90 deg (y, left) to the left.
  std::pair<double, double> at(double theta, double share) const {
    return {cx - radius * share * std::sin(theta), cy - radius * share * std::cos(theta)};
  }
  // Cairo's arc runs clockwise on screen from +x; theta runs anticlockwise from up.
  void arc(cairo_t* cairo, double share, double from_deg, double to_deg) const {
    const double a0 = -std::numbers::pi / 2 - model::deg_to_rad(to_deg);
    const double a1 = -std::numbers::pi / 2 - model::deg_to_rad(from_deg);
    cairo_arc(cairo, cx, cy, radius * share, a0, a1);
  }
};

// Requirement sectors shaded under everything, then the rings and spokes of the grid.
void draw_polar_grid(cairo_t* cairo, const metrics::RigCoverage& coverage,
                     const PolarChart& chart) {
  for (const metrics::SectorCoverage& sector : coverage.sectors) {
    for (const auto& [from, to] : sector_ranges_deg(sector.sector)) {
      set_colour(cairo, sector.pass ? kPassColour : kFailColour, 0.08);
      cairo_move_to(cairo, chart.cx, chart.cy);
      chart.arc(cairo, 1.0, from, to);
      cairo_close_path(cairo);
      cairo_fill(cairo);
    }
  }
  cairo_set_line_width(cairo, 1);
  for (const double percent : tick_values(kRingTickStep, 100, kRingTickStep)) {
    set_colour(cairo, kGridColour);
    cairo_arc(cairo, chart.cx, chart.cy, chart.radius * percent / 100.0, 0, 2 * std::numbers::pi);
    cairo_stroke(cairo);
  }
  for (const double degrees : tick_values(0, 360 - kSpokeStep, kSpokeStep)) {  // 360 is 0
    const auto [x, y] = chart.at(model::deg_to_rad(degrees), 1.0);
    set_colour(cairo, kGridColour);
    cairo_move_to(cairo, chart.cx, chart.cy);
    cairo_line_to(cairo, x, y);
    cairo_stroke(cairo);
    const auto [lx, ly] = chart.at(model::deg_to_rad(degrees), chart.ring_outer + 0.07);
    set_colour(cairo, kInkColour);
    draw_text(cairo, model::format_number(degrees), lx, ly + 5, 13, Anchor::centre);
  }
}

// Each sector's thresholds dashed over its angles, and its name outside the rings.
void draw_thresholds(cairo_t* cairo, const metrics::RigCoverage& coverage,
                     const PolarChart& chart) {
  const double dash[] = {7.0, 5.0};
  constexpr int kSegments = 48;
  cairo_set_line_width(cairo, 2);
  for (const metrics::SectorCoverage& sector : coverage.sectors) {
    for (const auto& [share, colour] :
         {std::pair{sector.sector.min_complete_coverage, kCompleteColour},
          std::pair{sector.sector.min_floor_coverage, kFloorColour}}) {
      set_colour(cairo, colour);
      cairo_set_dash(cairo, dash, 2, 0);
      for (int i = 0; i <= kSegments; ++i) {
        const double theta =
            sector.sector.from + (sector.sector.to - sector.sector.from) * i / kSegments;
        const auto [x, y] = chart.at(theta, share);
        i == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
      }
      cairo_stroke(cairo);
      cairo_set_dash(cairo, nullptr, 0, 0);
    }
    const auto [lx, ly] =
        chart.at(0.5 * (sector.sector.from + sector.sector.to), chart.ring_outer + 0.2);
    set_colour(cairo, sector.pass ? Rgb{0.0, 0.5, 0.2} : kFailColour);
    draw_text(cairo, sector.sector.name + (sector.pass ? "" : " (FAIL)"), lx, ly + 5, 12,
              Anchor::centre, true);
  }
}

void draw_mount_rings(cairo_t* cairo, const metrics::RigCoverage& coverage,
                      const PolarChart& chart) {
  for (std::size_t m = 0; m < coverage.mount_ids.size(); ++m) {
    const double share = 1.03 + kRingStep * (static_cast<double>(m) + 0.5);
    set_colour(cairo, sensor_colour(m));
    cairo_set_line_width(cairo, chart.radius * kRingStep * 0.8);
    for (const auto& [from, to] : mount_spans(coverage, m)) {
      cairo_new_sub_path(cairo);
      chart.arc(cairo, share, from, to);
      cairo_stroke(cairo);
    }
  }
}

void draw_polar_curves(cairo_t* cairo, const metrics::RigCoverage& coverage,
                       const PolarChart& chart) {
  cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
  for (const auto& [field, colour, dotted] :
       {std::tuple{&metrics::AngleCoverage::redundancy, kRedundancyColour, true},
        std::tuple{&metrics::AngleCoverage::floor, kFloorColour, false},
        std::tuple{&metrics::AngleCoverage::complete, kCompleteColour, false}}) {
    set_colour(cairo, colour);
    cairo_set_line_width(cairo, dotted ? 1.5 : 2.5);
    const double dots[] = {3.0, 3.0};
    cairo_set_dash(cairo, dots, dotted ? 2 : 0, 0);
    for (std::size_t i = 0; i < coverage.angles.size(); ++i) {
      const auto [x, y] = chart.at(coverage.angles[i].theta, coverage.angles[i].*field);
      i == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
    }
    cairo_close_path(cairo);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
  }
}

// Percent labels between two spokes, on a white patch so the curves cannot hide them, and
// which way is forward.
void draw_polar_labels(cairo_t* cairo, const PolarChart& chart) {
  for (const double percent : tick_values(kRingTickStep, 100, kRingTickStep)) {
    const auto [x, y] = chart.at(model::deg_to_rad(-kSpokeStep / 2), percent / 100.0);
    cairo_set_source_rgba(cairo, 1, 1, 1, 0.85);
    cairo_rectangle(cairo, x + 1, y - 14, 34, 14);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, model::format_number(percent) + " %", x + 3, y - 3, 11);
  }
  const auto [fx, fy] = chart.at(0.0, chart.ring_outer + 0.3);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "forward (x)", fx, fy + 4, 13, Anchor::centre, true);
}

// Under the chart: the lines in a row, then the sensors two to a row.
void draw_polar_legend(cairo_t* cairo, const metrics::RigCoverage& coverage, int size) {
  double legend_y = size + 94.0;
  legend_line(cairo, 30, legend_y, kCompleteColour, false, "SC complete");
  legend_line(cairo, 200, legend_y, kFloorColour, false, "SC floor");
  legend_line(cairo, 350, legend_y, kRedundancyColour, true, "seen by 2+ sensors");
  if (!coverage.sectors.empty()) {
    legend_line(cairo, 580, legend_y, kCompleteColour, true, "required (complete, floor)");
  }
  legend_y += 22;
  set_colour(cairo, kInkColour);
  draw_text(cairo,
            "sensors (outer rings, innermost first: angles where each sees the section); "
            "shaded: requirement sectors",
            30, legend_y, 12);
  for (std::size_t m = 0; m < coverage.mount_ids.size(); ++m) {
    if (m % 2 == 0) legend_y += 22;
    legend_box(cairo, m % 2 == 0 ? 30.0 : size / 2.0, legend_y, sensor_colour(m),
               mount_label(coverage, m), 12);
  }
}

}  // namespace

void plot_sc_polar(const metrics::RigCoverage& coverage, const std::string& rig_name,
                   const std::string& path, int size) {
  const std::size_t mounts = coverage.mount_ids.size();
  const int legend_rows = 2 + static_cast<int>((mounts + 1) / 2);
  const PolarChart chart{size / 2.0, size / 2.0 + 90, size * 0.33,
                         1.03 + kRingStep * static_cast<double>(mounts)};
  draw_to_file(path, size, size + 90 + 22 * legend_rows, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, coverage_title(coverage, rig_name), chart.cx, 30, 19, Anchor::centre, true);
    draw_polar_grid(cairo, coverage, chart);
    draw_thresholds(cairo, coverage, chart);
    draw_mount_rings(cairo, coverage, chart);
    draw_polar_curves(cairo, coverage, chart);
    draw_polar_labels(cairo, chart);
    draw_polar_legend(cairo, coverage, size);
  });
}

}  // namespace rigdesign::render
