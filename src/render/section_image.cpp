// One cross-section of the coverage analysis: what each sensor sees of the area to perceive
// beside the body, at equal scales, with a legend of each sensor's share.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"

namespace rigdesign::render {
namespace {

// Section ticks may fall on quarters (0.25, 2.5 m): a section's few metres read better so.
constexpr double kSectionStepFactors[] = {1.0, 2.0, 2.5, 5.0};
constexpr double kPlotLeft = 80;      // [px] x of rho = 0
constexpr double kPlotTop = 70;       // [px] the highest the plot reaches
constexpr double kLegendWidth = 250;  // [px] right of the plot
constexpr double kAxisMargin = 70;    // [px] under the plot: tick labels and the x title

// The axes run a little past the area to perceive, so its frame stands clear of their ends.
double rho_max_of(const geometry::SectionFrame& frame) {
  return frame.d * 1.04;
}
double z_max_of(const geometry::SectionFrame& frame) {
  return frame.h * 1.12;
}

std::string section_title(const metrics::SectionView& view, const std::string& rig_name) {
  return rig_name + ": cross-section at theta = " +
         model::format_number(model::rad_to_deg(view.frame.theta), 4) + " deg  (SC complete " +
         model::format_number(view.complete * 100, 3) + " %, floor " +
         model::format_number(view.floor * 100, 3) + " %)";
}

// Grid and ticks in metres.
void draw_section_axes(cairo_t* cairo, const SectionLayout& axes,
                       const geometry::SectionFrame& frame) {
  const double rho_max = rho_max_of(frame), z_max = z_max_of(frame);
  const PlotArea area{axes.x(0), axes.y(z_max), axes.x(rho_max), axes.y(0)};
  const Axis x{.ticks = tick_values(0, rho_max,
                                    tick_step(rho_max, 8, StepRounding::up, kSectionStepFactors)),
               .pixel = [&](double rho) { return axes.x(rho); },
               .digits = 3,
               .grid_from_bottom = true};
  const Axis y{
      .ticks = tick_values(0, z_max, tick_step(z_max, 5, StepRounding::up, kSectionStepFactors)),
      .pixel = [&](double z) { return axes.y(z); },
      .digits = 3};
  draw_ticks(cairo, area, x, y);
  // The x title's baseline 22 px above the canvas's bottom edge.
  draw_x_title(cairo, area, "rho: distance from the robot's vertical axis [m]", kAxisMargin - 22);
  draw_y_title(cairo, area, "z: height [m]", 26);
}

// The body, then each sensor's region translucent so overlaps read as darker blends.
void draw_body_and_regions(cairo_t* cairo, const SectionLayout& axes,
                           const metrics::SectionView& view) {
  const geometry::SectionFrame& frame = view.frame;
  set_colour(cairo, kBodyColour, 0.9);
  cairo_rectangle(cairo, axes.x(0), axes.y(frame.h), frame.r * axes.scale, frame.h * axes.scale);
  cairo_fill(cairo);
  set_colour(cairo, {1, 1, 1});
  draw_text(cairo, "body", axes.x(frame.r / 2), axes.y(frame.h / 2), 13, Anchor::centre);
  // One path per sensor: its strips fill as one region, without seams between them.
  for (std::size_t i = 0; i < view.polygons.size(); ++i) {
    for (const geometry::Polygon2& polygon : view.polygons[i]) {
      for (std::size_t k = 0; k < polygon.size(); ++k) {
        const double x = axes.x(polygon[k].x());
        const double y = axes.y(polygon[k].y());
        k == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
      }
      cairo_close_path(cairo);
    }
    set_colour(cairo, sensor_colour(i), 0.45);
    cairo_fill(cairo);
  }
}

// The covered floor as a thick line under the frame, and the area to perceive, [r, d] x
// [0, h], dashed.
void draw_floor_and_area(cairo_t* cairo, const SectionLayout& axes,
                         const metrics::SectionView& view) {
  const geometry::SectionFrame& frame = view.frame;
  geometry::IntervalSet floor;
  for (const geometry::IntervalSet& mount_floor : view.floors) floor = floor.united(mount_floor);
  set_colour(cairo, kFloorColour);
  cairo_set_line_width(cairo, 5);
  for (const auto& [low, high] : floor.intervals()) {
    cairo_move_to(cairo, axes.x(low), axes.y(0) + 3);
    cairo_line_to(cairo, axes.x(high), axes.y(0) + 3);
    cairo_stroke(cairo);
  }
  const double dash[] = {8.0, 5.0};
  cairo_set_dash(cairo, dash, 2, 0);
  set_colour(cairo, kInkColour);
  cairo_set_line_width(cairo, 1.6);
  cairo_rectangle(cairo, axes.x(frame.r), axes.y(frame.h), frame.width() * axes.scale,
                  frame.h * axes.scale);
  cairo_stroke(cairo);
  cairo_set_dash(cairo, nullptr, 0, 0);
  draw_text(cairo, "r", axes.x(frame.r), axes.y(frame.h) - 6, 13, Anchor::centre);
  draw_text(cairo, "d", axes.x(frame.d), axes.y(frame.h) - 6, 13, Anchor::centre);
}

// Sensors mounted near this half-plane: their origin, projected.
void draw_origins(cairo_t* cairo, const SectionLayout& axes, const metrics::SectionView& view) {
  const model::Vec2 outward(std::cos(view.frame.theta), std::sin(view.frame.theta));
  for (std::size_t i = 0; i < view.origins.size(); ++i) {
    const model::Vec2 horizontal = view.origins[i].head<2>();
    const double along = horizontal.dot(outward);
    const double aside = std::abs(horizontal.x() * outward.y() - horizontal.y() * outward.x());
    if (along < -1e-9 || aside > 0.05 + 0.1 * along) continue;
    set_colour(cairo, sensor_colour(i));
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, axes.x(along), axes.y(view.origins[i].z()), 6, 0, 2 * std::numbers::pi);
    cairo_fill_preserve(cairo);
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, 1.2);
    cairo_stroke(cairo);
  }
}

// Legend: each sensor with the share of the frame it sees alone, then the floor line and the
// area's frame.
void draw_section_legend(cairo_t* cairo, const metrics::SectionView& view, double legend_x) {
  double y = kPlotTop + 10;
  draw_text(cairo, "sensor (share seen here)", legend_x, y, 14, Anchor::left, true);
  for (std::size_t i = 0; i < view.polygons.size(); ++i) {
    double area = 0.0;
    for (const geometry::Polygon2& polygon : view.polygons[i]) area += model::signed_area(polygon);
    y += 26;
    set_colour(cairo, sensor_colour(i), 0.6);
    cairo_rectangle(cairo, legend_x, y - 13, 22, 16);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(
        cairo,
        view.mount_ids[i] + "  " + model::format_number(area / view.frame.area() * 100, 3) + " %",
        legend_x + 30, y, 13);
    if (i < view.mount_sensors.size()) {
      set_colour(cairo, kInkColour, 0.7);
      draw_text(cairo, view.mount_sensors[i], legend_x + 30, y += 15, 11);
    }
  }
  y += 34;
  set_colour(cairo, kFloorColour);
  cairo_set_line_width(cairo, 5);
  cairo_move_to(cairo, legend_x, y - 5);
  cairo_line_to(cairo, legend_x + 22, y - 5);
  cairo_stroke(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, "floor seen", legend_x + 30, y, 13);
  y += 24;
  const double dash[] = {8.0, 5.0};
  cairo_set_dash(cairo, dash, 2, 0);
  cairo_set_line_width(cairo, 1.6);
  cairo_rectangle(cairo, legend_x, y - 13, 22, 16);
  cairo_stroke(cairo);
  cairo_set_dash(cairo, nullptr, 0, 0);
  draw_text(cairo, "area to perceive", legend_x + 30, y, 13);
}

}  // namespace

SectionLayout section_layout(const geometry::SectionFrame& frame, std::size_t sensors, int width,
                             int max_height) {
  // The canvas is as tall as the section needs at equal scales (and tall enough for the
  // legend), but no taller than max_height.
  const double rho_max = rho_max_of(frame);
  const double z_max = z_max_of(frame);
  const double plot_right = width - kLegendWidth;
  const double legend_height = 140.0 + 26.0 * static_cast<double>(sensors);
  const double wanted = kPlotTop + z_max * (plot_right - kPlotLeft) / rho_max + kAxisMargin;
  SectionLayout layout;
  layout.width = width;
  layout.height = static_cast<int>(std::clamp(std::max(wanted, legend_height + kAxisMargin), 300.0,
                                              static_cast<double>(max_height)));
  layout.left = kPlotLeft;
  layout.bottom = layout.height - kAxisMargin;
  layout.scale = std::min((plot_right - kPlotLeft) / rho_max, (layout.bottom - kPlotTop) / z_max);
  return layout;
}

void draw_section(const metrics::SectionView& view, const std::string& rig_name,
                  const std::string& path, int width, int max_height) {
  const SectionLayout axes = section_layout(view.frame, view.polygons.size(), width, max_height);
  draw_to_file(path, width, axes.height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, section_title(view, rig_name), width / 2.0, 34, 19, Anchor::centre, true);
    draw_section_axes(cairo, axes, view.frame);
    draw_body_and_regions(cairo, axes, view);
    draw_floor_and_area(cairo, axes, view);
    draw_origins(cairo, axes, view);
    draw_section_legend(cairo, view, width - kLegendWidth + 30);
  });
}

}  // namespace rigdesign::render
