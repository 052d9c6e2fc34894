#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/polygon_area.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"

namespace rigdesign::render {
namespace {

using render::Anchor;
using render::draw_text;
using render::set_colour;

// Round tick spacing giving about `count` ticks over `span`.
double tick_step(double span, int count) {
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (factor * magnitude >= raw) return factor * magnitude;
  }
  return 10 * magnitude;
}

}  // namespace

constexpr double kPlotLeft = 80;
constexpr double kPlotTop = 70;
constexpr double kLegendWidth = 250;
constexpr double kAxisMargin = 70;

SectionLayout section_layout(const geometry::SectionFrame& frame, std::size_t sensors, int width,
                             int max_height) {
  // The canvas is as tall as the section needs at equal scales (and tall enough for the
  // legend), but no taller than max_height.
  const double rho_max = frame.d * 1.04;
  const double z_max = frame.h * 1.12;
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
  const geometry::SectionFrame& frame = view.frame;
  const SectionLayout axes = section_layout(frame, view.polygons.size(), width, max_height);
  const double rho_max = frame.d * 1.04;
  const double z_max = frame.h * 1.12;
  const double plot_right = width - kLegendWidth;
  const double plot_top = kPlotTop;
  const double scale = axes.scale;
  const int height = axes.height;
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo,
              rig_name + ": cross-section at theta = " +
                  model::format_number(model::rad_to_deg(frame.theta), 4) + " deg  (SC complete " +
                  model::format_number(view.complete * 100, 3) + " %, floor " +
                  model::format_number(view.floor * 100, 3) + " %)",
              width / 2.0, 34, 19, Anchor::centre, true);

    // Grid and ticks in metres.
    cairo_set_line_width(cairo, 1);
    const double rho_step = tick_step(rho_max, 8);
    const double z_step = tick_step(z_max, 5);
    for (double rho = 0; rho <= rho_max + 1e-9; rho += rho_step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, axes.x(rho), axes.y(0));
      cairo_line_to(cairo, axes.x(rho), axes.y(z_max));
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(rho, 3), axes.x(rho), axes.y(0) + 20, 13,
                Anchor::centre);
    }
    for (double z = 0; z <= z_max + 1e-9; z += z_step) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, axes.x(0), axes.y(z));
      cairo_line_to(cairo, axes.x(rho_max), axes.y(z));
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, model::format_number(z, 3), axes.x(0) - 8, axes.y(z) + 5, 13, Anchor::right);
    }
    draw_text(cairo, "rho: distance from the robot's vertical axis [m]", axes.x(rho_max / 2),
              height - 22.0, 14, Anchor::centre);
    cairo_save(cairo);
    cairo_translate(cairo, 26, axes.y(z_max / 2));
    cairo_rotate(cairo, -std::numbers::pi / 2);
    draw_text(cairo, "z: height [m]", 0, 0, 14, Anchor::centre);
    cairo_restore(cairo);

    // The body, then each sensor's region translucent so overlaps read as darker blends.
    set_colour(cairo, kBodyColour, 0.9);
    cairo_rectangle(cairo, axes.x(0), axes.y(frame.h), frame.r * scale, frame.h * scale);
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
    // Covered floor: a thick line under the frame.
    geometry::IntervalSet floor;
    for (const geometry::IntervalSet& mount_floor : view.floors) floor = floor.united(mount_floor);
    set_colour(cairo, kFloorColour);
    cairo_set_line_width(cairo, 5);
    for (const auto& [low, high] : floor.intervals()) {
      cairo_move_to(cairo, axes.x(low), axes.y(0) + 3);
      cairo_line_to(cairo, axes.x(high), axes.y(0) + 3);
      cairo_stroke(cairo);
    }
    // The area to perceive: [r, d] x [0, h].
    const double dash[] = {8.0, 5.0};
    cairo_set_dash(cairo, dash, 2, 0);
    set_colour(cairo, kInkColour);
    cairo_set_line_width(cairo, 1.6);
    cairo_rectangle(cairo, axes.x(frame.r), axes.y(frame.h), frame.width() * scale,
                    frame.h * scale);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, "r", axes.x(frame.r), axes.y(frame.h) - 6, 13, Anchor::centre);
    draw_text(cairo, "d", axes.x(frame.d), axes.y(frame.h) - 6, 13, Anchor::centre);

    // Sensors mounted near this half-plane: their origin, projected.
    const model::Vec2 outward(std::cos(frame.theta), std::sin(frame.theta));
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

    // Legend: each sensor with the share of the frame it sees alone.
    double y = plot_top + 10;
    const double legend_x = plot_right + 30;
    draw_text(cairo, "sensor (share seen here)", legend_x, y, 14, Anchor::left, true);
    for (std::size_t i = 0; i < view.polygons.size(); ++i) {
      double area = 0.0;
      for (const geometry::Polygon2& polygon : view.polygons[i])
        area += model::signed_area(polygon);
      y += 26;
      set_colour(cairo, sensor_colour(i), 0.6);
      cairo_rectangle(cairo, legend_x, y - 13, 22, 16);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(
          cairo,
          view.mount_ids[i] + "  " + model::format_number(area / frame.area() * 100, 3) + " %",
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
    cairo_set_dash(cairo, dash, 2, 0);
    cairo_set_line_width(cairo, 1.6);
    cairo_rectangle(cairo, legend_x, y - 13, 22, 16);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, "area to perceive", legend_x + 30, y, 13);
  });
}

}  // namespace rigdesign::render
