// SC against theta on Cartesian axes, with one strip per mount underneath showing the angles
// where it sees the section.
#include <cmath>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "coverage_chart_parts.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"

namespace rigdesign::render {
namespace {

constexpr double kStripRow = 16.0;  // [px] one mount's strip under the chart

struct CartesianAxes {
  double left, top, width, height;
  double x(double degrees) const { return left + width * degrees / 360.0; }
  double y(double share) const { return top + height * (1.0 - share); }
  PlotArea area() const { return {left, top, left + width, top + height}; }
};

void draw_curve(cairo_t* cairo, const metrics::RigCoverage& coverage, const CartesianAxes& axes,
                double metrics::AngleCoverage::*field) {
  bool first = true;
  for (const metrics::AngleCoverage& angle : coverage.angles) {
    const double x = axes.x(model::rad_to_deg(angle.theta));
    const double y = axes.y(angle.*field);
    first ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
    first = false;
  }
  if (!coverage.angles.empty()) {  // close the circle at 360 degrees
    cairo_line_to(cairo, axes.x(360.0), axes.y(coverage.angles.front().*field));
  }
  cairo_stroke(cairo);
}

// Requirement sectors first: shading under everything, thresholds dashed over their angles.
void draw_cartesian_sectors(cairo_t* cairo, const metrics::RigCoverage& coverage,
                            const CartesianAxes& axes) {
  const double dash[] = {7.0, 5.0};
  for (const metrics::SectorCoverage& sector : coverage.sectors) {
    for (const auto& [from, to] : sector_ranges_deg(sector.sector)) {
      set_colour(cairo, sector.pass ? kPassColour : kFailColour, 0.08);
      cairo_rectangle(cairo, axes.x(from), axes.top, axes.x(to) - axes.x(from), axes.height);
      cairo_fill(cairo);
      cairo_set_line_width(cairo, 2);
      cairo_set_dash(cairo, dash, 2, 0);
      for (const auto& [share, colour] :
           {std::pair{sector.sector.min_complete_coverage, kCompleteColour},
            std::pair{sector.sector.min_floor_coverage, kFloorColour}}) {
        set_colour(cairo, colour);
        cairo_move_to(cairo, axes.x(from), axes.y(share));
        cairo_line_to(cairo, axes.x(to), axes.y(share));
        cairo_stroke(cairo);
      }
      cairo_set_dash(cairo, nullptr, 0, 0);
      set_colour(cairo, kInkColour);
      draw_text(cairo, sector.sector.name + (sector.pass ? " (pass)" : " (FAIL)"),
                (axes.x(from) + axes.x(to)) / 2, axes.top - 6, 12, Anchor::centre);
    }
  }
}

void draw_cartesian_axes(cairo_t* cairo, const CartesianAxes& axes) {
  const Axis x{tick_values(0, 360, 45), [&](double degrees) { return axes.x(degrees); }};
  const Axis y{tick_values(0, 100, 25), [&](double percent) { return axes.y(percent / 100.0); }};
  draw_ticks(cairo, axes.area(), x, y);
  draw_x_title(cairo, axes.area(),
               "azimuth theta [deg]  (0 = forward, 90 = left, 180 = back, 270 = right)", 42);
  draw_y_title(cairo, axes.area(), "coverage [%]", 60);
}

// Redundancy dotted and thin under floor and complete, then the plot's frame over them.
void draw_cartesian_curves(cairo_t* cairo, const metrics::RigCoverage& coverage,
                           const CartesianAxes& axes) {
  cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_width(cairo, 1.5);
  const double dotted[] = {3.0, 3.0};
  cairo_set_dash(cairo, dotted, 2, 0);
  set_colour(cairo, kRedundancyColour);
  draw_curve(cairo, coverage, axes, &metrics::AngleCoverage::redundancy);
  cairo_set_dash(cairo, nullptr, 0, 0);
  cairo_set_line_width(cairo, 2.5);
  set_colour(cairo, kFloorColour);
  draw_curve(cairo, coverage, axes, &metrics::AngleCoverage::floor);
  set_colour(cairo, kCompleteColour);
  draw_curve(cairo, coverage, axes, &metrics::AngleCoverage::complete);

  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1.2);
  cairo_rectangle(cairo, axes.left, axes.top, axes.width, axes.height);
  cairo_stroke(cairo);
}

// The strips: one row per mount in its colour, on the same angle axis, so each lobe of the
// curves is attributed to the sensors that make it.
void draw_mount_strips(cairo_t* cairo, const metrics::RigCoverage& coverage,
                       const CartesianAxes& axes) {
  const double strip_top = axes.top + axes.height + 58;
  for (std::size_t m = 0; m < coverage.mount_ids.size(); ++m) {
    const double row = strip_top + kStripRow * static_cast<double>(m);
    set_colour(cairo, kGridColour);
    cairo_rectangle(cairo, axes.left, row + 2, axes.width, kStripRow - 4);
    cairo_fill(cairo);
    set_colour(cairo, sensor_colour(m));
    for (const auto& [from, to] : mount_spans(coverage, m)) {
      cairo_rectangle(cairo, axes.x(from), row + 2, axes.x(to) - axes.x(from), kStripRow - 4);
      cairo_fill(cairo);
    }
    set_colour(cairo, kInkColour);
    draw_text(cairo, coverage.mount_ids[m], axes.left - 8, row + kStripRow - 4, 11, Anchor::right);
  }
}

// Right of the chart: the lines, the requirement's, the sensors' colours and the summary.
void draw_cartesian_legend(cairo_t* cairo, const metrics::RigCoverage& coverage, double legend_x,
                           double y) {
  legend_line(cairo, legend_x, y, kCompleteColour, false, "SC complete");
  legend_line(cairo, legend_x, y += 22, kFloorColour, false, "SC floor");
  legend_line(cairo, legend_x, y += 22, kRedundancyColour, true, "seen by 2+ sensors");
  if (!coverage.sectors.empty()) {
    legend_line(cairo, legend_x, y += 22, kCompleteColour, true, "required complete");
    legend_line(cairo, legend_x, y += 22, kFloorColour, true, "required floor");
    set_colour(cairo, kPassColour, 0.15);
    cairo_rectangle(cairo, legend_x, y + 11, 30, 12);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, "requirement sector", legend_x + 38, y += 22, 14);
  }
  y += 30;
  set_colour(cairo, kInkColour);
  draw_text(cairo, "sensors (strips below: angles", legend_x, y, 13, Anchor::left, true);
  draw_text(cairo, "where each sees the section)", legend_x, y += 17, 13, Anchor::left, true);
  for (std::size_t m = 0; m < coverage.mount_ids.size(); ++m) {
    legend_box(cairo, legend_x, y += 20, sensor_colour(m), mount_label(coverage, m), 12);
  }
  y += 30;
  set_colour(cairo, kInkColour);
  draw_text(cairo,
            "complete: min " + model::format_number(coverage.complete.min * 100, 3) + " %, mean " +
                model::format_number(coverage.complete.mean * 100, 3) + " %",
            legend_x, y, 12);
  draw_text(cairo,
            "floor: min " + model::format_number(coverage.floor.min * 100, 3) + " %, mean " +
                model::format_number(coverage.floor.mean * 100, 3) + " %",
            legend_x, y += 17, 12);
  draw_text(cairo, coverage.exact ? "exact path (CGAL)" : "raster path", legend_x, y += 17, 12);
}

}  // namespace

void plot_sc_cartesian(const metrics::RigCoverage& coverage, const std::string& rig_name,
                       const std::string& path, int width, int height) {
  const std::size_t mounts = coverage.mount_ids.size();
  const double strips = kStripRow * static_cast<double>(mounts);
  const int total_height = height + static_cast<int>(strips) + (mounts > 0 ? 30 : 0);
  // Room on the left for the strips' mount names.
  const CartesianAxes axes{120, 60, width - 120.0 - 300.0, height - 60.0 - 80.0};
  draw_to_file(path, width, total_height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, coverage_title(coverage, rig_name), width / 2.0, 32, 20, Anchor::centre, true);
    draw_cartesian_sectors(cairo, coverage, axes);
    draw_cartesian_axes(cairo, axes);
    draw_cartesian_curves(cairo, coverage, axes);
    draw_mount_strips(cairo, coverage, axes);
    draw_cartesian_legend(cairo, coverage, axes.left + axes.width + 20, axes.top + 14);
  });
}

}  // namespace rigdesign::render
