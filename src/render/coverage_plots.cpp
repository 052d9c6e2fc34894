#include "rigdesign/render/coverage_plots.hpp"

#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "rigdesign/model/format_number.hpp"
#include "rigdesign/model/units.hpp"

namespace rigdesign::render {
namespace {

using render::Anchor;
using render::draw_text;
using render::set_colour;

constexpr Rgb kRedundancy{0.45, 0.45, 0.45};

std::string title(const metrics::RigCoverage& coverage, const std::string& rig_name) {
  return rig_name + ": spatial coverage, d = " + model::format_number(coverage.distance) +
         " m, h = " + model::format_number(coverage.height) + " m";
}

// A sector as one or two [from, to] degree ranges inside [0, 360].
std::vector<std::pair<double, double>> sector_ranges_deg(const model::SectorRequirement& sector) {
  double from = std::fmod(model::rad_to_deg(sector.from), 360.0);
  if (from < 0) from += 360.0;
  const double to = from + model::rad_to_deg(sector.to - sector.from);
  if (to <= 360.0) return {{from, to}};
  return {{from, 360.0}, {0.0, to - 360.0}};
}

struct CartesianAxes {
  double left, top, width, height;
  double x(double degrees) const { return left + width * degrees / 360.0; }
  double y(double share) const { return top + height * (1.0 - share); }
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

}  // namespace

void plot_sc_cartesian(const metrics::RigCoverage& coverage, const std::string& rig_name,
                       const std::string& path, int width, int height) {
  render::draw_to_file(path, width, height, [&](cairo_t* cairo) {
    const CartesianAxes axes{80, 60, width - 80.0 - 260.0, height - 60.0 - 80.0};
    set_colour(cairo, kInkColour);
    draw_text(cairo, title(coverage, rig_name), width / 2.0, 32, 20, Anchor::centre, true);
    cairo_set_line_width(cairo, 1);
    for (int degrees = 0; degrees <= 360; degrees += 45) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, axes.x(degrees), axes.top);
      cairo_line_to(cairo, axes.x(degrees), axes.top + axes.height);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(degrees), axes.x(degrees), axes.top + axes.height + 20, 13,
                Anchor::centre);
    }
    for (int percent = 0; percent <= 100; percent += 25) {
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, axes.left, axes.y(percent / 100.0));
      cairo_line_to(cairo, axes.left + axes.width, axes.y(percent / 100.0));
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(percent), axes.left - 8, axes.y(percent / 100.0) + 5, 13,
                Anchor::right);
    }
    draw_text(cairo, "azimuth theta [deg]  (0 = forward, 90 = left, 180 = back, 270 = right)",
              axes.left + axes.width / 2, height - 22.0, 14, Anchor::centre);
    cairo_save(cairo);
    cairo_translate(cairo, 26, axes.top + axes.height / 2);
    cairo_rotate(cairo, -std::numbers::pi / 2);
    draw_text(cairo, "coverage [%]", 0, 0, 14, Anchor::centre);
    cairo_restore(cairo);

    // Requirement thresholds: dashed lines over each sector's angles, labelled above.
    const double dash[] = {7.0, 5.0};
    for (const metrics::SectorCoverage& sector : coverage.sectors) {
      for (const auto& [from, to] : sector_ranges_deg(sector.sector)) {
        set_colour(cairo, sector.pass ? Rgb{0.0, 0.55, 0.25} : Rgb{0.8, 0.1, 0.1}, 0.08);
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

    cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_width(cairo, 1.5);
    const double dotted[] = {3.0, 3.0};
    cairo_set_dash(cairo, dotted, 2, 0);
    set_colour(cairo, kRedundancy);
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

    const double legend_x = axes.left + axes.width + 20;
    double y = axes.top + 20;
    legend_line(cairo, legend_x, y, kCompleteColour, false, "SC complete");
    legend_line(cairo, legend_x, y += 24, kFloorColour, false, "SC floor");
    legend_line(cairo, legend_x, y += 24, kRedundancy, true, "seen by 2+ sensors");
    if (!coverage.sectors.empty()) {
      legend_line(cairo, legend_x, y += 24, kCompleteColour, true, "required complete");
      legend_line(cairo, legend_x, y += 24, kFloorColour, true, "required floor");
    }
    y += 40;
    set_colour(cairo, kInkColour);
    draw_text(cairo, "complete: min " + model::format_number(coverage.complete.min * 100, 3) + " %",
              legend_x, y, 13);
    draw_text(cairo, "  mean " + model::format_number(coverage.complete.mean * 100, 3) + " %",
              legend_x, y += 18, 13);
    draw_text(cairo, "floor: min " + model::format_number(coverage.floor.min * 100, 3) + " %",
              legend_x, y += 22, 13);
    draw_text(cairo, "  mean " + model::format_number(coverage.floor.mean * 100, 3) + " %",
              legend_x, y += 18, 13);
    draw_text(cairo, coverage.exact ? "exact path (CGAL)" : "raster path", legend_x, y += 28, 12);
  });
}

void plot_sc_polar(const metrics::RigCoverage& coverage, const std::string& rig_name,
                   const std::string& path, int size) {
  render::draw_to_file(path, size, size + 90, [&](cairo_t* cairo) {
    const double cx = size / 2.0;
    const double cy = size / 2.0 + 40;
    const double radius = size * 0.36;
    // Robot seen from above: theta = 0 (x, forward) up, theta = 90 deg (y, left) to the left.
    const auto at = [&](double theta, double share) {
      return std::pair{cx - radius * share * std::sin(theta),
                       cy - radius * share * std::cos(theta)};
    };
    set_colour(cairo, kInkColour);
    draw_text(cairo, title(coverage, rig_name), cx, 32, 19, Anchor::centre, true);
    cairo_set_line_width(cairo, 1);
    for (int percent = 25; percent <= 100; percent += 25) {
      set_colour(cairo, kGridColour);
      cairo_arc(cairo, cx, cy, radius * percent / 100.0, 0, 2 * std::numbers::pi);
      cairo_stroke(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(percent) + " %", cx + 4, cy - radius * percent / 100.0 - 4,
                11);
    }
    for (int degrees = 0; degrees < 360; degrees += 45) {
      const auto [x, y] = at(model::deg_to_rad(degrees), 1.0);
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, cx, cy);
      cairo_line_to(cairo, x, y);
      cairo_stroke(cairo);
      const auto [lx, ly] = at(model::deg_to_rad(degrees), 1.12);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(degrees), lx, ly + 5, 13, Anchor::centre);
    }
    const auto [fx, fy] = at(0.0, 1.22);
    draw_text(cairo, "forward", fx, fy + 4, 13, Anchor::centre, true);

    const double dash[] = {7.0, 5.0};
    cairo_set_line_width(cairo, 2);
    for (const metrics::SectorCoverage& sector : coverage.sectors) {
      for (const auto& [share, colour] :
           {std::pair{sector.sector.min_complete_coverage, kCompleteColour},
            std::pair{sector.sector.min_floor_coverage, kFloorColour}}) {
        set_colour(cairo, colour);
        cairo_set_dash(cairo, dash, 2, 0);
        const int segments = 48;
        for (int i = 0; i <= segments; ++i) {
          const double theta =
              sector.sector.from + (sector.sector.to - sector.sector.from) * i / segments;
          const auto [x, y] = at(theta, share);
          i == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
        }
        cairo_stroke(cairo);
        cairo_set_dash(cairo, nullptr, 0, 0);
      }
      const auto [lx, ly] = at(0.5 * (sector.sector.from + sector.sector.to), 1.04);
      set_colour(cairo, sector.pass ? Rgb{0.0, 0.5, 0.2} : Rgb{0.8, 0.1, 0.1});
      draw_text(cairo, sector.sector.name, lx, ly, 12, Anchor::centre, true);
    }

    cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
    for (const auto& [field, colour] :
         {std::pair{&metrics::AngleCoverage::floor, kFloorColour},
          std::pair{&metrics::AngleCoverage::complete, kCompleteColour}}) {
      set_colour(cairo, colour);
      cairo_set_line_width(cairo, 2.5);
      for (std::size_t i = 0; i < coverage.angles.size(); ++i) {
        const auto [x, y] = at(coverage.angles[i].theta, coverage.angles[i].*field);
        i == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
      }
      cairo_close_path(cairo);
      cairo_stroke(cairo);
    }
    const double legend_y = size + 60.0;
    legend_line(cairo, 40, legend_y, kCompleteColour, false, "SC complete");
    legend_line(cairo, 220, legend_y, kFloorColour, false, "SC floor");
    if (!coverage.sectors.empty()) {
      legend_line(cairo, 380, legend_y, kCompleteColour, true, "required complete");
      legend_line(cairo, 600, legend_y, kFloorColour, true, "required floor");
    }
  });
}

}  // namespace rigdesign::render
