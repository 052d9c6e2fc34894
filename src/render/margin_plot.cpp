#include "rigdesign/render/margin_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "cairo_canvas.hpp"
#include "chart_axes.hpp"

namespace rigdesign::render {
namespace {

constexpr Rgb kCurve{0.1, 0.35, 0.7};
constexpr Rgb kGridChoice{0.0, 0.55, 0.25};
constexpr Rgb kRefined{0.85, 0.1, 0.1};
constexpr Rgb kMiss{0.95, 0.85, 0.85};

Rgb sector_colour(std::size_t index) {
  constexpr Rgb kColours[] = {
      {0.55, 0.35, 0.0}, {0.45, 0.2, 0.6}, {0.0, 0.5, 0.5}, {0.6, 0.6, 0.1}, {0.3, 0.3, 0.3}};
  return kColours[index % std::size(kColours)];
}

// A sector whose margin the sweep leaves unchanged is not drawn: it would be a flat line
// saying nothing about this axis, and it would stretch the y range.
bool varies(const std::vector<double>& values) {
  return !values.empty() && *std::max_element(values.begin(), values.end()) -
                                    *std::min_element(values.begin(), values.end()) >
                                1e-9;
}

// The chart's plot area and the data ranges it shows.
struct MarginChart {
  PlotArea area;
  double x_low = 0.0, x_high = 0.0;  // the swept values and the grid [axis unit]
  double y_low = 0.0, y_high = 0.0;  // zero and every drawn margin, padded [points]
  double px(double x) const {
    return area.left + (area.right - area.left) * (x - x_low) / (x_high - x_low);
  }
  double py(double y) const {
    return area.bottom - (area.bottom - area.top) * (y - y_low) / (y_high - y_low);
  }
};

MarginChart margin_chart(const MarginCurve& curve, int width, int height) {
  MarginChart chart{
      {80, 60, width - 30.0, height - 70.0}, curve.grid_choice, curve.grid_choice, 0.0, 0.0};
  const auto widen = [](double& low, double& high, const std::vector<double>& values) {
    for (const double value : values) {
      low = std::min(low, value);
      high = std::max(high, value);
    }
  };
  widen(chart.x_low, chart.x_high, curve.at);
  widen(chart.y_low, chart.y_high, curve.smallest);
  for (const auto& [name, margins] : curve.sectors) {
    if (varies(margins)) widen(chart.y_low, chart.y_high, margins);
  }
  widen(chart.x_low, chart.x_high, curve.grid);
  for (const auto& [x, label] : curve.marks) widen(chart.x_low, chart.x_high, {x});
  if (chart.x_high - chart.x_low < 1e-9) chart.x_high = chart.x_low + 1.0;
  const double y_pad = std::max(1.0, 0.08 * (chart.y_high - chart.y_low));
  chart.y_low -= y_pad;
  chart.y_high += y_pad;
  return chart;
}

// The band below zero margin (a sector threshold missed), then the axes over it.
void draw_margin_axes(cairo_t* cairo, const MarginChart& chart, const MarginCurve& curve) {
  const PlotArea& area = chart.area;
  set_colour(cairo, kMiss);
  cairo_rectangle(cairo, area.left, chart.py(0), area.right - area.left, area.bottom - chart.py(0));
  cairo_fill(cairo);
  // At least five intervals on each axis: a sweep's few degrees and points read finely.
  const Axis x{.ticks = tick_values(chart.x_low, chart.x_high,
                                    tick_step(chart.x_high - chart.x_low, 5, StepRounding::down)),
               .pixel = [&](double value) { return chart.px(value); },
               .digits = 4};
  const Axis y{.ticks = tick_values(chart.y_low, chart.y_high,
                                    tick_step(chart.y_high - chart.y_low, 5, StepRounding::down)),
               .pixel = [&](double value) { return chart.py(value); },
               .digits = 4,
               .ink_at_zero = true};
  draw_ticks(cairo, area, x, y);
  draw_x_title(cairo, area, curve.axis_label, 45);
  draw_y_title(cairo, area, "smallest SC margin to the sector thresholds [points]", 24);
}

// The sectors this axis changes, thin and named at their right end; the rig's smallest margin
// (what the search and the refinement widen) thick on top.
void draw_margin_lines(cairo_t* cairo, const MarginChart& chart, const MarginCurve& curve) {
  const auto polyline = [&](const std::vector<double>& margins) {
    for (std::size_t i = 0; i < margins.size() && i < curve.at.size(); ++i) {
      i == 0 ? cairo_move_to(cairo, chart.px(curve.at[i]), chart.py(margins[i]))
             : cairo_line_to(cairo, chart.px(curve.at[i]), chart.py(margins[i]));
    }
    cairo_stroke(cairo);
  };
  for (std::size_t s = 0; s < curve.sectors.size(); ++s) {
    const auto& [name, margins] = curve.sectors[s];
    if (!varies(margins)) continue;
    set_colour(cairo, sector_colour(s));
    cairo_set_line_width(cairo, 1.3);
    polyline(margins);
    draw_text(cairo, "sector " + name, chart.px(curve.at.back()) - 4, chart.py(margins.back()) - 6,
              12, Anchor::right);
  }
  set_colour(cairo, kCurve);
  cairo_set_line_width(cairo, 2.5);
  polyline(curve.smallest);
  if (!curve.at.empty())
    draw_text(cairo, "smallest (the rig)", chart.px(curve.at.front()) + 4,
              chart.py(curve.smallest.front()) - 8, 12, Anchor::left, true);
}

// The grid the search chose from, as ticks on the axis, and the grid optimum and the refined
// value as dashed lines (one line when the refinement kept the grid's value).
void draw_margin_choices(cairo_t* cairo, const MarginChart& chart, const MarginCurve& curve) {
  const PlotArea& area = chart.area;
  set_colour(cairo, kInkColour);
  for (const double g : curve.grid) {
    cairo_move_to(cairo, chart.px(g), area.bottom);
    cairo_line_to(cairo, chart.px(g), area.bottom - 8);
  }
  cairo_stroke(cairo);
  const double dash[] = {6.0, 4.0};
  const bool same = std::abs(curve.refined - curve.grid_choice) < 1e-9;
  struct Marker {
    double x;
    Rgb colour;
    std::string label;
    double label_y;
  };
  std::vector<Marker> markers;
  if (curve.marks.empty()) {
    markers.push_back({curve.grid_choice, kGridChoice,
                       same ? "grid optimum = refined" : "grid optimum", area.top + 16});
    if (!same) markers.push_back({curve.refined, kRefined, "refined", area.top + 34});
  }
  for (std::size_t i = 0; i < curve.marks.size(); ++i) {
    markers.push_back({curve.marks[i].first, i % 2 == 0 ? kRefined : kGridChoice,
                       curve.marks[i].second, area.top + 16 + 18.0 * static_cast<double>(i % 2)});
  }
  for (const Marker& marker : markers) {
    set_colour(cairo, marker.colour);
    cairo_set_dash(cairo, dash, 2, 0);
    cairo_move_to(cairo, chart.px(marker.x), area.top);
    cairo_line_to(cairo, chart.px(marker.x), area.bottom);
    cairo_stroke(cairo);
    cairo_set_dash(cairo, nullptr, 0, 0);
    draw_text(cairo, marker.label, chart.px(marker.x) + 5, marker.label_y, 13);
  }
}

}  // namespace

void plot_margin_curve(const MarginCurve& curve, const std::string& title, const std::string& path,
                       int width, int height) {
  const MarginChart chart = margin_chart(curve, width, height);
  draw_to_file(path, width, height, [&](cairo_t* cairo) {
    set_colour(cairo, kInkColour);
    draw_text(cairo, title, width / 2.0, 32, 17, Anchor::centre, true);
    draw_margin_axes(cairo, chart, curve);
    draw_margin_lines(cairo, chart, curve);
    draw_margin_choices(cairo, chart, curve);
  });
}

}  // namespace rigdesign::render
