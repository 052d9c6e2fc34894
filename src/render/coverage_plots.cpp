#include "rigdesign/render/coverage_plots.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

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

std::string mount_label(const metrics::RigCoverage& coverage, std::size_t i) {
  const std::string sensor = i < coverage.mount_sensors.size() ? coverage.mount_sensors[i] : "";
  return coverage.mount_ids[i] + (sensor.empty() ? "" : " (" + sensor + ")");
}

void legend_box(cairo_t* cairo, double x, double y, const Rgb& colour, const std::string& label,
                double size = 13) {
  set_colour(cairo, colour);
  cairo_rectangle(cairo, x, y - 11, 30, 12);
  cairo_fill(cairo);
  set_colour(cairo, kInkColour);
  draw_text(cairo, label, x + 38, y, size);
}

// Runs of consecutive sampled angles where `sees(i)` holds, as [from, to] degree spans (each
// sample stands for the half steps either side of it).
template <typename Sees>
std::vector<std::pair<double, double>> seen_spans(const metrics::RigCoverage& coverage, Sees sees) {
  std::vector<std::pair<double, double>> spans;
  const std::size_t n = coverage.angles.size();
  if (n == 0) return spans;
  const double half = 180.0 / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!sees(i)) continue;
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

}  // namespace

void plot_sc_cartesian(const metrics::RigCoverage& coverage, const std::string& rig_name,
                       const std::string& path, int width, int height) {
  // One strip per mount under the chart: where the mount sees part of the cross-section, so
  // each lobe of the curves is attributed to the sensors that make it.
  const std::size_t mounts = coverage.mount_ids.size();
  constexpr double kStripRow = 16.0;
  const double strips = kStripRow * static_cast<double>(mounts);
  const int total_height = height + static_cast<int>(strips) + (mounts > 0 ? 30 : 0);
  render::draw_to_file(path, width, total_height, [&](cairo_t* cairo) {
    // Room on the left for the strips' mount names.
    const CartesianAxes axes{120, 60, width - 120.0 - 300.0, height - 60.0 - 80.0};
    set_colour(cairo, kInkColour);
    draw_text(cairo, title(coverage, rig_name), width / 2.0, 32, 20, Anchor::centre, true);

    // Requirement sectors first: shading under everything, thresholds dashed over their angles.
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
              axes.left + axes.width / 2, axes.top + axes.height + 42, 14, Anchor::centre);
    cairo_save(cairo);
    cairo_translate(cairo, 60, axes.top + axes.height / 2);
    cairo_rotate(cairo, -std::numbers::pi / 2);
    draw_text(cairo, "coverage [%]", 0, 0, 14, Anchor::centre);
    cairo_restore(cairo);

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

    // The strips: one row per mount in its colour, on the same angle axis.
    const double strip_top = axes.top + axes.height + 58;
    for (std::size_t m = 0; m < mounts; ++m) {
      const double row = strip_top + kStripRow * static_cast<double>(m);
      set_colour(cairo, kGridColour);
      cairo_rectangle(cairo, axes.left, row + 2, axes.width, kStripRow - 4);
      cairo_fill(cairo);
      set_colour(cairo, sensor_colour(m));
      for (const auto& [from, to] : seen_spans(coverage, [&](std::size_t i) {
             const auto& sees = coverage.angles[i].mount_sees;
             return m < sees.size() && sees[m];
           })) {
        cairo_rectangle(cairo, axes.x(from), row + 2, axes.x(to) - axes.x(from), kStripRow - 4);
        cairo_fill(cairo);
      }
      set_colour(cairo, kInkColour);
      draw_text(cairo, coverage.mount_ids[m], axes.left - 8, row + kStripRow - 4, 11,
                Anchor::right);
    }

    const double legend_x = axes.left + axes.width + 20;
    double y = axes.top + 14;
    legend_line(cairo, legend_x, y, kCompleteColour, false, "SC complete");
    legend_line(cairo, legend_x, y += 22, kFloorColour, false, "SC floor");
    legend_line(cairo, legend_x, y += 22, kRedundancy, true, "seen by 2+ sensors");
    if (!coverage.sectors.empty()) {
      legend_line(cairo, legend_x, y += 22, kCompleteColour, true, "required complete");
      legend_line(cairo, legend_x, y += 22, kFloorColour, true, "required floor");
      set_colour(cairo, Rgb{0.0, 0.55, 0.25}, 0.15);
      cairo_rectangle(cairo, legend_x, y + 11, 30, 12);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, "requirement sector", legend_x + 38, y += 22, 14);
    }
    y += 30;
    set_colour(cairo, kInkColour);
    draw_text(cairo, "sensors (strips below: angles", legend_x, y, 13, Anchor::left, true);
    draw_text(cairo, "where each sees the section)", legend_x, y += 17, 13, Anchor::left, true);
    for (std::size_t m = 0; m < mounts; ++m) {
      legend_box(cairo, legend_x, y += 20, sensor_colour(m), mount_label(coverage, m), 12);
    }
    y += 30;
    set_colour(cairo, kInkColour);
    draw_text(cairo,
              "complete: min " + model::format_number(coverage.complete.min * 100, 3) +
                  " %, mean " + model::format_number(coverage.complete.mean * 100, 3) + " %",
              legend_x, y, 12);
    draw_text(cairo,
              "floor: min " + model::format_number(coverage.floor.min * 100, 3) + " %, mean " +
                  model::format_number(coverage.floor.mean * 100, 3) + " %",
              legend_x, y += 17, 12);
    draw_text(cairo, coverage.exact ? "exact path (CGAL)" : "raster path", legend_x, y += 17, 12);
  });
}

void plot_sc_polar(const metrics::RigCoverage& coverage, const std::string& rig_name,
                   const std::string& path, int size) {
  const std::size_t mounts = coverage.mount_ids.size();
  const int legend_rows = 2 + static_cast<int>((mounts + 1) / 2);
  render::draw_to_file(path, size, size + 90 + 22 * legend_rows, [&](cairo_t* cairo) {
    const double cx = size / 2.0;
    const double cy = size / 2.0 + 90;
    const double radius = size * 0.33;
    // One ring per mount outside the 100 % circle: where it sees part of the section.
    constexpr double kRingStep = 0.035;  // of the radius
    const double ring_outer = 1.03 + kRingStep * static_cast<double>(mounts);
    // Robot seen from above: theta = 0 (x, forward) up, theta = 90 deg (y, left) to the left.
    const auto at = [&](double theta, double share) {
      return std::pair{cx - radius * share * std::sin(theta),
                       cy - radius * share * std::cos(theta)};
    };
    // Cairo's arc runs clockwise on screen from +x; theta runs anticlockwise from up.
    const auto arc = [&](double share, double from_deg, double to_deg) {
      const double a0 = -std::numbers::pi / 2 - model::deg_to_rad(to_deg);
      const double a1 = -std::numbers::pi / 2 - model::deg_to_rad(from_deg);
      cairo_arc(cairo, cx, cy, radius * share, a0, a1);
    };
    set_colour(cairo, kInkColour);
    draw_text(cairo, title(coverage, rig_name), cx, 30, 19, Anchor::centre, true);

    for (const metrics::SectorCoverage& sector : coverage.sectors) {
      for (const auto& [from, to] : sector_ranges_deg(sector.sector)) {
        set_colour(cairo, sector.pass ? Rgb{0.0, 0.55, 0.25} : Rgb{0.8, 0.1, 0.1}, 0.08);
        cairo_move_to(cairo, cx, cy);
        arc(1.0, from, to);
        cairo_close_path(cairo);
        cairo_fill(cairo);
      }
    }
    cairo_set_line_width(cairo, 1);
    for (int percent = 25; percent <= 100; percent += 25) {
      set_colour(cairo, kGridColour);
      cairo_arc(cairo, cx, cy, radius * percent / 100.0, 0, 2 * std::numbers::pi);
      cairo_stroke(cairo);
    }
    for (int degrees = 0; degrees < 360; degrees += 45) {
      const auto [x, y] = at(model::deg_to_rad(degrees), 1.0);
      set_colour(cairo, kGridColour);
      cairo_move_to(cairo, cx, cy);
      cairo_line_to(cairo, x, y);
      cairo_stroke(cairo);
      const auto [lx, ly] = at(model::deg_to_rad(degrees), ring_outer + 0.07);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(degrees), lx, ly + 5, 13, Anchor::centre);
    }
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
      const auto [lx, ly] = at(0.5 * (sector.sector.from + sector.sector.to), ring_outer + 0.2);
      set_colour(cairo, sector.pass ? Rgb{0.0, 0.5, 0.2} : Rgb{0.8, 0.1, 0.1});
      draw_text(cairo, sector.sector.name + (sector.pass ? "" : " (FAIL)"), lx, ly + 5, 12,
                Anchor::centre, true);
    }

    // Mount rings.
    for (std::size_t m = 0; m < mounts; ++m) {
      const double share = 1.03 + kRingStep * (static_cast<double>(m) + 0.5);
      set_colour(cairo, sensor_colour(m));
      cairo_set_line_width(cairo, radius * kRingStep * 0.8);
      for (const auto& [from, to] : seen_spans(coverage, [&](std::size_t i) {
             const auto& sees = coverage.angles[i].mount_sees;
             return m < sees.size() && sees[m];
           })) {
        cairo_new_sub_path(cairo);
        arc(share, from, to);
        cairo_stroke(cairo);
      }
    }

    cairo_set_line_join(cairo, CAIRO_LINE_JOIN_ROUND);
    for (const auto& [field, colour, dotted] :
         {std::tuple{&metrics::AngleCoverage::redundancy, kRedundancy, true},
          std::tuple{&metrics::AngleCoverage::floor, kFloorColour, false},
          std::tuple{&metrics::AngleCoverage::complete, kCompleteColour, false}}) {
      set_colour(cairo, colour);
      cairo_set_line_width(cairo, dotted ? 1.5 : 2.5);
      const double dots[] = {3.0, 3.0};
      cairo_set_dash(cairo, dots, dotted ? 2 : 0, 0);
      for (std::size_t i = 0; i < coverage.angles.size(); ++i) {
        const auto [x, y] = at(coverage.angles[i].theta, coverage.angles[i].*field);
        i == 0 ? cairo_move_to(cairo, x, y) : cairo_line_to(cairo, x, y);
      }
      cairo_close_path(cairo);
      cairo_stroke(cairo);
      cairo_set_dash(cairo, nullptr, 0, 0);
    }
    // Percent labels between two spokes, on a white patch so the curves cannot hide them.
    for (int percent = 25; percent <= 100; percent += 25) {
      const auto [x, y] = at(model::deg_to_rad(-22.5), percent / 100.0);
      cairo_set_source_rgba(cairo, 1, 1, 1, 0.85);
      cairo_rectangle(cairo, x + 1, y - 14, 34, 14);
      cairo_fill(cairo);
      set_colour(cairo, kInkColour);
      draw_text(cairo, std::to_string(percent) + " %", x + 3, y - 3, 11);
    }

    const auto [fx, fy] = at(0.0, ring_outer + 0.3);
    set_colour(cairo, kInkColour);
    draw_text(cairo, "forward (x)", fx, fy + 4, 13, Anchor::centre, true);

    double legend_y = size + 94.0;
    legend_line(cairo, 30, legend_y, kCompleteColour, false, "SC complete");
    legend_line(cairo, 200, legend_y, kFloorColour, false, "SC floor");
    legend_line(cairo, 350, legend_y, kRedundancy, true, "seen by 2+ sensors");
    if (!coverage.sectors.empty()) {
      legend_line(cairo, 580, legend_y, kCompleteColour, true, "required (complete, floor)");
    }
    legend_y += 22;
    set_colour(cairo, kInkColour);
    draw_text(cairo,
              "sensors (outer rings, innermost first: angles where each sees the section); "
              "shaded: requirement sectors",
              30, legend_y, 12);
    for (std::size_t m = 0; m < mounts; ++m) {
      if (m % 2 == 0) legend_y += 22;
      legend_box(cairo, m % 2 == 0 ? 30.0 : size / 2.0, legend_y, sensor_colour(m),
                 mount_label(coverage, m), 12);
    }
  });
}

}  // namespace rigdesign::render
