#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"
#include "rigdesign/render/coverage_plots.hpp"

namespace rigdesign {
namespace {

using render::Anchor;
using render::draw_text;
using render::set_colour;

constexpr Rgb kInk{0.15, 0.15, 0.15};
constexpr Rgb kGrid{0.9, 0.9, 0.9};

// Round tick spacing giving about `count` ticks over `span`.
double tick_step(double span, int count) {
  const double raw = span / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (factor * magnitude >= raw) return factor * magnitude;
  }
  return 10 * magnitude;
}

struct SectionAxes {
  double left, bottom, scale;  // pixels per metre, equal on both axes
  double x(double rho) const { return left + rho * scale; }
  double y(double z) const { return bottom - z * scale; }
};

}  // namespace

void draw_section(const SectionView& view, const std::string& rig_name, const std::string& path,
                  int width, int height) {
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    const SectionFrame& frame = view.frame;
    const double rho_max = frame.d * 1.04;
    const double z_max = frame.h * 1.12;
    const double plot_left = 80;
    const double plot_right = width - 250.0;
    const double plot_top = 70;
    const double plot_bottom = height - 70.0;
    const double scale = std::min((plot_right - plot_left) / rho_max, (plot_bottom - plot_top) / z_max);
    const SectionAxes axes{plot_left, plot_bottom, scale};

    set_colour(cairo, kInk);
    draw_text(cairo,
              rig_name + ": cross-section at theta = " +
                  format_number(rad_to_deg(frame.theta), 4) + " deg  (SC complete " +
                  format_number(view.complete * 100, 3) + " %, floor " +
                  format_number(view.floor * 100, 3) + " %)",
              width / 2.0, 34, 19, Anchor::centre, true);

    // Grid and ticks in metres.
    cairo_set_line_width(cairo, 1);
    const double rho_step = tick_step(rho_max, 8);
    const double z_step = tick_step(z_max, 5);
    for (double rho = 0; rho <= rho_max + 1e-9; rho += rho_step) {
      set_colour(cairo, kGrid);
      cairo_move_to(cairo, axes.x(rho), axes.y(0));
      cairo_line_to(cairo, axes.x(rho), axes.y(z_max));
      cairo_stroke(cairo);
      set_colour(cairo, kInk);
      draw_text(cairo, format_number(rho, 3), axes.x(rho), axes.y(0) + 20, 13, Anchor::centre);
    }
    for (double z = 0; z <= z_max + 1e-9; z += z_step) {
      set_colour(cairo, kGrid);
      cairo_move_to(cairo, axes.x(0), axes.y(z));
      cairo_line_to(cairo, axes.x(rho_max), axes.y(z));
      cairo_stroke(cairo);
      set_colour(cairo, kInk);
      draw_text(cairo, format_number(z, 3), axes.x(0) - 8, axes.y(z) + 5, 13, Anchor::right);
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
    for (std::size_t i = 0; i < view.polygons.size(); ++i) {
      const Rgb colour = sensor_colour(i);
      for (const Polygon2& polygon : view.polygons[i]) {
        for (std::size_t k = 0; k < polygon.size(); ++k) {
          const double x = axes.x(polygon[k].x());
          const double y = axes.y(polygon[k].y());
          k == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
        }
        cairo_close_path(cairo);
        set_colour(cairo, colour, 0.42);
        cairo_fill_preserve(cairo);
        set_colour(cairo, colour, 0.95);
        cairo_set_line_width(cairo, 1.2);
        cairo_stroke(cairo);
      }
    }
    // Covered floor: a thick line under the frame.
    IntervalSet floor;
    for (const IntervalSet& mount_floor : view.floors) floor = floor.united(mount_floor);
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
    set_colour(cairo, kInk);
    cairo_set_line_width(cairo, 1.6);
    cairo_rectangle(cairo, axes.x(frame.r), axes.y(frame.h), frame.width() * scale, frame.h * scale);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, "r", axes.x(frame.r), axes.y(frame.h) - 6, 13, Anchor::centre);
    draw_text(cairo, "d", axes.x(frame.d), axes.y(frame.h) - 6, 13, Anchor::centre);

    // Sensors mounted near this half-plane: their origin, projected.
    const Vec2 outward(std::cos(frame.theta), std::sin(frame.theta));
    for (std::size_t i = 0; i < view.origins.size(); ++i) {
      const Vec2 horizontal = view.origins[i].head<2>();
      const double along = horizontal.dot(outward);
      const double aside = std::abs(horizontal.x() * outward.y() - horizontal.y() * outward.x());
      if (along < -1e-9 || aside > 0.05 + 0.1 * along) continue;
      set_colour(cairo, sensor_colour(i));
      cairo_arc(cairo, axes.x(along), axes.y(view.origins[i].z()), 6, 0, 2 * std::numbers::pi);
      cairo_fill_preserve(cairo);
      set_colour(cairo, kInk);
      cairo_set_line_width(cairo, 1.2);
      cairo_stroke(cairo);
    }

    // Legend: each sensor with the share of the frame it sees alone.
    double y = plot_top + 10;
    const double legend_x = plot_right + 30;
    draw_text(cairo, "sensor (share seen here)", legend_x, y, 14, Anchor::left, true);
    for (std::size_t i = 0; i < view.polygons.size(); ++i) {
      double area = 0.0;
      for (const Polygon2& polygon : view.polygons[i]) area += polygon_area(polygon);
      y += 26;
      set_colour(cairo, sensor_colour(i), 0.6);
      cairo_rectangle(cairo, legend_x, y - 13, 22, 16);
      cairo_fill(cairo);
      set_colour(cairo, kInk);
      draw_text(cairo, view.mount_ids[i] + "  " + format_number(area / frame.area() * 100, 3) + " %",
                legend_x + 30, y, 13);
    }
    y += 34;
    set_colour(cairo, kFloorColour);
    cairo_set_line_width(cairo, 5);
    cairo_move_to(cairo, legend_x, y - 5);
    cairo_line_to(cairo, legend_x + 22, y - 5);
    cairo_stroke(cairo);
    set_colour(cairo, kInk);
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

}  // namespace rigdesign
