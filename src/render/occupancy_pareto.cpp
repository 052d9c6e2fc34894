#include "rigdesign/render/occupancy_pareto.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"
#include "rigdesign/model/format_number.hpp"

namespace rigdesign::render {
namespace {

double f2_or_worst(double f2) {
  return std::isnan(f2) ? -1.0 : f2;
}

// Fast (green) to slow (red) along the log of the time, so decades read evenly.
Rgb speed_colour(double share) {
  share = std::clamp(share, 0.0, 1.0);
  return {0.15 + 0.75 * share, 0.65 - 0.45 * share, 0.2};
}

// Ghost area from zero on x (ending on a tick), F2 from 0 to 1 on y; the update times' range
// for the colour scale.
struct OccupancyChart {
  PlotArea area;
  double ghost_max = 0.0, x_step = 0.0;  // [m^2]
  double ms_low = 1e300, ms_high = 0.0;  // [ms]
  std::pair<double, double> px(double ghost, double f2) const {
    return std::pair{area.left + ghost / ghost_max * (area.right - area.left),
                     area.bottom - f2 * (area.bottom - area.top)};
  }
  double log_span() const { return std::max(std::log(ms_high / ms_low), 1e-9); }
};

OccupancyChart occupancy_chart(const std::vector<ParetoPoint>& points, int width, int height) {
  OccupancyChart chart{{80, 60, width - 190.0, height - 70.0}};
  for (const ParetoPoint& p : points) {
    chart.ghost_max = std::max(chart.ghost_max, p.ghost_area);
    chart.ms_low = std::min(chart.ms_low, std::max(p.update_ms, 1e-3));
    chart.ms_high = std::max(chart.ms_high, std::max(p.update_ms, 1e-3));
  }
  chart.ghost_max = std::max(chart.ghost_max * 1.1, 0.01);
  chart.x_step = tick_step(chart.ghost_max, 8, StepRounding::up);
  chart.ghost_max = std::ceil(chart.ghost_max / chart.x_step) * chart.x_step;
  return chart;
}

void draw_occupancy_axes(cairo_t* cairo, const OccupancyChart& chart) {
  const Axis x{.ticks = tick_values(0, chart.ghost_max, chart.x_step),
               .pixel = [&](double ghost) { return chart.px(ghost, 0).first; },
               .digits = 4};
  std::vector<double> tenths;
  for (int i = 0; i <= 10; ++i) tenths.push_back(i / 10.0);  // exact tenths, not a sum of 0.1s
  const Axis y{
      .ticks = tenths, .pixel = [&](double f2) { return chart.px(0, f2).second; }, .digits = 2};
  draw_ticks(cairo, chart.area, x, y, {.size = 12, .below = 18, .beside = 8, .lift = 4});
  draw_x_title(cairo, chart.area, "mean ghost area over the cell [m^2] (lower is better)", 42, 13);
  draw_text(cairo, "mean F2 near the person", 14, chart.area.top - 14, 13);
}

// Each configuration as a dot in its speed's colour, ringed on the front, with its label.
void draw_configurations(cairo_t* cairo, const OccupancyChart& chart,
                         const std::vector<ParetoPoint>& points,
                         const std::vector<std::size_t>& front) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ParetoPoint& p = points[i];
    if (std::isnan(p.f2)) continue;
    const auto [x, y] = chart.px(p.ghost_area, p.f2);
    set_colour(cairo, speed_colour(std::log(std::max(p.update_ms, 1e-3) / chart.ms_low) /
                                   chart.log_span()));
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, x, y, 6, 0, 2 * std::numbers::pi);
    cairo_fill(cairo);
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    set_colour(cairo, kInkColour);
    if (on_front) {
      cairo_set_line_width(cairo, 2);
      cairo_new_sub_path(cairo);
      cairo_arc(cairo, x, y, 10, 0, 2 * std::numbers::pi);
      cairo_stroke(cairo);
    }
    draw_text(cairo, p.label, x + 12, y - 6, 10);
  }
}

// Legend: the time scale and the ring.
void draw_occupancy_legend(cairo_t* cairo, const OccupancyChart& chart) {
  const double lx = chart.area.right + 24, top = chart.area.top;
  draw_text(cairo, "ms per update", lx, top + 10, 12, Anchor::left, true);
  for (int i = 0; i < 5; ++i) {
    const double share = i / 4.0;
    set_colour(cairo, speed_colour(share));
    cairo_new_sub_path(cairo);
    cairo_arc(cairo, lx + 6, top + 32 + i * 22, 6, 0, 2 * std::numbers::pi);
    cairo_fill(cairo);
    set_colour(cairo, kInkColour);
    draw_text(cairo, model::format_number(chart.ms_low * std::exp(share * chart.log_span()), 3),
              lx + 20, top + 36 + i * 22, 11);
  }
  cairo_set_line_width(cairo, 2);
  cairo_new_sub_path(cairo);
  cairo_arc(cairo, lx + 6, top + 160, 10, 0, 2 * std::numbers::pi);
  cairo_stroke(cairo);
  draw_text(cairo, "Pareto-optimal", lx + 22, top + 164, 11);
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<ParetoPoint>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ParetoPoint& a = points[i];
    const bool dominated = std::any_of(points.begin(), points.end(), [&](const ParetoPoint& b) {
      const bool no_worse = f2_or_worst(b.f2) >= f2_or_worst(a.f2) &&
                            b.ghost_area <= a.ghost_area && b.update_ms <= a.update_ms;
      const bool better = f2_or_worst(b.f2) > f2_or_worst(a.f2) || b.ghost_area < a.ghost_area ||
                          b.update_ms < a.update_ms;
      return no_worse && better;
    });
    if (!dominated) front.push_back(i);
  }
  return front;
}

void plot_occupancy_pareto(const std::vector<ParetoPoint>& points, const std::string& title,
                           const std::string& path, int width, int height) {
  const std::vector<std::size_t> front = pareto_front(points);
  const OccupancyChart chart = occupancy_chart(points, width, height);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, title, width / 2.0, 34, 18, Anchor::centre, true);
    draw_occupancy_axes(cairo, chart);
    draw_configurations(cairo, chart, points, front);
    draw_occupancy_legend(cairo, chart);
  });
}

}  // namespace rigdesign::render
